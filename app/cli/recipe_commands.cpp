// benchpilot-cli recipe validate | plan | run (docs/recipes.md).
//   validate FILE            every problem, "FILE:LINE:COL: FIELD: MESSAGE"; exit 1 when any is an error
//   plan FILE [--json]       each op with its moves (well, x, y, z, volume) and the total time; nothing moves
//   run FILE [--log RUN.jsonl | --resume RUN.jsonl] [--interrupted=skip|redo] [--home]
// The deck is the built-in analyzer deck unless --deck names another; slots use
// the calibration the GUI keeps (or --calibration FILE, or "none").
#include "cli_session.h"
#include "command.h"
#include "recipe_setup.h"

#include "device/files/recipes/recipe_loader.h"
#include "motion/plans/recipes/plan_bound.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <cmath>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

/// Millimetres and microlitres to the nanometre, seconds to the microsecond:
/// the JSON shows 22.38, not 22.380000000000003.
double r6(double v) { return std::round(v * 1e6) / 1e6; }

QJsonObject moveJson(const motion::plates::MachineMove& m)
{
    QJsonObject o{{QStringLiteral("move"), QString::fromLatin1(motion::plates::moveKindName(m.kind))}};
    switch (m.kind) {
    case motion::plates::MoveKind::Raise:
    case motion::plates::MoveKind::Lower: o.insert(QStringLiteral("z_mm"), r6(m.zMm)); break;
    case motion::plates::MoveKind::Travel:
    case motion::plates::MoveKind::Touch:
        o.insert(QStringLiteral("x_mm"), r6(m.xMm));
        o.insert(QStringLiteral("y_mm"), r6(m.yMm));
        if (m.withZ)
            o.insert(QStringLiteral("z_mm"), r6(m.zMm));  // arched: Z moves there at the same time
        if (m.arch) {  // one blended move: up to the clearance, across, down
            o.insert(QStringLiteral("clear_z_mm"), r6(m.clearZMm));
            o.insert(QStringLiteral("depart_mm"), r6(m.departMm));
            o.insert(QStringLiteral("approach_mm"), r6(m.approachMm));
        }
        if (m.archPump) {  // the plunger inside the well, below its rim; then up to leave_z_mm
            o.insert(QStringLiteral("pump_ul"), r6(m.pumpDeltaUl));
            o.insert(QStringLiteral("liquid_z_mm"), r6(m.liquidZMm));
            o.insert(QStringLiteral("leave_z_mm"), r6(m.leaveZMm));
        }
        break;
    case motion::plates::MoveKind::Pump: o.insert(QStringLiteral("pump_ul"), r6(m.pumpDeltaUl)); break;
    case motion::plates::MoveKind::Dwell: o.insert(QStringLiteral("seconds"), m.seconds); break;
    }
    if (m.speed > 0)
        o.insert(QStringLiteral("speed"), m.speed);
    if (m.deferred)
        o.insert(QStringLiteral("deferred"), true);  // the next op's arched move takes the tip up
    o.insert(QStringLiteral("duration_s"), r6(m.durationS));
    return o;
}

int validate(Invocation& inv)
{
    RecipeSetup setup;
    if (int rc = loadSetup(inv, &setup))
        return rc;
    const dev::files::plates::LoadedRecipe& l = setup.loaded;
    if (inv.json()) {
        QJsonArray errors, warnings;
        for (const motion::msg::Problem& p : l.problems)
            (p.isWarning() ? warnings : errors).append(ui::words::toJson(p));
        inv.printJson(QJsonObject{{QStringLiteral("file"), l.path},
                                               {QStringLiteral("ok"), l.ok()},
                                               {QStringLiteral("errors"), errors},
                                               {QStringLiteral("warnings"), warnings},
                                               {QStringLiteral("ops"), static_cast<int>(l.plan.ops.size())},
                                               {QStringLiteral("total_time_s"), l.plan.totalTimeS}});
    } else {
        for (const motion::msg::Problem& p : l.problems)
            (p.isWarning() ? inv.out() : inv.err()) << ui::words::problem(p) << "\n";
        if (l.ok())
            inv.out() << tr("%1: valid: %2 ops, about %3 s").arg(l.path).arg(l.plan.ops.size()).arg(std::lround(l.plan.totalTimeS)) << "\n";
        else
            inv.err() << tr("%1: %2 errors").arg(l.path).arg(l.errorCount) << "\n";
    }
    inv.out().flush();
    inv.err().flush();
    return l.ok() ? Ok : Usage;
}

