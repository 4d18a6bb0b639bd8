// The Calibration screen's runs on the job board (the operator's jobs): an accuracy
// run's readings and a circular test's share of its circles, while they run or wait
// paused. A runner lives for one run; one that goes away while listed ends its entry.
#include "job_board.h"

#include "device/jobs/accuracy/accuracy_runner.h"
#include "device/jobs/accuracy/circle_runner.h"

#include <QPointer>

#include <memory>

namespace app::api {
namespace {

struct Watch {
    QString id;
};

/// Adds the entry when `active` turns true, finishes it when it turns false, and ends it
/// as stopped if the runner is destroyed while listed.
template <typename Runner, typename State>
void watchStates(JobBoard& board, Runner* runner, const QString& instrument, const QString& kind, const std::shared_ptr<Watch>& w)
{
    QPointer<JobBoard> b(&board);
    QObject::connect(runner, &Runner::stateChanged, &board, [b, w, instrument, kind](State s) {
        const bool active = s == State::Running || s == State::Pausing || s == State::Paused;
        if (active && w->id.isEmpty())
            w->id = b->add(kind, instrument, JobBoard::kOperator, false);
        else if (!active && !w->id.isEmpty()) {
            b->finish(w->id, s == State::Finished ? QStringLiteral("finished") : QStringLiteral("stopped"));
            w->id.clear();
        }
    });
    QObject::connect(runner, &QObject::destroyed, &board, [b, w] {
        if (b && !w->id.isEmpty())
            b->finish(w->id, QStringLiteral("stopped"));
        w->id.clear();
    });
}

} // namespace

void watchAccuracyRunner(JobBoard& board, dev::jobs::AccuracyRunner* runner, const QString& instrument, const QString& kind)
{
    auto w = std::make_shared<Watch>();
    watchStates<dev::jobs::AccuracyRunner, dev::jobs::AccuracyRunner::State>(board, runner, instrument, kind, w);
    QPointer<JobBoard> b(&board);
    QObject::connect(runner, &dev::jobs::AccuracyRunner::progress, &board, [b, w](int taken, int total, double etaS) {
        if (!w->id.isEmpty())
            b->setProgress(w->id, QJsonObject{{QStringLiteral("readings_taken"), taken},
                                              {QStringLiteral("readings"), total},
                                              {QStringLiteral("eta_s"), etaS}});
    });
}

void watchCircleRunner(JobBoard& board, dev::jobs::CircleRunner* runner, const QString& instrument, const QString& kind)
{
    auto w = std::make_shared<Watch>();
    watchStates<dev::jobs::CircleRunner, dev::jobs::CircleRunner::State>(board, runner, instrument, kind, w);
    QPointer<JobBoard> b(&board);
    QObject::connect(runner, &dev::jobs::CircleRunner::progress, &board, [b, w](double fraction, double etaS) {
        if (!w->id.isEmpty())
            b->setProgress(w->id, QJsonObject{{QStringLiteral("fraction"), fraction}, {QStringLiteral("eta_s"), etaS}});
    });
}

} // namespace app::api
