#pragma once
// One closed-loop axis of an instrument as a tuning target: the device runs
// each experiment at its loop rate (STEP_TEST / RELAY_TEST), the end arrives as
// an event, and the capture is read back at the loop rate whatever the link
// carries. A lost link ends the run with linkLost; the device, for its part,
// ends the test by itself within 0.5 s and holds the axis under its gains.
#include "device/client/tuning_client.h"
#include "device/jobs/tuning/tuning_target.h"

#include <QPointer>
#include <QTimer>

namespace dev {

class InstrumentTarget : public TuningTarget {
    Q_OBJECT
public:
    InstrumentTarget(TuningClient* tuning, int axis, const QString& instrumentName, QObject* parent = nullptr);
    int axis() const { return m_axis; }
    TuningClient* tuning() const { return m_tuning; }

    QString describe() const override;
    QString unit() const override { return QStringLiteral("mm"); }
    double controlPeriodS() const override { return m_periodS; }
    motion::control::InputModel inputModel() const override { return motion::control::InputModel::Sampled; }
    double noiseFloor() const override;
    bool ready() const override;
    void runStep(const motion::control::StepSpec& spec, bool trial, double swing, Done done) override;
    void runRelay(const motion::control::RelaySpec& spec, bool continueRun, Done done) override;
    void abort() override;

    /// The loop period comes with the gains (GET_GAINS); until read, HELLO's is assumed.
    void setControlPeriodS(double t) { m_periodS = t; }

private:
    /// Sends the test with `send` and waits for the device's end of it.
    void launch(double maxS, Done done, const std::function<void(TuningClient::Callback)>& send);
    void started(const std::optional<RequestError>& e, double maxS);
    void finish(const RunOutcome& out);
    void fetch();

    QPointer<TuningClient> m_tuning;
    int m_axis;
    QString m_name;
    double m_periodS = 1e-3;
    Done m_done;                 ///< the run in progress
    bool m_running = false;      ///< accepted by the device, end not seen yet
    QTimer m_deadline;           ///< a test that outlives its own envelope by far: the end event was lost
    QList<QMetaObject::Connection> m_watch;
};

} // namespace dev
