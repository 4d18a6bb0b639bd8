// CliSession on a serial port (or benchpilot-sim's pty): which protocol the port speaks — the
// machine profile says, or a probe asks (dev::ProtocolProbe) — and the backend that speaks it
// behind the session's proxy: the BenchPilot client, or the GRBL client wired by --profile (or
// the default wiring of --instrument).
#include "cli_session.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/backends/grbl/client/grbl_client.h"
#include "device/backends/grbl/grbl_home_memory.h"
#include "device/backends/protocol_probe.h"
#include "device/files/machine_profile_file.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QFileInfo>

namespace app::cli {

namespace {
QString kindWord(dev::proto::DeviceKind k) { return ui::words::term(dev::instrumentTerm(k)); }
} // namespace

bool CliSession::choosePortBackend(dev::Transport* transport)
{
    std::optional<dev::files::MachineProfile> profile;
    if (!m_opt.profile.isEmpty()) {
        dev::files::MachineProfile p;
        dev::files::json::Problems problems;
        if (!dev::files::loadMachineProfileFile(m_opt.profile, &p, &problems)) {
            report(tr("--profile: %1").arg(ui::words::fileProblems(problems, QFileInfo(m_opt.profile).fileName()).join(QLatin1Char('\n'))));
            return false;
        }
        profile = p;
    }
    std::optional<dev::proto::DeviceKind> asked;
    if (!m_opt.instrument.isEmpty())
        asked = m_opt.instrument == QLatin1String("stage") ? dev::proto::DeviceKind::Stage : dev::proto::DeviceKind::Analyzer;
    if (asked && profile && profile->instrument != *asked) {
        report(tr("--profile %1 is for the %2, but --instrument says %3").arg(m_opt.profile, kindWord(profile->instrument), kindWord(*asked)));
        return false;
    }
    auto protocol = profile ? profile->protocol : dev::files::MachineProfile::Protocol::Auto;
    dev::ProbeResult found;
    if (protocol == dev::files::MachineProfile::Protocol::Auto) {
        dev::ProtocolProbe probe(transport);
        probe.start();
        spinUntil([&probe] { return probe.done(); }, dev::ProtocolProbe::kLongestMs + 2000);
        if (!probe.done()) {
            report(tr("cannot connect to %1: the protocol could not be detected").arg(transport->describe()));
            return false;
        }
        found = probe.result();
        if (found.protocol == dev::ProbeResult::Protocol::None) {
            report(tr("cannot connect to %1: %2").arg(transport->describe(), ui::words::text(found.error)));
            return false;
        }
        protocol = found.protocol == dev::ProbeResult::Protocol::Grbl ? dev::files::MachineProfile::Protocol::Grbl
                                                                      : dev::files::MachineProfile::Protocol::BenchPilot;
    }
    if (protocol == dev::files::MachineProfile::Protocol::BenchPilot) {
        if (asked && found.kindKnown && found.kind != *asked) {
            transport->close();
            report(tr("%1 is a %2, not the %3 --instrument names").arg(transport->describe(), kindWord(found.kind), kindWord(*asked)));
            return false;
        }
        m_benchPilot = new dev::BenchPilotClient;
        m_ownProxy->setBackend(m_benchPilot);
        m_benchPilot->setTransport(transport);
        return true;
    }
    // GRBL names no instrument: the profile's, else --instrument's, else the analyzer.
    const dev::proto::DeviceKind kind = profile ? profile->instrument : asked.value_or(dev::proto::DeviceKind::Analyzer);
    auto* grbl = new dev::GrblClient(profile ? *profile : dev::files::defaultProfile(kind), !profile.has_value());
    grbl->rememberHomesIn(dev::GrblHomeMemory::defaultPath(), m_opt.port);
    grbl->setRestartHeardBeforeConnect(found.grblBanner);
    m_ownProxy->setBackend(grbl);
    grbl->setTransport(transport);
    return true;
}

} // namespace app::cli
