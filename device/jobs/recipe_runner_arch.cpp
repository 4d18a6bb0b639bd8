// The recipe runner's arched moves (docs/recipes.md, "Travel"): what it sends when it
// does not know where the tip is, and the legs it falls back to on a device that does
// not blend Z with XY.
#include "device/jobs/recipe_runner.h"

#include "device/protocol/messages_arch.h"

#include <algorithm>

namespace dev::jobs {

using motion::plates::MachineMove;
using motion::plates::MoveKind;

MachineMove RecipeRunner::archAsSent(const MachineMove& planned) const
{
    MachineMove m = planned;
    const bool fromPlannedWell = m_deferredFrom >= 0 && m_deferredFrom == m_op - 1 && m_knowXy && m_knowZ;
    if (!fromPlannedWell)
        m.departMm = 0;  // wherever the tip is, it goes straight up before it moves sideways
    if ((!m_knowXy || !m_knowZ) && m_op >= 0 && m_op < static_cast<int>(m_plan.ops.size()))
        m.clearZMm = std::min(m.clearZMm, m_plan.ops[static_cast<std::size_t>(m_op)].safeZMm);  // clears every labware
    return m;
}

void RecipeRunner::archAsLegs()
{
    auto& moves = m_plan.ops[static_cast<std::size_t>(m_op)].moves;
    const auto at = moves.begin() + m_move;
    const MachineMove arch = *at;
    MachineMove up, across, down;
    up.kind = MoveKind::Raise;
    up.zMm = arch.clearZMm;
    up.speed = arch.zSpeed;
    across.kind = MoveKind::Travel;
    across.xMm = arch.xMm;
    across.yMm = arch.yMm;
    across.speed = arch.speed;
    down.kind = MoveKind::Lower;
    down.zMm = arch.zMm;
    down.speed = arch.zSpeed;
    // The op's planned time stays what it was (progress and the ETA count ops, not moves).
    up.durationS = arch.durationS;
    *at = up;
    moves.insert(moves.begin() + m_move + 1, {across, down});
    auto& op = m_plan.ops[static_cast<std::size_t>(m_op)];
    if (m_move < op.visitMoves)
        op.visitMoves += 2;
}

bool RecipeRunner::canArchPump() const
{
    return m_client->can(dev::Capability::ArchedMove) && (m_client->identity().protocolCapabilities & dev::proto::kCapArchPump) != 0;
}

void RecipeRunner::archPumpApart()
{
    auto& op = m_plan.ops[static_cast<std::size_t>(m_op)];
    const auto at = op.moves.begin() + m_move;
    MachineMove arch = *at;
    MachineMove pump, up;
    pump.kind = MoveKind::Pump;
    pump.pumpDeltaUl = arch.pumpDeltaUl;
    pump.speed = arch.pumpSpeed;
    up.kind = MoveKind::Raise;
    up.zMm = arch.leaveZMm;
    up.speed = arch.zSpeed;
    arch.archPump = false;
    arch.pumpDeltaUl = 0;
    // The op's planned time stays what it was (progress and the ETA count ops, not moves).
    *at = arch;
    op.moves.insert(op.moves.begin() + m_move + 1, {pump, up});
}

} // namespace dev::jobs
