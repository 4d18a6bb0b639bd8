#pragma once
// benchpilot-cli's device side: connects to one instrument and offers what the
// device commands share: send a request and wait for its answer, wait until the
// machine is still, print the status as text or JSON.
#include "command.h"
#include "device/client/instrument_proxy.h"

#include <QJsonObject>
#include <QObject>
#include <QPointer>
#include <QStringList>
#include <QTextStream>

#include <functional>
#include <memory>
#include <optional>

namespace dev {
class BenchPilotClient;
class Transport;
}

namespace app::cli {

class CliSession : public QObject {
    Q_OBJECT
public:
    /// A link of its own, to the instrument `options` name (benchpilot-cli's process).
    CliSession(Invocation& inv, const LinkOptions& options);
    /// An instrument someone else holds and keeps connected (the GUI's, for the API):
    /// connectDevice() is not needed, and the session never disconnects it.
    CliSession(Invocation& inv, dev::Instrument* instrument);
    ~CliSession() override;

    /// Opens the link and waits until the device is ready; false after saying why.
    bool connectDevice();
    /// The instrument, whichever backend the connection speaks (a proxy in front of it).
    dev::Instrument* instrument() { return m_client; }
    const LinkOptions& options() const { return m_opt; }
    /// The in-process simulator's link when that is what is connected, else nullptr
    /// (always nullptr for an instrument the GUI holds: its clock is not ours to change).
    QObject* link() const { return m_link; }
    /// Where a simulated camera looks: the in-process simulator's link behind the
    /// instrument, ours or (for the GUI's) the one its holder names; nullptr if none.
    /// Only for reading the simulated machine, never for changing its clock.
    using SimulatorLookup = std::function<QObject*()>;
    void setSimulatorLookup(SimulatorLookup lookup) { m_simulatorLookup = std::move(lookup); }
    QObject* simulator() const { return m_link ? m_link : m_simulatorLookup ? m_simulatorLookup() : nullptr; }

    /// Sends one request and waits for its answer; prints a refusal. Returns an exit code.
    int request(const std::function<void(dev::Instrument::Callback)>& send, const QString& what);
    /// request() in two halves, so that a halt goes out to every instrument before any
    /// answer is awaited: sendRequest() sends, awaitAnswer() waits as request() does.
    struct PendingRequest {
        bool done = false;
        std::optional<dev::RequestError> error;
    };
    std::shared_ptr<PendingRequest> sendRequest(const std::function<void(dev::Instrument::Callback)>& send);
    int awaitAnswer(const std::shared_ptr<PendingRequest>& pending, const QString& what);
    /// Waits until no axis moves (or the timeout, then stops the machine); prints the
    /// status unless `printStatusAfter` is false.
    int waitUntilStill(const QString& what, bool printStatusAfter = true);
    /// After a home request was accepted: waits, quietly, until the axes in `mask` are
    /// homed and at rest in a status read after the request (an axis homed before looks
    /// done at once in the last one). False on timeout or a lost link.
    bool waitUntilHomed(quint8 mask);
    /// Axis letters ("XY", "X,Z") to a mask; false after a usage message.
    bool parseAxes(const QString& text, quint8* mask);
    /// "X=12.5", "Y=-3" (one a word) to axis indices and values; false after a usage message.
    bool parseTargets(const QStringList& words, QVector<QPair<int, double>>* targets);
    void printStatus();
    /// The status as `--json` prints it.
    QJsonObject statusJson() const;
    void report(const QString& message);
    /// Limit hits, faults and the like seen since the last call.
    QStringList takeMotionErrors();
    /// The device's last refusal seen through request() (the API names its code).
    const std::optional<dev::RequestError>& lastRefusal() const { return m_lastRefusal; }
    void noteRefusal(const dev::RequestError& e) { m_lastRefusal = e; }

    /// Telemetry a job needs (channels at rateHz; empty withdraws). By default the
    /// instrument's subscription is replaced; inside the GUI the host routes it
    /// through the telemetry hub, so the plots keep what they show.
    using TelemetryWish = std::function<void(const QVector<dev::proto::ChannelRef>& channels, int rateHz)>;
    void wantTelemetry(const QVector<dev::proto::ChannelRef>& channels, int rateHz);
    void setTelemetryWish(TelemetryWish wish) { m_telemetryWish = std::move(wish); }

private:
    /// cli_session_port.cpp: the backend for a port — the profile's protocol, or the one a
    /// probe hears (a BenchPilot HELLO or a GRBL banner); false after saying why.
    bool choosePortBackend(dev::Transport* transport);

    void watchMotionErrors();

    Invocation& m_inv;
    LinkOptions m_opt;
    dev::Instrument* m_client;
    dev::InstrumentProxy* m_ownProxy = nullptr;  ///< set when the session made the connection
    QPointer<dev::BenchPilotClient> m_benchPilot;  ///< the backend, owned by the proxy
    QObject* m_link = nullptr;    ///< owns the transport (simulated link or serial port)
    QStringList m_motionErrors;   ///< limit hits and faults seen while waiting
    std::optional<dev::RequestError> m_lastRefusal;
    TelemetryWish m_telemetryWish;
    SimulatorLookup m_simulatorLookup;
    bool m_wantedTelemetry = false;
};

/// Runs the event loop until `done` returns true or `timeoutMs` passes; false on timeout.
/// On a Fiber (a command the API runs inside the GUI) it suspends the command instead
/// of nesting an event loop (fiber.h); the commands never need to know.
bool spinUntil(const std::function<bool()>& done, int timeoutMs);

} // namespace app::cli