int plan(Invocation& inv)
{
    RecipeSetup setup;
    if (int rc = loadSetup(inv, &setup))
        return rc;
    const dev::files::plates::LoadedRecipe& l = setup.loaded;
    if (!l.ok())
        return reportInvalid(inv, l);
    const motion::plates::RecipePlan& p = l.plan;
    if (inv.json()) {
        QJsonArray ops, wells;
        for (const auto& op : p.ops) {
            QJsonArray moves;
            for (const auto& m : op.moves)
                moves.append(moveJson(m));
            QJsonObject o{{QStringLiteral("op"), op.index},
                          {QStringLiteral("step"), op.step},
                          {QStringLiteral("kind"), QString::fromLatin1(motion::plates::stepTypeName(op.type))},
                          {QStringLiteral("volume_ul"), r6(op.volumeUl)},
                          {QStringLiteral("pump_ul"), r6(op.pumpNetUl)},
                          {QStringLiteral("x_mm"), r6(op.at.x)},
                          {QStringLiteral("y_mm"), r6(op.at.y)},
                          {QStringLiteral("start_s"), r6(op.startS)},
                          {QStringLiteral("duration_s"), r6(op.durationS)},
                          {QStringLiteral("moves"), moves}};
            if (!op.well.empty() || !op.station.empty())
                o.insert(QStringLiteral("z_mm"), r6(op.depthZMm));  // where the tip goes down to there
            if (!op.plate.empty())
                o.insert(QStringLiteral("plate"), QString::fromStdString(op.plate));
            if (!op.well.empty())
                o.insert(QStringLiteral("well"), QString::fromStdString(op.well));
            if (!op.station.empty())
                o.insert(QStringLiteral("station"), QString::fromStdString(op.station));
            if (op.round > 0)
                o.insert(QStringLiteral("round"), op.round);
            ops.append(o);
        }
        for (const auto& w : p.wells)
            wells.append(QJsonObject{{QStringLiteral("plate"), QString::fromStdString(w.plate)},
                                     {QStringLiteral("well"), QString::fromStdString(w.well)},
                                     {QStringLiteral("dispensed_ul"), r6(w.dispensedUl)},
                                     {QStringLiteral("aspirated_ul"), r6(w.aspiratedUl)},
                                     {QStringLiteral("visits"), w.visits}});
        QJsonArray warnings;
        for (const motion::msg::Problem& m : l.problems)
            warnings.append(ui::words::toJson(m));
        QJsonObject head{{QStringLiteral("recipe"), QString::fromStdString(l.recipe.name)},
                                               {QStringLiteral("fingerprint"), QString::fromStdString(motion::plates::fingerprintHex(p.fingerprint))},
                                               {QStringLiteral("total_time_s"), r6(p.totalTimeS)},
                                               {QStringLiteral("bound_s"), r6(p.boundS)},
                                               {QStringLiteral("dispensed_ul"), r6(p.totalDispensedUl)},
                                               {QStringLiteral("aspirated_ul"), r6(p.totalAspiratedUl)},
                                               {QStringLiteral("pump_start_ul"), r6(p.pumpStartUl)},
                                               {QStringLiteral("pump_end_ul"), r6(p.pumpEndUl)},
                                               {QStringLiteral("warnings"), warnings},
                                               {QStringLiteral("ops"), ops},
                                               {QStringLiteral("wells"), wells}};
        if (inv.isSet(QStringLiteral("compare-orders"))) {
            QJsonArray orders;
            for (const motion::plates::OrderComparison& c : motion::plates::compareOrders(l.recipe, l.context))
                orders.append(QJsonObject{{QStringLiteral("order"), QString::fromLatin1(motion::plates::wellOrderName(c.order))},
                                          {QStringLiteral("ok"), c.ok},
                                          {QStringLiteral("total_time_s"), r6(c.totalTimeS)},
                                          {QStringLiteral("bound_s"), r6(c.boundS)}});
            head.insert(QStringLiteral("orders"), orders);
        }
        inv.printJson(head);
    } else {
        for (const QString& m : ui::words::problems(l.problems))
            inv.out() << m << "\n";
        for (const auto& op : p.ops)
            inv.out() << QStringLiteral("%1  %2  (%3, %4) mm  Z %5  pump %6 µL  at %7 s\n")
                             .arg(op.index + 1, 5)
                             .arg(ui::words::text(op.label()), -44)
                             .arg(op.at.x, 7, 'f', 2)
                             .arg(op.at.y, 7, 'f', 2)
                             .arg(op.well.empty() && op.station.empty() ? QStringLiteral("     —") : QString::number(op.depthZMm, 'f', 2).rightJustified(6))
                             .arg(op.pumpNetUl, 8, 'f', 2)
                             .arg(op.startS, 8, 'f', 1);
        inv.out() << tr("%1 ops · %2 µL dispensed, %3 µL aspirated · plunger %4 → %5 µL · total %6 s")
                         .arg(p.ops.size())
                         .arg(p.totalDispensedUl)
                         .arg(p.totalAspiratedUl)
                         .arg(p.pumpStartUl)
                         .arg(p.pumpEndUl)
                         .arg(p.totalTimeS, 0, 'f', 1)
                  << "\n";
        inv.out() << tr("time-optimal bound %1 s: the plan takes %2 times the bound").arg(p.boundS, 0, 'f', 1).arg(p.boundS > 0 ? p.totalTimeS / p.boundS : 1.0, 0, 'f', 2)
                  << "\n";
        if (inv.isSet(QStringLiteral("compare-orders")))
            for (const motion::plates::OrderComparison& c : motion::plates::compareOrders(l.recipe, l.context))
                inv.out() << (c.ok ? tr("order %1: %2 s, bound %3 s").arg(QString::fromLatin1(motion::plates::wellOrderName(c.order)), -14).arg(c.totalTimeS, 0, 'f', 1).arg(c.boundS, 0, 'f', 1)
                                   : tr("order %1: a step cannot take it").arg(QString::fromLatin1(motion::plates::wellOrderName(c.order)), -14))
                          << "\n";
    }
    inv.out().flush();
    return Ok;
}

} // namespace

