#pragma once
// benchpilot-cli's device side: connects to one instrument and offers what the
// device commands share: send a request and wait for its answer, wait until the
// machine is still, print the status as text or JSON.
#include "command.h"
#include "device/client/instrument_proxy.h"

#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTextStream>

#include <functional>

namespace dev {
class BenchPilotClient;
class Transport;
}

namespace cli {

class CliSession : public QObject {
    Q_OBJECT
public:
    /// `prefix` starts every message on stderr ("benchpilot-cli home").
    CliSession(const LinkOptions& options, const QString& prefix, QTextStream& out, QTextStream& err);
    ~CliSession() override;

    /// Opens the link and waits until the device is ready; false after saying why.
    bool connectDevice();
    /// The instrument, whichever backend the connection speaks (a proxy in front of it).
    dev::Instrument* instrument() { return m_client; }
    const LinkOptions& options() const { return m_opt; }
    /// The in-process simulator's link when that is what is connected, else nullptr.
    QObject* link() const { return m_link; }

    /// Sends one request and waits for its answer; prints a refusal. Returns an exit code.
    int request(const std::function<void(dev::Instrument::Callback)>& send, const QString& what);
    /// Waits until no axis moves (or the timeout, then stops the machine); prints the status.
    int waitUntilStill(const QString& what);
    /// Axis letters ("XY", "X,Z") to a mask; false after a usage message.
    bool parseAxes(const QString& text, quint8* mask);
    void printStatus();
    void report(const QString& message);
    /// Limit hits, faults and the like seen since the last call.
    QStringList takeMotionErrors();

private:
    /// cli_session_port.cpp: the backend for a port — the profile's protocol, or the one a
    /// probe hears (a BenchPilot HELLO or a GRBL banner); false after saying why.
    bool choosePortBackend(dev::Transport* transport);

    LinkOptions m_opt;
    QString m_prefix;
    QTextStream& m_out;
    QTextStream& m_err;
    dev::InstrumentProxy* m_client;
    QPointer<dev::BenchPilotClient> m_benchPilot;  ///< the backend, owned by the proxy
    QObject* m_link = nullptr;    ///< owns the transport (simulated link or serial port)
    QStringList m_motionErrors;   ///< limit hits and faults seen while waiting
};

/// Runs the event loop until `done` returns true or `timeoutMs` passes; false on timeout.
bool spinUntil(const std::function<bool()>& done, int timeoutMs);

} // namespace cli
