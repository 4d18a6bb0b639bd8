// benchpilot-cli recipe run: a recipe on the analyzer through dev::jobs::RecipeRunner,
// a line per well, resumable from its run log. Ctrl+C (or SIGTERM; call.cancel
// through the API) aborts cleanly: the machine stops, the tip rises, the log says
// where it stopped.
#include "cli_session.h"
#include "recipe_setup.h"

#include "device/jobs/machine_model.h"
#include "device/jobs/recipe_runner.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>

#include <cmath>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

QString clock(double s)
{
    const long t = std::lround(std::max(0.0, s));
    return QStringLiteral("%1:%2").arg(t / 60).arg(t % 60, 2, 10, QLatin1Char('0'));
}


} // namespace

int runRecipe(Invocation& inv)
{
    const bool resuming = inv.isSet(QStringLiteral("resume"));
    if (resuming && inv.isSet(QStringLiteral("log")))
        return inv.usage(tr("give --log for a new run or --resume for one to continue, not both"));
    const QString interrupted = inv.value(QStringLiteral("interrupted"));
    if (!interrupted.isEmpty() && interrupted != QLatin1String("skip") && interrupted != QLatin1String("redo"))
        return inv.usage(tr("--interrupted must be skip or redo (got '%1')").arg(interrupted));
    RecipeSetup setup;
    if (int rc = loadSetup(inv, &setup))
        return rc;
    const dev::files::plates::LoadedRecipe& l = setup.loaded;
    if (!l.ok()) {
        reportInvalid(inv, l);
        return inv.usage(tr("%1 does not validate: nothing moved").arg(l.path));
    }
    QString logPath;
    if (resuming) {
        logPath = inv.path(inv.value(QStringLiteral("resume")));
        if (!QFileInfo::exists(logPath))
            return inv.usage(tr("no run log %1 to resume").arg(logPath));
    } else if (inv.isSet(QStringLiteral("log"))) {
        logPath = inv.path(inv.value(QStringLiteral("log")));
    } else {
        QString stem = QFileInfo(l.path).fileName();
        stem.remove(QRegularExpression(QStringLiteral("(\\.recipe)?\\.json$")));
        logPath = inv.path(QStringLiteral("%1-%2.run.jsonl").arg(stem, QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss"))));
    }
    if (!resuming && QFileInfo::exists(logPath))
        return inv.usage(tr("%1 exists: a run log is never overwritten (continue it with --resume, or name another with --log)").arg(logPath));

    CliSession* s = inv.session();
    if (!s)
        return LinkTrouble;
    dev::Instrument* c = s->instrument();
    if (inv.isSet(QStringLiteral("home"))) {
        if (int rc = s->request([&](auto cb) { c->home(0, cb); }, tr("home")))
            return rc;
        if (int rc = s->waitUntilStill(tr("home")))
            return rc;
    }
    // After a killed run the analyzer may still finish the move it had: wait for
    // two fresh status polls that show it still.
    int fresh = 0;
    auto conn = QObject::connect(c, &dev::Instrument::statusChanged, s, [&fresh] { ++fresh; });
    spinUntil([&] { return c->state() != dev::LinkState::Ready || (fresh >= 2 && !c->status().anyMoving()); }, 30000);
    QObject::disconnect(conn);

    motion::plates::StartState start;
    const auto& axes = c->status().axes;
    if (axes.size() >= 4)
        start = {axes[0].commanded, axes[1].commanded, axes[2].commanded, axes[3].commanded};
    if (resuming)
        start = dev::jobs::RecipeRunner::resumeStart(logPath, *c);
    // Times (the ETA) follow the analyzer's own planner limits when it reports them.
    motion::plates::PlanContext context = l.context;
    context.deck = dev::jobs::deckWithDeviceMotion(context.deck, c->identity());
    const motion::plates::RecipePlan plan = motion::plates::planRecipe(l.recipe, context, start);
    dev::jobs::RecipeRunner runner(c);
    motion::msg::Message error;
    const QString name = QString::fromStdString(l.recipe.name.empty() ? QFileInfo(l.path).fileName().toStdString() : l.recipe.name);
    if (!runner.setPlan(plan, name, &error))
        return inv.refused(ui::words::text(error));

    QTextStream& out = inv.out();
    QObject::connect(&runner, &dev::jobs::RecipeRunner::message, &runner, [&](const motion::msg::Message& text, bool problem) {
        if (inv.json())
            inv.printJson(QJsonObject{{QStringLiteral("event"), problem ? QStringLiteral("problem") : QStringLiteral("note")},
                                      {QStringLiteral("text"), ui::words::toJson(text)}});
        else
            (problem ? inv.err() : out) << ui::words::text(text) << "\n";
        inv.err().flush();
        out.flush();
    });
    QObject::connect(&runner, &dev::jobs::RecipeRunner::opFinished, &runner, [&](int op) {
        const dev::jobs::RunProgress p = runner.progress();
        const motion::plates::PlanOp& o = plan.ops[static_cast<std::size_t>(op)];
        if (inv.json()) {
            QJsonObject line{{QStringLiteral("event"), QStringLiteral("done")},
                             {QStringLiteral("op"), op},
                             {QStringLiteral("kind"), QString::fromLatin1(motion::plates::stepTypeName(o.type))},
                             {QStringLiteral("volume_ul"), o.volumeUl},
                             {QStringLiteral("ops_done"), p.opsDone},
                             {QStringLiteral("ops"), p.opsTotal},
                             {QStringLiteral("elapsed_s"), p.elapsedS},
                             {QStringLiteral("eta_s"), p.etaS}};
            if (!o.well.empty()) {
                line.insert(QStringLiteral("plate"), QString::fromStdString(o.plate));
                line.insert(QStringLiteral("well"), QString::fromStdString(o.well));
            }
            inv.printJson(line);
        } else {
            out << QStringLiteral("[%1/%2] %3 · %4 elapsed · ETA %5\n")
                       .arg(p.opsDone, QString::number(p.opsTotal).size())
                       .arg(p.opsTotal)
                       .arg(ui::words::text(o.label()), clock(p.elapsedS), clock(p.etaS));
            out.flush();
        }
    });

    bool needDecision = false;
    const dev::jobs::InterruptedDecider decide = [&](const dev::jobs::InterruptedOp& op) {
        inv.report(tr("%1 was interrupted after its plunger move was sent: %2").arg(ui::words::text(op.label), ui::words::text(op.evidence)));
        if (interrupted == QLatin1String("skip"))
            return dev::jobs::InterruptedChoice::Skip;
        if (interrupted == QLatin1String("redo"))
            return dev::jobs::InterruptedChoice::Redo;
        needDecision = true;
        return dev::jobs::InterruptedChoice::Cancel;
    };
    // Ctrl+C here, a cancelled call through the GUI's API.
    const auto interrupt = inv.host().onInterrupt([&runner, &inv] {
        inv.report(tr("interrupted: aborting (the tip rises, the log can resume)"));
        runner.abort();
    });
    const bool started = resuming ? runner.resumeFromLog(logPath, decide, &error) : runner.start(logPath, &error);
    if (!started) {
        if (needDecision)
            return inv.usage(tr("not resumed: say --interrupted=skip (count the well as done) or --interrupted=redo (do it again)"));
        return inv.refused(ui::words::text(error));
    }
    if (!inv.json())
        out << tr("log: %1").arg(logPath) << "\n";
    out.flush();
    spinUntil([&] { return runner.state() == dev::jobs::RunState::Finished || runner.state() == dev::jobs::RunState::Stopped; }, INT32_MAX);
    const dev::jobs::RunProgress p = runner.progress();
    const bool finished = runner.state() == dev::jobs::RunState::Finished;
    if (inv.json())
        inv.printJson(QJsonObject{{QStringLiteral("event"), finished ? QStringLiteral("finished") : QStringLiteral("stopped")},
                                  {QStringLiteral("ops_done"), p.opsDone},
                                  {QStringLiteral("ops"), p.opsTotal},
                                  {QStringLiteral("elapsed_s"), p.elapsedS},
                                  {QStringLiteral("log"), logPath}});
    if (finished) {
        if (!inv.json())
            out << tr("finished: %1 of %2 operations in %3").arg(p.opsDone).arg(p.opsTotal).arg(clock(p.elapsedS)) << "\n";
        out.flush();
        return Ok;
    }
    inv.report(tr("stopped after %1 of %2 operations; continue with: benchpilot-cli recipe run %3 --resume %4")
                   .arg(p.opsDone)
                   .arg(p.opsTotal)
                   .arg(l.path, logPath));
    return c->state() == dev::LinkState::Ready ? Refused : LinkTrouble;
}

} // namespace app::cli
