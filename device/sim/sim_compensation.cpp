#include "device/sim/sim_compensation.h"

#include "device/sim/sim_machine.h"

#include <cmath>
#include <cstdio>

namespace dev::sim {

using motion::metrology::CompensationModel;

namespace {

std::int32_t compNm(double mm) { return static_cast<std::int32_t>(std::llround(mm * 1e6)); }
std::int32_t compNmFromUm(double um) { return static_cast<std::int32_t>(std::llround(um * 1e3)); }

std::string kindText(const CompensationModel& m)
{
    char buf[96];
    if (m.kind == CompensationModel::Kind::Polynomial)
        std::snprintf(buf, sizeof buf, "a polynomial of order %d over %.3f to %.3f mm", static_cast<int>(m.polynomial.coefficientsUm.size()) - 1,
                      m.validFromMm, m.validToMm);
    else
        std::snprintf(buf, sizeof buf, "a table of %d points%s", static_cast<int>(m.table.size()), m.perDirection ? " per direction" : "");
    return buf;
}

/// The index in a problem's path ("table[3].nominal_mm" → 3), or −1.
std::int32_t indexIn(const std::string& path)
{
    const auto open = path.find('[');
    if (open == std::string::npos)
        return -1;
    return static_cast<std::int32_t>(std::atoi(path.c_str() + open + 1));
}

} // namespace

SimCompensation::SimCompensation(SimMachine& machine, const NonVolatile& powerUp) : m_m(machine), m_flash(powerUp)
{
    m_axes.resize(static_cast<std::size_t>(machine.axisCount()));
    m_flash.axes.resize(m_axes.size());
    for (std::size_t i = 0; i < m_axes.size(); ++i) {
        m_axes[i].model = m_flash.axes[i].model;
        m_axes[i].enabled = m_flash.axes[i].model && m_flash.axes[i].enabled;
        m_axes[i].saved = true;
    }
}

const std::optional<CompensationModel>& SimCompensation::model(int axis) const { return m_axes[static_cast<std::size_t>(axis)].model; }
bool SimCompensation::enabled(int axis) const { return m_axes[static_cast<std::size_t>(axis)].enabled; }
bool SimCompensation::applied(int axis) const { return m_axes[static_cast<std::size_t>(axis)].applied; }

dev::proto::ErrorReply SimCompensation::error(dev::proto::ErrorCode code, int axis, std::int32_t value, const std::string& text) const
{
    dev::proto::ErrorReply e;
    e.code = code;
    e.axis = axis < 0 ? dev::proto::kNoAxis : static_cast<std::uint8_t>(axis);
    e.value = value;
    e.message = text;
    return e;
}

SimCompensation::Result SimCompensation::upload(const dev::proto::CompUploadRequest& r, dev::proto::CompUploadReply& out)
{
    if (r.axis >= m_axes.size())
        return error(dev::proto::ErrorCode::BadAxis, -1, r.axis, "axis index " + std::to_string(r.axis) + " does not exist");
    const int i = r.axis;
    const auto& cfg = m_m.st(i).plant->config();
    const std::string letter(1, cfg.letter);
    if (cfg.unit != dev::proto::AxisUnit::Millimetre)
        return error(dev::proto::ErrorCode::BadAxis, i, 0, "axis " + letter + " is not a linear axis: it has no positioning error to compensate");
    if (m_m.st(i).mode != SimMachine::Mode::Idle)
        return error(dev::proto::ErrorCode::Busy, i, 0, "axis " + letter + " is moving: upload its compensation at rest");
    Axis& a = m_axes[static_cast<std::size_t>(i)];
    Staging& s = a.staging;
    const bool table = r.kind != dev::proto::CompKind::Polynomial;
    if (r.first == 0) {
        if (table && (r.total < dev::proto::kMinCompPoints || r.total > dev::proto::kMaxCompPoints))
            return error(dev::proto::kErrCompInvalid, i, -1,
                         "a table of " + std::to_string(r.total) + " points: a compensation table has 2 to 256");
        if (!table && (r.total < 1 || r.total > dev::proto::kMaxCompCoefficients))
            return error(dev::proto::kErrCompInvalid, i, -1, std::to_string(r.total) + " coefficients: a polynomial has 1 to 6");
        s = Staging{};
        s.active = true;
        s.kind = r.kind;
        s.backlash = r.backlash;
        s.total = r.total;
    } else if (!s.active || s.kind != r.kind || s.backlash != r.backlash || s.total != r.total
               || r.first != s.points.size()) {
        const std::int32_t expected = s.active ? static_cast<std::int32_t>(s.points.size()) : 0;
        return error(dev::proto::kErrCompSequence, i, expected,
                     "part from entry " + std::to_string(r.first) + " of axis " + letter + "'s compensation: the device expects entry "
                         + std::to_string(expected) + (s.active ? " of the upload in progress" : " (no upload in progress)"));
    }
    if (table) {
        if (r.first + r.points.size() > s.total)
            return error(dev::proto::kErrCompInvalid, i, static_cast<std::int32_t>(s.total),
                         "more points than the " + std::to_string(s.total) + " the upload announced");
        s.points.insert(s.points.end(), r.points.begin(), r.points.end());
    }
    out.axis = r.axis;
    out.received = table ? static_cast<std::uint16_t>(s.points.size()) : r.total;
    out.installed = 0;
    if (table && s.points.size() < s.total)
        return std::nullopt;

    CompensationModel m;
    m.axis = letter;
    m.backlashUm = s.backlash / 1e3;
    if (table) {
        m.kind = CompensationModel::Kind::Table;
        m.perDirection = s.kind == dev::proto::CompKind::TablePerDirection;
        for (const auto& p : s.points)
            m.table.push_back({p.nominal / 1e6, p.correctionUp / 1e3, (m.perDirection ? p.correctionDown : p.correctionUp) / 1e3});
    } else {
        m.kind = CompensationModel::Kind::Polynomial;
        m.polynomial.coefficientsUm = r.coefficients;
        m.validFromMm = r.validFrom / 1e6;
        m.validToMm = r.validTo / 1e6;
    }
    s = Staging{};
    if (auto e = install(i, std::move(m)))
        return e;
    out.installed = 1;
    return std::nullopt;
}

SimCompensation::Result SimCompensation::install(int i, CompensationModel model)
{
    for (const auto& p : motion::metrology::validate(model)) {
        if (p.isWarning())
            continue;
        return error(dev::proto::kErrCompInvalid, i, indexIn(p.path),
                     "the compensation is refused" + (p.path.empty() ? std::string() : " at " + p.path) + ": "
                         + motion::msg::debugString(p.message));
    }
    Axis& a = m_axes[static_cast<std::size_t>(i)];
    const std::string text = "installed " + kindText(model) + ", disabled";
    const bool poly = model.kind == CompensationModel::Kind::Polynomial;
    std::vector<double> values = poly ? std::vector<double>{2, static_cast<double>(model.polynomial.coefficientsUm.size()) - 1, model.validFromMm, model.validToMm}
                                      : std::vector<double>{1, static_cast<double>(model.table.size()), model.perDirection ? 1.0 : 0.0};
    a.model = std::move(model);
    a.enabled = false;  // a new compensation is enabled on purpose, never by accident
    a.saved = false;
    reconcile();
    m_m.raiseEvent(dev::proto::kEvCompChanged, i, text, dev::proto::reason::kInstalled, std::move(values));
    return std::nullopt;
}

SimCompensation::Result SimCompensation::get(const dev::proto::CompGetRequest& r, dev::proto::CompGetReply& out) const
{
    if (r.axis >= m_axes.size())
        return error(dev::proto::ErrorCode::BadAxis, -1, r.axis, "axis index " + std::to_string(r.axis) + " does not exist");
    const Axis& a = m_axes[r.axis];
    out = dev::proto::CompGetReply{};
    out.axis = r.axis;
    out.flags = static_cast<std::uint8_t>((a.enabled ? dev::proto::CompEnabled : 0) | (a.applied ? dev::proto::CompApplied : 0)
                                          | (a.saved ? dev::proto::CompSaved : 0));
    if (!a.model)
        return std::nullopt;
    const CompensationModel& m = *a.model;
    out.backlash = compNmFromUm(m.backlashUm);
    if (m.kind == CompensationModel::Kind::Polynomial) {
        out.kind = dev::proto::CompKind::Polynomial;
        out.coefficients = m.polynomial.coefficientsUm;
        out.total = static_cast<std::uint16_t>(out.coefficients.size());
        out.validFrom = compNm(m.validFromMm);
        out.validTo = compNm(m.validToMm);
        return std::nullopt;
    }
    out.kind = m.perDirection ? dev::proto::CompKind::TablePerDirection : dev::proto::CompKind::Table;
    out.total = static_cast<std::uint16_t>(m.table.size());
    out.first = r.first;
    const std::size_t count = std::min<std::size_t>(std::min<std::uint8_t>(r.maxCount, dev::proto::kMaxCompPointsPerFrame),
                                                     r.first < m.table.size() ? m.table.size() - r.first : 0);
    for (std::size_t k = 0; k < count; ++k) {
        const auto& p = m.table[r.first + k];
        out.points.push_back({compNm(p.nominalMm), compNmFromUm(p.correctionUpUm), compNmFromUm(p.correctionDownUm)});
    }
    return std::nullopt;
}

SimCompensation::Result SimCompensation::enable(const dev::proto::CompEnableRequest& r)
{
    const bool on = r.flags & dev::proto::CompEnableOn;
    const bool save = r.flags & dev::proto::CompEnableSave;
    std::vector<int> axes;
    for (int i = 0; i < static_cast<int>(m_axes.size()); ++i) {
        const bool named = r.axisMask & (1u << i);
        if (r.axisMask == 0 ? (m_axes[static_cast<std::size_t>(i)].model.has_value() || !on) : named)
            axes.push_back(i);
    }
    for (int b = static_cast<int>(m_axes.size()); b < 8; ++b)
        if (r.axisMask & (1u << b))
            return error(dev::proto::ErrorCode::BadAxis, -1, b, "axis index " + std::to_string(b) + " does not exist");
    // Check every axis before changing any: a refusal changes nothing.
    for (int i : axes) {
        const std::string letter(1, m_m.st(i).plant->config().letter);
        if (on && !m_axes[static_cast<std::size_t>(i)].model)
            return error(dev::proto::kErrCompMissing, i, 0, "axis " + letter + " has no compensation to enable: upload one first");
        if (m_m.st(i).mode != SimMachine::Mode::Idle)
            return error(dev::proto::ErrorCode::Busy, i, 0, "axis " + letter + " is moving: change its compensation at rest");
    }
    for (int i : axes) {
        Axis& a = m_axes[static_cast<std::size_t>(i)];
        const bool changed = a.enabled != on;
        a.enabled = on && a.model.has_value();
        if (changed)
            a.saved = false;
        if (save) {
            m_flash.axes[static_cast<std::size_t>(i)] = {a.model, a.enabled};
            a.saved = true;
        }
        if (changed || save)
            m_m.raiseEvent(dev::proto::kEvCompChanged, i, std::string(a.enabled ? "enabled" : "disabled") + (save ? ", kept for power-up" : ""),
                           a.enabled ? dev::proto::reason::kEnabled : dev::proto::reason::kDisabled, {save ? 1.0 : 0.0});
    }
    reconcile();
    return std::nullopt;
}

void SimCompensation::reconcile()
{
    for (int i = 0; i < static_cast<int>(m_axes.size()); ++i) {
        Axis& a = m_axes[static_cast<std::size_t>(i)];
        auto& s = m_m.st(i);
        const bool want = a.model && a.enabled && s.homed && s.mode != SimMachine::Mode::Homing;
        if (want && !a.applied && s.mode == SimMachine::Mode::Idle) {
            s.plant->setCompensation(&*a.model, s.homeOffset);
            a.applied = true;
        } else if (!want && a.applied) {
            s.plant->setCompensation(nullptr, 0);
            a.applied = false;
        }
    }
}

} // namespace dev::sim
