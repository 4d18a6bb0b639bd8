#pragma once
// One instrument as the application holds it: a dev::InstrumentProxy that screens,
// runners and the telemetry hub keep for the whole run, the backend the present
// connection speaks behind it, and whatever link it is on now (simulator or serial
// port). Switching links never restarts the app and never hands screens a new object.
//
// connectTo() picks the backend for the connection. The simulator speaks the BenchPilot
// protocol, whose backend is made once and kept across reconnections (a pattern run
// interrupted by a pulled cable resumes on the same path queue). A port is first asked
// which protocol it speaks (dev::ProtocolProbe: a BenchPilot HELLO or a GRBL banner), unless
// the machine profile says; one that speaks GRBL gets a GRBL backend wired by the profile
// (instrument_session_port.cpp), handed to the same proxy: the screens see a new identity,
// never a new pointer.
#include "device/client/instrument_proxy.h"
#include "widgets/connection_bar.h"

#include <QCoreApplication>
#include <QObject>
#include <QPointer>

namespace dev {
class BenchPilotClient;
class GrblClient;
class ProtocolProbe;
class SimulatedLink;
class Transport;
}

namespace app {

class InstrumentSession : public QObject {
    Q_OBJECT
public:
    InstrumentSession(dev::proto::DeviceKind kind, const QString& name, QObject* parent = nullptr);
    ~InstrumentSession() override;

    /// The one instrument of this session, whichever backend drives it.
    dev::Instrument* instrument() { return m_proxy; }
    dev::proto::DeviceKind kind() const { return m_kind; }
    /// "Analyzer" or "Stage" in the language in force now (not the one at construction).
    QString name() const
    {
        return m_kind == dev::proto::DeviceKind::Stage ? QCoreApplication::translate("app::MainWindow", "Stage")
                                                  : QCoreApplication::translate("app::MainWindow", "Analyzer");
    }
    ui::ConnectionChoice choice() const { return m_choice; }
    /// Drops the present link (if any) and connects through the chosen one.
    void connectTo(const ui::ConnectionChoice& choice);
    void disconnectLink();
    /// The in-process simulator's link, when that is what is connected (for tests and benches).
    QObject* link() const { return m_link; }

signals:
    /// Asking a port which protocol it speaks (a few seconds at most); `what` for people.
    void detecting(const QString& what);
    /// The connection could not be made before any backend took it (a profile that does not
    /// load, a port that answers neither protocol); a sentence.
    void connectFailed(const QString& why);

private:
    /// The BenchPilot backend on `transport`, made once and kept.
    dev::BenchPilotClient* benchPilotOn(dev::Transport* transport);
    // instrument_session_port.cpp: a serial port (or a typed path), its protocol and backend.
    void connectPort(dev::Transport* transport, const ui::ConnectionChoice& choice);
    dev::GrblClient* grblOn(dev::Transport* transport, const ui::ConnectionChoice& choice);
    void stopProbe();
    void dropSimulator();

    dev::proto::DeviceKind m_kind;
    QString m_name;
    dev::InstrumentProxy* m_proxy;
    QPointer<dev::BenchPilotClient> m_benchPilot;
    QPointer<dev::GrblClient> m_grbl;
    QPointer<dev::ProtocolProbe> m_probe;
    QPointer<QObject> m_link;
    /// The in-process simulator, kept across Disconnect → Connect like a powered
    /// instrument whose cable was out: positions, homed flags and the plunger's
    /// contents are found again. Ends with the session or when another link is chosen.
    QPointer<dev::SimulatedLink> m_sim;
    qint32 m_simBaud = 0;
    ui::ConnectionChoice m_choice;
};

} // namespace app
