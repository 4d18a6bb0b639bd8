// GrblClient, part 7: a home set here on a controller without homing, kept across connections
// while the controller provably did not restart (grbl_home_memory.h). GRBL keeps its G54 offset
// in EEPROM through a restart, so the offset alone cannot tell; a restart also zeroes the machine
// position and prints the start-up banner, so a connection that hears no banner and finds both
// the offset and the machine position this host last saw is talking to the controller that
// still stands where its home was set. Anything else starts unestablished, and the memory of
// the home is dropped so that a later connection cannot take it up again.
#include "device/backends/grbl/client/grbl_client.h"

#include "device/backends/grbl/grbl_home_memory.h"

#include <cmath>

namespace dev {

namespace {

/// Reports carry 0.001 mm (0.0001 in): two readings of a machine at rest agree to this.
constexpr double kHomeSameMm = 0.003;

bool homeSameMm(const std::vector<double>& a, const std::vector<double>& b)
{
    if (a.empty() || a.size() != b.size())
        return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!(std::fabs(a[i] - b[i]) <= kHomeSameMm))
            return false;
    return true;
}

} // namespace

std::string GrblClient::controllerKey() const
{
    // GRBL has no serial number: the port it is on, what it says it is, and the instrument it is.
    return (m_homePort + QStringLiteral(" | ") + m_identity.family + QStringLiteral(" | ") + m_identity.firmware + QStringLiteral(" | ")
            + QString::fromStdString(instrumentTerm(m_identity.kind)))
        .toStdString();
}

quint32 GrblClient::recallHome(dev::grbl::MachineState state)
{
    if (m_homeFile.isEmpty())
        return 0;
    const GrblHomeMemory memory(m_homeFile);
    const std::string key = controllerKey();
    const auto home = memory.recall(key);
    if (!home)
        return 0;
    quint32 mask = 0;
    std::string letters;
    for (int i = 0; i < m_map.size(); ++i)
        if (home->axes.find(grblLetterOf(i)) != std::string::npos) {
            mask |= 1u << i;
            letters.push_back(static_cast<char>(m_identity.axes[i].letter.toLatin1()));
        }
    const bool stillSo = !m_wire.restartHeard && state != dev::grbl::MachineState::Alarm && m_controller.haveParameters
                         && homeSameMm(home->g54Mm, m_controller.g54Mm) && homeSameMm(home->machineMm, m_reports.machineMm);
    if (!stillSo || mask == 0) {
        memory.forget(key);
        if (mask)
            note(motion::msg::make(m_wire.restartHeard ? "grbl.home_lost_restart" : "grbl.home_lost_changed", {motion::msg::verbatim("axes", letters)}));
        return 0;
    }
    note(motion::msg::make("grbl.home_kept", {motion::msg::verbatim("axes", letters)}));
    return mask;
}

void GrblClient::rememberHome()
{
    if (m_homeFile.isEmpty() || m_controller.limits.homingEnabled || !m_controller.haveParameters || m_reports.machineMm.empty())
        return;
    GrblHome home;
    home.controller = controllerKey();
    for (int i = 0; i < m_map.size(); ++i)
        if (established(i) && grblLetterOf(i) != 0 && home.axes.find(grblLetterOf(i)) == std::string::npos)
            home.axes.push_back(grblLetterOf(i));
    home.g54Mm = m_controller.g54Mm;
    home.machineMm = m_reports.machineMm;
    if (home.axes.empty())
        return;
    if (!GrblHomeMemory(m_homeFile).remember(home))
        note(motion::msg::make("grbl.home_not_saved", {motion::msg::verbatim("file", m_homeFile.toStdString())}));
}

void GrblClient::keepHomeOnLeave()
{
    if (m_homeFile.isEmpty() || m_controller.limits.homingEnabled)
        return;
    const GrblHomeMemory memory(m_homeFile);
    const std::string key = controllerKey();
    auto home = memory.recall(key);
    if (!home)
        return;
    if (m_positions.established == 0 || m_reports.tracker.state() == dev::grbl::MachineState::Alarm
        || m_reports.machineMm.size() != home->machineMm.size()) {
        memory.forget(key);
        return;
    }
    home->machineMm = m_reports.machineMm;
    memory.remember(*home);
}

void GrblClient::loseEstablished()
{
    m_positions = Positions{};
    if (!m_homeFile.isEmpty() && m_phase == Phase::Ready)
        GrblHomeMemory(m_homeFile).forget(controllerKey());
}

} // namespace dev