void addRecipeCommands(std::vector<Command>& list)
{
    const QList<QCommandLineOption> setupOptions = recipeSetupOptions();
    auto api = [&](const char* method, Access access) {
        ApiSpec a;
        a.method = QString::fromLatin1(method);
        a.access = access;
        a.params = {{QStringLiteral("file"), ParamType::File, tr("the recipe file"), true, {}, {}},
                    optionParam("deck", ParamType::File), optionParam("calibration", ParamType::Text)};
        a.example = QJsonObject{{QStringLiteral("file"), QStringLiteral("resources/examples/reagent-transfer.recipe.json")},
                                {QStringLiteral("calibration"), QStringLiteral("none")}};
        return a;
    };
    Command recipe{QStringLiteral("recipe"), tr("validate, plan and run dispensing recipes on the analyzer (docs/recipes.md)"), {}, {}, {}, {}, {}};
    recipe.subcommands.push_back({QStringLiteral("validate"), tr("check a recipe: every problem with its line, column and field"),
                                  QStringLiteral("FILE"),
                                  tr("Exit 0 when the recipe can run (warnings allowed), 1 with every error otherwise. Nothing moves."),
                                  setupOptions, validate, {}, api("recipe.validate", Access::Compute)});
    recipe.subcommands.push_back({QStringLiteral("plan"), tr("the dry run: each op and move with well, x, y, z, volume, and the total time"),
                                  QStringLiteral("FILE"), tr("Planned from the machine at home (0, 0, 0) with an empty syringe. Nothing moves."),
                                  QList<QCommandLineOption>(setupOptions)
                                      << QCommandLineOption(QStringLiteral("compare-orders"),
                                                            tr("also plan every well order (as-written, column-major, snake-rows, snake-columns, shortest): time and bound of each")),
                                  plan, {}, [&] {
                                      ApiSpec a = api("recipe.plan", Access::Compute);
                                      a.params << optionParam("compare-orders", ParamType::Boolean);
                                      return a;
                                  }()});
    QList<QCommandLineOption> runOptions = setupOptions;
    runOptions << QCommandLineOption(QStringLiteral("log"), tr("the run log to write (a new file; default RECIPE-DATE.run.jsonl here)"),
                                     QStringLiteral("RUN.jsonl"))
               << QCommandLineOption(QStringLiteral("resume"), tr("continue the run this log records; wells done are not done again"),
                                     QStringLiteral("RUN.jsonl"))
               << QCommandLineOption(QStringLiteral("interrupted"),
                                     tr("a well interrupted after its plunger moved: skip (count it done) or redo it; asked for, never guessed"),
                                     QStringLiteral("skip|redo"))
               << QCommandLineOption(QStringLiteral("home"), tr("home the analyzer first"));
    recipe.subcommands.push_back({QStringLiteral("run"), tr("run a recipe, logging every well so it can be resumed"), QStringLiteral("FILE"),
                                  tr("Prints a line per well (one JSON object with --json). Ctrl+C aborts: the tip rises and the log "
                                     "can resume. Exit 2 when the device refuses or the run stops, 3 when the link is lost."),
                                  runOptions, runRecipe, {}, [&] {
                                      ApiSpec a = api("recipe.run", Access::Control);
                                      a.params << optionParam("log", ParamType::File) << optionParam("resume", ParamType::File);
                                      ApiParam interrupted = optionParam("interrupted", ParamType::Text);
                                      interrupted.choices = QStringList{QStringLiteral("skip"), QStringLiteral("redo")};
                                      a.params << interrupted;
                                      a.example.insert(QStringLiteral("file"), QStringLiteral("resources/examples/api-two-wells.recipe.json"));
                                      a.example.insert(QStringLiteral("log"), QStringLiteral("two-wells.run.jsonl"));
                                      a.example.insert(QStringLiteral("instrument"), QStringLiteral("analyzer"));
                                      a.example.insert(QStringLiteral("home"), true);
                                      return a;
                                  }()});
    list.push_back(std::move(recipe));
}

} // namespace app::cli
