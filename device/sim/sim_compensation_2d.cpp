#include "device/sim/sim_compensation_2d.h"

#include "device/protocol/event_reasons.h"
#include "device/sim/sim_machine.h"

#include <cstdio>

namespace dev::sim {

using motion::metrology::CompensationTable2D;

SimCompensation2d::SimCompensation2d(SimMachine& machine, const NonVolatile& powerUp)
    : m_m(machine), m_table(powerUp.table2d), m_enabled(powerUp.table2d && powerUp.table2dEnabled)
{
    // The axes are made before this part, and never change: asked every tick, so kept.
    if (m_m.axisCount() >= 2) {
        const auto& x = m_m.st(0).plant->config();
        const auto& y = m_m.st(1).plant->config();
        m_available = x.letter == 'X' && y.letter == 'Y' && x.unit == dev::proto::AxisUnit::Millimetre
                      && y.unit == dev::proto::AxisUnit::Millimetre;
    }
}

dev::proto::ErrorReply SimCompensation2d::error(dev::proto::ErrorCode code, std::int32_t value, const std::string& text) const
{
    dev::proto::ErrorReply e;
    e.code = code;
    e.axis = dev::proto::kNoAxis;
    e.value = value;
    e.message = text;
    return e;
}

dev::proto::Comp2dEnableReply SimCompensation2d::state() const
{
    dev::proto::Comp2dEnableReply s;
    if (m_table) {
        s.state |= dev::proto::Comp2dInstalled;
        s.columns = static_cast<std::uint8_t>(m_table->columns);
        s.rows = static_cast<std::uint8_t>(m_table->rows);
    }
    if (m_enabled)
        s.state |= dev::proto::Comp2dEnabled;
    if (m_applied)
        s.state |= dev::proto::Comp2dApplied;
    if (m_saved)
        s.state |= dev::proto::Comp2dSaved;
    return s;
}

SimCompensation2d::Result SimCompensation2d::upload(const dev::proto::Comp2dUploadRequest& r, dev::proto::Comp2dUploadReply& out)
{
    if (!available())
        return error(dev::proto::ErrorCode::BadAxis, 0, "this instrument has no X and Y axes for a 2D table");
    if (m_m.st(0).mode != SimMachine::Mode::Idle || m_m.st(1).mode != SimMachine::Mode::Idle)
        return error(dev::proto::ErrorCode::Busy, 0, "X or Y is moving: upload the 2D table at rest");
    const std::size_t total = static_cast<std::size_t>(r.columns) * r.rows;
    if (r.first == 0) {
        m_staging = r;
        m_staging->nodes.clear();
        m_stagingNodes.clear();
    } else if (!m_staging || r.first != m_stagingNodes.size() || r.columns != m_staging->columns || r.rows != m_staging->rows
               || r.originX != m_staging->originX || r.originY != m_staging->originY || r.pitchX != m_staging->pitchX
               || r.pitchY != m_staging->pitchY) {
        const auto expected = static_cast<std::int32_t>(m_staging ? m_stagingNodes.size() : 0);
        return error(dev::proto::kErrCompSequence, expected,
                     "part from node " + std::to_string(r.first) + " of the 2D table: the device expects node "
                         + std::to_string(expected) + " of the upload in progress, on the same grid");
    }
    if (m_stagingNodes.size() + r.nodes.size() > total) {
        m_staging.reset();
        return error(dev::proto::kErrCompInvalid, static_cast<std::int32_t>(total),
                     "the 2D table's parts hold more nodes than its " + std::to_string(total));
    }
    m_stagingNodes.insert(m_stagingNodes.end(), r.nodes.begin(), r.nodes.end());
    out.received = static_cast<std::uint16_t>(m_stagingNodes.size());
    out.installed = 0;
    if (m_stagingNodes.size() < total)
        return std::nullopt;
    CompensationTable2D t;
    t.columns = r.columns;
    t.rows = r.rows;
    t.originXMm = r.originX / 1e6;
    t.originYMm = r.originY / 1e6;
    t.pitchXMm = r.pitchX / 1e6;
    t.pitchYMm = r.pitchY / 1e6;
    for (const auto& n : m_stagingNodes) {
        t.correctionXUm.push_back(n.correctionX / 1e3);
        t.correctionYUm.push_back(n.correctionY / 1e3);
    }
    m_staging.reset();
    m_stagingNodes.clear();
    const auto problems = motion::metrology::validate(t);
    for (const auto& p : problems)
        if (p.isError())
            return error(dev::proto::kErrCompInvalid, -1, "the 2D table cannot be applied: " + p.path + ": " + motion::msg::debugString(p.message));
    if (m_applied)
        attach(false);
    m_table = t;
    m_enabled = false;
    m_saved = false;
    out.installed = 1;
    char text[96];
    std::snprintf(text, sizeof text, "2D table of %d x %d nodes installed, disabled", t.columns, t.rows);
    m_m.raiseEvent(dev::proto::kEvCompChanged, -1, text);
    return std::nullopt;
}

SimCompensation2d::Result SimCompensation2d::enable(const dev::proto::Comp2dEnableRequest& r, dev::proto::Comp2dEnableReply& out)
{
    if (!available())
        return error(dev::proto::ErrorCode::BadAxis, 0, "this instrument has no X and Y axes for a 2D table");
    if (r.flags & dev::proto::Comp2dEnableQuery) {
        out = state();
        return std::nullopt;
    }
    const bool on = r.flags & dev::proto::Comp2dEnableOn;
    const bool save = r.flags & dev::proto::Comp2dEnableSave;
    if (on && !m_table)
        return error(dev::proto::kErrCompMissing, 0, "there is no 2D table to enable: upload one first");
    if (m_m.st(0).mode != SimMachine::Mode::Idle || m_m.st(1).mode != SimMachine::Mode::Idle)
        return error(dev::proto::ErrorCode::Busy, 0, "X or Y is moving: change the 2D table at rest");
    const bool changed = m_enabled != on;
    m_enabled = on;
    if (changed)
        m_saved = false;
    if (save) {
        m_m.compensation().saveTable2d(m_table, m_enabled);
        m_saved = true;
    }
    follow();
    if (changed || save)
        m_m.raiseEvent(dev::proto::kEvCompChanged, -1,
                       std::string(on ? "2D table enabled" : "2D table disabled") + (save ? ", kept for power-up" : ""),
                       on ? dev::proto::reason::kEnabled : dev::proto::reason::kDisabled, {save ? 1.0 : 0.0});
    out = state();
    return std::nullopt;
}

void SimCompensation2d::correctionsNow(double& xMm, double& yMm) const
{
    const auto& sx = m_m.st(0);
    const auto& sy = m_m.st(1);
    const auto k = m_table->correctionAt(sx.plant->reference() - sx.homeOffset, sy.plant->reference() - sy.homeOffset);
    xMm = k.xUm * 1e-3;
    yMm = k.yUm * 1e-3;
}

void SimCompensation2d::attach(bool on)
{
    SimAxis& x = *m_m.st(0).plant;
    SimAxis& y = *m_m.st(1).plant;
    if (!on) {
        x.setCrossCorrection(0, true);
        y.setCrossCorrection(0, true);
        m_applied = false;
        return;
    }
    // n + k(n) = drive for both axes at once: a fixed point, since k changes far
    // more slowly than n (its slope is µm per mm).
    for (int it = 0; it < 12; ++it) {
        double kx = 0, ky = 0;
        correctionsNow(kx, ky);
        x.setCrossCorrection(kx, true);
        y.setCrossCorrection(ky, true);
    }
    m_applied = true;
}

void SimCompensation2d::follow()
{
    if (!available())
        return;
    const auto& sx = m_m.st(0);
    const auto& sy = m_m.st(1);
    const bool want = m_table && m_enabled && sx.homed && sy.homed && sx.mode != SimMachine::Mode::Homing
                      && sy.mode != SimMachine::Mode::Homing;
    const bool atRest = sx.mode == SimMachine::Mode::Idle && sy.mode == SimMachine::Mode::Idle;
    if (want && !m_applied) {
        if (atRest)
            attach(true);
        return;
    }
    if (!want) {
        if (m_applied)
            attach(false);
        return;
    }
    double kx = 0, ky = 0;
    correctionsNow(kx, ky);
    sx.plant->setCrossCorrection(kx, false);
    sy.plant->setCrossCorrection(ky, false);
}

} // namespace dev::sim
