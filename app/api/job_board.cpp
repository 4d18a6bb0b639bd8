#include "job_board.h"

#include "widgets/wording/wording.h"

#include "device/jobs/pattern_runner.h"
#include "device/jobs/recipe_runner.h"
#include "device/jobs/scan_runner.h"

#include <QPointer>

#include <algorithm>
#include <memory>

namespace app::api {

QJsonObject Job::toJson() const
{
    QJsonObject o{{QStringLiteral("id"), id},
                  {QStringLiteral("kind"), kind},
                  {QStringLiteral("instrument"), instrument},
                  {QStringLiteral("owner"), owner},
                  {QStringLiteral("started_by"), startedBy},
                  {QStringLiteral("started"), started.toString(Qt::ISODate)},
                  {QStringLiteral("state"), state},
                  {QStringLiteral("handed_over"), handedOver}};
    if (!progress.isEmpty())
        o.insert(QStringLiteral("progress"), progress);
    return o;
}

JobBoard::JobBoard(QObject* parent) : QObject(parent) {}

QString JobBoard::add(const QString& kind, const QString& instrument, const QString& owner, bool fromApi)
{
    Job j;
    j.id = QStringLiteral("j%1").arg(m_next++);
    j.kind = kind;
    j.instrument = instrument;
    j.owner = owner;
    j.startedBy = owner;
    j.started = QDateTime::currentDateTime();
    j.fromApi = fromApi;
    m_jobs.push_back(j);
    trim();
    ++m_seq;
    emit changed(j.id);
    return j.id;
}

Job* JobBoard::find(const QString& id)
{
    for (auto& j : m_jobs)
        if (j.id == id)
            return &j;
    return nullptr;
}

const Job* JobBoard::job(const QString& id) const { return const_cast<JobBoard*>(this)->find(id); }

void JobBoard::setProgress(const QString& id, const QJsonObject& progress)
{
    if (Job* j = find(id)) {
        j->progress = progress;
        ++m_seq;
        emit changed(id);
    }
}

void JobBoard::finish(const QString& id, const QString& state)
{
    if (Job* j = find(id); j && j->state == QLatin1String("running")) {
        j->state = state;
        ++m_seq;
        emit changed(id);
        trim();
    }
}

void JobBoard::handOver(const QString& id)
{
    if (Job* j = find(id); j && j->state == QLatin1String("running") && j->owner != kOperator) {
        j->owner = kOperator;
        j->handedOver = true;
        ++m_seq;
        emit changed(id);
    }
}

bool JobBoard::anyRunning(const QString& instrument, bool fromApi) const
{
    return std::any_of(m_jobs.begin(), m_jobs.end(), [&](const Job& j) {
        return j.state == QLatin1String("running") && j.fromApi == fromApi && (instrument.isEmpty() || j.instrument == instrument);
    });
}

void JobBoard::trim()
{
    int finished = 0;
    for (const auto& j : m_jobs)
        finished += j.state != QLatin1String("running");
    for (auto it = m_jobs.begin(); it != m_jobs.end() && finished > kKeepFinished;) {
        if (it->state != QLatin1String("running")) {
            it = m_jobs.erase(it);
            --finished;
        } else {
            ++it;
        }
    }
}

namespace {
/// The id of the board entry for a screen's runner while it runs.
struct Watch {
    QString id;
};
} // namespace

void watchRecipeRunner(JobBoard& board, dev::jobs::RecipeRunner* runner, const QString& instrument, const QString& kind)
{
    auto w = std::make_shared<Watch>();
    QPointer<JobBoard> b(&board);
    QObject::connect(runner, &dev::jobs::RecipeRunner::stateChanged, &board, [b, w, runner, instrument, kind](dev::jobs::RunState s) {
        const bool active = s == dev::jobs::RunState::Running || s == dev::jobs::RunState::Pausing || s == dev::jobs::RunState::Paused
            || s == dev::jobs::RunState::Aborting;
        if (active && w->id.isEmpty())
            w->id = b->add(kind, instrument, JobBoard::kOperator, false);
        else if (!active && !w->id.isEmpty()) {
            b->finish(w->id, s == dev::jobs::RunState::Stopped ? QStringLiteral("stopped") : QStringLiteral("finished"));
            w->id.clear();
        }
        (void)runner;
    });
    QObject::connect(runner, &dev::jobs::RecipeRunner::progressChanged, &board, [b, w, runner] {
        if (w->id.isEmpty())
            return;
        const dev::jobs::RunProgress p = runner->progress();
        b->setProgress(w->id, QJsonObject{{QStringLiteral("ops_done"), p.opsDone},
                                          {QStringLiteral("ops"), p.opsTotal},
                                          {QStringLiteral("well"), ui::words::englishText(p.currentWhere)},
                                          {QStringLiteral("elapsed_s"), p.elapsedS},
                                          {QStringLiteral("eta_s"), p.etaS}});
    });
}

void watchScanRunner(JobBoard& board, dev::jobs::ScanRunner* runner, const QString& instrument, const QString& kind)
{
    auto w = std::make_shared<Watch>();
    QPointer<JobBoard> b(&board);
    QObject::connect(runner, &dev::jobs::ScanRunner::stateChanged, &board, [b, w, instrument, kind](dev::jobs::ScanRunner::State s) {
        using S = dev::jobs::ScanRunner::State;
        const bool active = s == S::Running || s == S::Pausing || s == S::Paused;
        if (active && w->id.isEmpty())
            w->id = b->add(kind, instrument, JobBoard::kOperator, false);
        else if (!active && !w->id.isEmpty()) {
            b->finish(w->id, s == S::Finished ? QStringLiteral("finished") : QStringLiteral("stopped"));
            w->id.clear();
        }
    });
    QObject::connect(runner, &dev::jobs::ScanRunner::progress, &board, [b, w](int taken, int total, double etaS) {
        if (!w->id.isEmpty())
            b->setProgress(w->id, QJsonObject{{QStringLiteral("tiles_taken"), taken},
                                              {QStringLiteral("tiles"), total},
                                              {QStringLiteral("eta_s"), etaS}});
    });
}

void watchPatternRunner(JobBoard& board, dev::jobs::PatternRunner* runner, const QString& instrument, const QString& kind)
{
    auto w = std::make_shared<Watch>();
    QPointer<JobBoard> b(&board);
    QObject::connect(runner, &dev::jobs::PatternRunner::stateChanged, &board, [b, w, runner, instrument, kind](dev::jobs::PatternRunner::State s) {
        if (runner->busy() && w->id.isEmpty())
            w->id = b->add(kind, instrument, JobBoard::kOperator, false);
        else if (!runner->busy() && !w->id.isEmpty()) {
            b->finish(w->id, s == dev::jobs::PatternRunner::State::Done ? QStringLiteral("finished") : QStringLiteral("stopped"));
            w->id.clear();
        }
    });
    QObject::connect(runner, &dev::jobs::PatternRunner::progress, &board, [b, w](std::size_t done, std::size_t total) {
        if (!w->id.isEmpty())
            b->setProgress(w->id, QJsonObject{{QStringLiteral("segments_done"), static_cast<qint64>(done)},
                                              {QStringLiteral("segments"), static_cast<qint64>(total)}});
    });
}

} // namespace app::api
