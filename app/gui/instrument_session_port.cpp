// InstrumentSession on a serial port (or a typed path): which protocol it speaks — the
// machine profile says, or a probe asks (dev::ProtocolProbe) — and the backend that speaks it,
// handed to the session's proxy. The simulator's path stays in instrument_session.cpp.
#include "instrument_session.h"

#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/backends/grbl/client/grbl_client.h"
#include "device/backends/grbl/grbl_home_memory.h"
#include "device/backends/protocol_probe.h"
#include "device/files/machine_profile_file.h"
#include "widgets/wording/wording.h"

#include <QFileInfo>

namespace app {

namespace {

QString kindWord(dev::proto::DeviceKind k)
{
    return k == dev::proto::DeviceKind::Stage ? InstrumentSession::tr("stage") : InstrumentSession::tr("analyzer");
}

} // namespace

void InstrumentSession::stopProbe()
{
    if (m_probe)
        m_probe->deleteLater();
    m_probe = nullptr;
}

dev::GrblClient* InstrumentSession::grblOn(dev::Transport* transport, const ui::ConnectionChoice& choice)
{
    dev::files::MachineProfile profile = dev::files::defaultProfile(m_kind);
    if (!choice.profile.isEmpty())
        dev::files::loadMachineProfileFile(choice.profile, &profile, nullptr);  // checked in connectPort()
    // A new backend per connection: the wiring may have changed with the profile.
    m_grbl = new dev::GrblClient(profile, choice.profile.isEmpty());
    m_grbl->rememberHomesIn(dev::GrblHomeMemory::defaultPath(), choice.port);
    m_proxy->setBackend(m_grbl);
    m_grbl->setTransport(transport);
    return m_grbl;
}

void InstrumentSession::connectPort(dev::Transport* transport, const ui::ConnectionChoice& choice)
{
    auto protocol = dev::files::MachineProfile::Protocol::Auto;
    if (!choice.profile.isEmpty()) {
        dev::files::MachineProfile profile;
        dev::files::json::Problems problems;
        if (!dev::files::loadMachineProfileFile(choice.profile, &profile, &problems)) {
            emit connectFailed(tr("The machine profile does not load: %1")
                                   .arg(ui::words::fileProblems(problems, QFileInfo(choice.profile).fileName()).join(QLatin1Char('\n'))));
            return;
        }
        if (profile.instrument != m_kind) {
            emit connectFailed(tr("The machine profile %1 is for the %2, not the %3.")
                                   .arg(choice.profile, kindWord(profile.instrument), kindWord(m_kind)));
            return;
        }
        protocol = profile.protocol;
    }
    if (protocol == dev::files::MachineProfile::Protocol::BenchPilot) {
        benchPilotOn(transport)->connectLink();
        return;
    }
    if (protocol == dev::files::MachineProfile::Protocol::Grbl) {
        grblOn(transport, choice)->connectLink();
        return;
    }
    auto* probe = new dev::ProtocolProbe(transport, this);
    m_probe = probe;
    emit detecting(tr("detecting the protocol on %1…").arg(choice.port));
    connect(probe, &dev::ProtocolProbe::finished, this, [this, probe, transport, choice](const dev::ProbeResult& r) {
        if (m_probe != probe)
            return;  // disconnected or connected elsewhere meanwhile
        stopProbe();
        switch (r.protocol) {
        case dev::ProbeResult::Protocol::BenchPilot:
            if (r.kindKnown && r.kind != m_kind) {
                transport->close();
                emit connectFailed(tr("%1 is a %2, not the %3: connect it in the %2's bar.")
                                       .arg(choice.port, kindWord(r.kind), kindWord(m_kind)));
                return;
            }
            benchPilotOn(transport)->connectLink();
            return;
        case dev::ProbeResult::Protocol::Grbl: {
            dev::GrblClient* grbl = grblOn(transport, choice);
            grbl->setRestartHeardBeforeConnect(r.grblBanner);
            grbl->connectLink();
            return;
        }
        case dev::ProbeResult::Protocol::None:
            emit connectFailed(ui::words::text(r.error));
            return;
        }
    });
    probe->start();
}

} // namespace app
