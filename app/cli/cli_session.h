#pragma once
// benchpilot-cli's device side: connects to one instrument, runs one command,
// waits until the machine is still, and prints the result as text or JSON.
#include "device/client/instrument_client.h"

#include <QObject>
#include <QStringList>
#include <QTextStream>

#include <functional>
#include <memory>

namespace cli {

struct LinkOptions {
    QString sim;          ///< "analyzer" or "stage" when simulated in-process
    QString port;         ///< serial port path otherwise
    qint32 baud = 115200;
    bool json = false;
    double timeoutS = 120;///< longest wait for motion to finish
};

/// Exit codes: 0 ok, 1 usage, 2 refused by the device or failed motion, 3 link trouble.
enum ExitCode { Ok = 0, Usage = 1, Refused = 2, LinkTrouble = 3 };

class CliSession : public QObject {
    Q_OBJECT
public:
    CliSession(const LinkOptions& options, QTextStream& out, QTextStream& err);
    ~CliSession() override;

    /// Runs `command args…` to completion (spins its own event loop) and returns the exit code.
    int run(const QString& command, const QStringList& args);

private:
    bool connectDevice();
    int cmdInfo();
    int cmdStatus();
    int cmdHome(const QStringList& args);
    int cmdMove(const QStringList& args);
    int cmdJog(const QStringList& args);
    int cmdStop();
    int cmdEStop();
    int cmdReset();
    int cmdZero(const QStringList& args);
    int cmdLimits(const QStringList& args);
    /// Sends one request and waits for its answer; prints a refusal. Returns an exit code.
    int request(const std::function<void(dev::InstrumentClient::Callback)>& send, const QString& what);
    int waitUntilStill(const QString& what);
    bool parseAxes(const QString& text, quint8* mask);
    void printStatus();
    int usage(const QString& message);

    LinkOptions m_opt;
    QTextStream& m_out;
    QTextStream& m_err;
    dev::InstrumentClient* m_client;
    QObject* m_link = nullptr;    ///< owns the transport (simulated link or serial port)
    QStringList m_motionErrors;   ///< limit hits and faults seen while waiting
};

} // namespace cli
