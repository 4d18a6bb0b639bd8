#pragma once
// The simulated controller's 2D compensation table (docs/protocol.md, "2D
// compensation"): X and Y corrections on a regular grid over the X and Y axes' home
// coordinates, uploaded in parts, enabled, disabled and kept for power-up when asked.
//
// While enabled and both axes are homed, every tick the nominal references of X
// and Y (where the trajectory generator wants them) give the bilinearly
// interpolated corrections, which each axis' drive follows on top of its own
// compensation (SimAxis::setCrossCorrection): moves, jogs and paths alike. Enabling
// or disabling at rest never moves the axes; the positions they report shift
// instead, as with the per-axis compensation (sim_compensation.h).
//
// It lives in the machine: a reconnect keeps it; a power cycle starts from what was
// saved (NonVolatile::table2d).
#include "device/protocol/messages_compensation_2d.h"
#include "device/sim/sim_compensation.h"
#include "motion/metrology/grid/compensation_table_2d.h"

#include <optional>
#include <vector>

namespace dev::sim {

class SimMachine;

class SimCompensation2d {
public:
    SimCompensation2d(SimMachine& machine, const NonVolatile& powerUp);

    using Result = std::optional<dev::proto::ErrorReply>;
    Result upload(const dev::proto::Comp2dUploadRequest& r, dev::proto::Comp2dUploadReply& out);
    Result enable(const dev::proto::Comp2dEnableRequest& r, dev::proto::Comp2dEnableReply& out);

    /// Once per tick, after the references were set and before the plants move.
    void follow();

    const std::optional<motion::metrology::CompensationTable2D>& table() const { return m_table; }
    bool enabled() const { return m_enabled; }
    bool applied() const { return m_applied; }
    /// The machine has X and Y as axes 0 and 1, in mm: the table has somewhere to go.
    bool available() const { return m_available; }

private:
    dev::proto::ErrorReply error(dev::proto::ErrorCode code, std::int32_t value, const std::string& text) const;
    dev::proto::Comp2dEnableReply state() const;
    /// The corrections (mm) at the axes' present nominal references.
    void correctionsNow(double& xMm, double& yMm) const;
    /// Attaches or detaches at rest: the nominal references move, the drives stay.
    void attach(bool on);

    SimMachine& m_m;
    std::optional<motion::metrology::CompensationTable2D> m_table;
    bool m_enabled = false;
    bool m_applied = false;
    bool m_saved = true;
    bool m_available = false;
    std::optional<dev::proto::Comp2dUploadRequest> m_staging;  ///< the grid of the upload in progress
    std::vector<dev::proto::Comp2dNode> m_stagingNodes;
};

} // namespace dev::sim
