#pragma once
// The tuning side of one instrument (docs/tuning.md), in axis units: PID gains of the
// closed-loop axes, step and relay tests that run on the device, the device's
// capture of a test, and the realtime abort. A BenchPilot-protocol feature, reached
// as Instrument::tuning() (nullptr on a backend without it, such as GRBL); the
// backend's implementation is device/backends/benchpilot/protocol_tuning_client.h.
// Widgets and runners use this, never the protocol.
#include "device/client/instrument.h"
#include "motion/control/experiment.h"
#include "motion/control/gains.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>

namespace dev {

struct AxisGains {
    int axis = -1;
    double controlPeriodS = 0;               ///< the T of eq. 2
    motion::control::DiscreteGains gains;    ///< the operator's set (in force whenever no test runs)
    motion::control::DiscreteGains saved;    ///< the power-up set
    motion::control::DiscreteGains limits;   ///< the largest the device accepts
    bool testRunning = false;
};

/// A test the device ran, in axis units (mm; the controller output in mm of motor correction).
struct TestCapture {
    int axis = -1;
    int kind = 0;                            ///< 1 step test, 2 relay test
    quint32 testId = 0;
    motion::control::Record record;          ///< reason, trip value and limit (mm, or s for the duration) included
    motion::control::DiscreteGains gains;    ///< what a step test ran with
};

struct StepTestParams {
    int axis = 0;
    double stepMm = 0.01;
    double settleBandMm = 0.001;             ///< 0: never ends on settling
    double settleHoldS = 0.05;
    double runS = 0;                         ///< 0: until settled
    motion::control::Envelope envelope{0.05, 0.05, 2};  ///< mm, mm, s
    std::optional<motion::control::DiscreteGains> trialGains;
};

struct RelayTestParams {
    int axis = 0;
    double amplitudeMm = 0.005;              ///< d, of controller output
    double hysteresisMm = 0.001;             ///< ε
    double forcedPeriodS = 0;                ///< 0: relay on the error
    int cycles = 20;
    motion::control::Envelope envelope{0.05, 0.05, 2};
};

class TuningClient : public QObject {
    Q_OBJECT
public:
    explicit TuningClient(Instrument* instrument, QObject* parent = nullptr) : QObject(parent), m_instrument(instrument) {}
    /// The instrument these gains and tests belong to (its link state, identity, axes).
    Instrument* instrument() const { return m_instrument; }

    /// The device has gains / runs tests.
    virtual bool hasGains() const = 0;
    virtual bool hasTests() const = 0;
    /// Axes whose gains can be tuned: every axis of a closed-loop instrument with gains.
    virtual QVector<int> tunableAxes() const = 0;

    using Callback = Instrument::Callback;
    using GainsDone = std::function<void(const std::optional<RequestError>&, const AxisGains&)>;
    using CaptureDone = std::function<void(const std::optional<RequestError>&, const TestCapture&)>;
    using Progress = std::function<void(int received, int total)>;

    virtual void getGains(int axis, GainsDone done) = 0;
    /// Refused (with the device's reason) if a gain is NaN, infinite, negative or
    /// above the device's limit; the previous set then stays in force.
    virtual void setGains(int axis, const motion::control::DiscreteGains& gains, bool keepForPowerUp, Callback done = {}) = 0;
    virtual void startStepTest(const StepTestParams& p, Callback done = {}) = 0;
    virtual void startRelayTest(const RelayTestParams& p, Callback done = {}) = 0;
    /// Realtime: ends the tests on these axes (0 = all); the axes stop where they are.
    virtual void abortTests(quint8 axisMask = 0, Callback done = {}) = 0;
    /// The whole capture of the axis' last test.
    virtual void fetchCapture(int axis, CaptureDone done, Progress progress = {}) = 0;

signals:
    /// A test ended on the device (event TestEnded, TestTripped or TestAborted); text says how.
    void testEnded(int axis, dev::proto::EventKind kind, const QString& text);
    void gainsChanged(int axis, const QString& text);

private:
    QPointer<Instrument> m_instrument;
};

} // namespace dev
