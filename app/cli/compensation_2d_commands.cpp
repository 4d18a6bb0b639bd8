// benchpilot-cli compensation fit-2d | upload-2d | enable-2d | disable-2d | show-2d | export-2d
// (docs/accuracy.md, "2D compensation table"):
//   fit-2d RESULT.json --out TABLE.json     a grid map's result file to a 2D table
//   upload-2d TABLE.json [--enable] [--save]  the table to the device (installed disabled)
//   enable-2d | disable-2d [--save]          on the device; show-2d: what it holds
//   export-2d TABLE.json [--out FILE.csv]    the table as CSV
#include "accuracy_cli.h"
#include "cli_session.h"
#include "command.h"

#include "device/client/compensation_2d_client.h"
#include "device/files/accuracy/grid/compensation_2d_file.h"
#include "device/files/accuracy/grid/grid_map_result_file.h"
#include "device/files/text_file.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

QJsonObject state2dJson(const dev::Compensation2dState& s)
{
    return QJsonObject{{QStringLiteral("installed"), s.installed}, {QStringLiteral("enabled"), s.enabled},
                       {QStringLiteral("applied"), s.applied},     {QStringLiteral("saved"), s.saved},
                       {QStringLiteral("columns"), s.columns},     {QStringLiteral("rows"), s.rows}};
}

void printState2d(Invocation& inv, const dev::Compensation2dState& s)
{
    if (inv.json()) {
        printJson(inv, state2dJson(s));
        return;
    }
    if (!s.installed) {
        inv.out() << tr("no 2D compensation table on the device") << "\n";
        return;
    }
    inv.out() << tr("2D table of %1 × %2 nodes; %3%4%5")
                     .arg(s.columns)
                     .arg(s.rows)
                     .arg(s.enabled ? tr("enabled") : tr("disabled"))
                     .arg(s.enabled && !s.applied ? tr(" (applied once X and Y are homed)") : QString())
                     .arg(s.saved ? tr(", kept for power-up") : QString())
              << "\n";
}

/// The device's 2D table part: nullptr after reporting why.
dev::Compensation2dClient* device2d(Invocation& inv)
{
    CliSession* session = inv.session();
    if (!session)
        return nullptr;
    dev::Compensation2dClient* c = session->instrument()->compensation2d();
    if (!c || !c->available()) {
        reportFailure(inv, motion::msg::make("compensation2d.not_supported"), Refused);
        return nullptr;
    }
    return c;
}

int wait2d(Invocation& inv, const std::function<void(dev::Compensation2dClient::StateDone)>& send, dev::Compensation2dState* state)
{
    bool done = false;
    std::optional<dev::RequestError> error;
    send([&](const std::optional<dev::RequestError>& e, const dev::Compensation2dState& s) {
        error = e;
        if (state)
            *state = s;
        done = true;
    });
    if (!spinUntil([&] { return done; }, 30000))
        return reportFailure(inv, motion::msg::make("accuracy.run.link_lost"), LinkTrouble);
    if (error)
        return reportFailure(inv, motion::msg::make("compensation.device_refused", {motion::msg::nested("detail", error->message)}),
                             error->kind == dev::RequestError::Kind::LinkDown || error->kind == dev::RequestError::Kind::Timeout
                                 ? LinkTrouble
                                 : Refused);
    return Ok;
}

int fit2d(Invocation& inv)
{
    if (inv.arguments().size() != 1)
        return inv.usage(tr("give one grid map result file"));
    if (!inv.isSet(QStringLiteral("out")))
        return inv.usage(tr("give the table file to write: --out FILE"));
    const QString input = inv.path(inv.arguments().front());
    const auto read = dev::files::accuracy::loadGridMapResultFile(input);
    if (reportProblems(inv, read.problems()) || !read.ok())
        return Usage;
    const auto table = motion::metrology::compensationFromMap(read->result);
    if (!table)
        return reportFailure(inv, motion::msg::make("compensation2d.map_not_a_grid", {motion::msg::verbatim("file", QFileInfo(input).fileName().toStdString())}), Usage);
    motion::msg::Problems problems;
    for (auto p : motion::metrology::validate(*table)) {
        p.file = QFileInfo(input).fileName().toStdString();
        problems.push_back(p);
    }
    if (reportProblems(inv, problems))
        return Usage;
    const QString out = inv.path(inv.value(QStringLiteral("out")));
    motion::msg::Message error;
    if (!dev::files::accuracy::saveCompensation2DFile(out, {*table, QFileInfo(input).fileName().toStdString()}, &error))
        return reportFailure(inv, error, Refused);
    if (inv.json()) {
        printJson(inv, QJsonObject{{QStringLiteral("ok"), true},
                                   {QStringLiteral("columns"), table->columns},
                                   {QStringLiteral("rows"), table->rows},
                                   {QStringLiteral("pitch_x_mm"), table->pitchXMm},
                                   {QStringLiteral("pitch_y_mm"), table->pitchYMm},
                                   {QStringLiteral("files"), QJsonArray{out}}});
        return Ok;
    }
    inv.out() << tr("2D table of %1 × %2 nodes, every %3 × %4 mm from (%5, %6) mm")
                     .arg(table->columns)
                     .arg(table->rows)
                     .arg(table->pitchXMm)
                     .arg(table->pitchYMm)
                     .arg(table->originXMm)
                     .arg(table->originYMm)
              << "\n"
              << tr("wrote %1").arg(out) << "\n";
    return Ok;
}

int upload2d(Invocation& inv)
{
    if (inv.arguments().size() != 1)
        return inv.usage(tr("give one 2D compensation table file"));
    const auto read = dev::files::accuracy::loadCompensation2DFile(inv.path(inv.arguments().front()));
    if (reportProblems(inv, read.problems()) || !read.ok())
        return Usage;
    dev::Compensation2dClient* c = device2d(inv);
    if (!c)
        return inv.session() ? Refused : LinkTrouble;
    bool done = false;
    std::optional<dev::RequestError> error;
    c->upload(read->table, [&](const std::optional<dev::RequestError>& e) {
        error = e;
        done = true;
    });
    if (!spinUntil([&] { return done; }, 30000))
        return reportFailure(inv, motion::msg::make("accuracy.run.link_lost"), LinkTrouble);
    if (error)
        return reportFailure(inv, motion::msg::make("compensation.device_refused", {motion::msg::nested("detail", error->message)}), Refused);
    dev::Compensation2dState s;
    const bool on = inv.isSet(QStringLiteral("enable"));
    if (int rc = on ? wait2d(inv, [&](auto cb) { c->setEnabled(true, inv.isSet(QStringLiteral("save")), cb); }, &s)
                    : wait2d(inv, [&](auto cb) { c->state(cb); }, &s))
        return rc;
    printState2d(inv, s);
    return Ok;
}

int setEnabled2d(Invocation& inv, bool on)
{
    dev::Compensation2dClient* c = device2d(inv);
    if (!c)
        return inv.session() ? Refused : LinkTrouble;
    dev::Compensation2dState s;
    if (int rc = wait2d(inv, [&](auto cb) { c->setEnabled(on, inv.isSet(QStringLiteral("save")), cb); }, &s))
        return rc;
    printState2d(inv, s);
    return Ok;
}

int show2d(Invocation& inv)
{
    dev::Compensation2dClient* c = device2d(inv);
    if (!c)
        return inv.session() ? Refused : LinkTrouble;
    dev::Compensation2dState s;
    if (int rc = wait2d(inv, [&](auto cb) { c->state(cb); }, &s))
        return rc;
    printState2d(inv, s);
    return Ok;
}

int export2d(Invocation& inv)
{
    if (inv.arguments().size() != 1)
        return inv.usage(tr("give one 2D compensation table file"));
    const auto read = dev::files::accuracy::loadCompensation2DFile(inv.path(inv.arguments().front()));
    if (reportProblems(inv, read.problems()) || !read.ok())
        return Usage;
    const std::string text = dev::files::accuracy::compensation2DToCsv(read->table);
    if (inv.isSet(QStringLiteral("out"))) {
        motion::msg::Message error;
        const QString out = inv.path(inv.value(QStringLiteral("out")));
        if (!dev::files::writeAtomically(out, text, &error))
            return reportFailure(inv, error, Refused);
        if (inv.json())
            printJson(inv, QJsonObject{{QStringLiteral("ok"), true}, {QStringLiteral("files"), QJsonArray{out}}});
        return Ok;
    }
    inv.out() << QString::fromStdString(text);
    inv.out().flush();
    return Ok;
}

} // namespace

void addCompensation2dSubcommands(Command& comp)
{
    const QCommandLineOption save = option("save", "also keep it for power-up on the device");
    std::vector<Command> more = {
        {QStringLiteral("fit-2d"), tr("a 2D compensation table from a grid map's result file"), tr("RESULT"),
         tr("RESULT is a benchpilot.grid-map-result file; the table has a node at each of its nodes, with the X and Y "
              "corrections that put the work point on them."),
         {option("out", "write the 2D table file", "file")}, &fit2d, {}},
        {QStringLiteral("upload-2d"), tr("send a 2D compensation table to the device (installed disabled)"), tr("FILE"), QString(),
         {option("enable", "enable it once installed"), save}, &upload2d, {}},
        {QStringLiteral("show-2d"), tr("the device's 2D compensation table"), QString(), QString(), {}, &show2d, {}},
        {QStringLiteral("enable-2d"), tr("enable the device's 2D compensation table"), QString(), QString(), {save},
         [](Invocation& inv) { return setEnabled2d(inv, true); }, {}},
        {QStringLiteral("disable-2d"), tr("disable the device's 2D compensation table"), QString(), QString(), {save},
         [](Invocation& inv) { return setEnabled2d(inv, false); }, {}},
        {QStringLiteral("export-2d"), tr("a 2D compensation table as CSV"), tr("FILE"), QString(),
         {option("out", "write here instead of standard output", "file")}, &export2d, {}},
    };
    // The scripting API offers the same methods (compensation.fit_2d, upload_2d, show_2d,
    // enable_2d, disable_2d, export_2d), each with its worked example in docs/api.md.
    Command& fit = more[0];
    fit.api.access = Access::Compute;
    fit.api.params = {{QStringLiteral("result"), ParamType::File, tr("the grid map's result file"), true, {}, {}},
                      optionParam("out", ParamType::File, true)};
    fit.api.example = QJsonObject{{QStringLiteral("result"), QStringLiteral("resources/examples/stage-example.grid-map-result.json")},
                                  {QStringLiteral("out"), QStringLiteral("stage.compensation-2d.json")}};
    Command& upload = more[1];
    upload.api.access = Access::Control;
    upload.api.params = {{QStringLiteral("table"), ParamType::File, tr("the 2D compensation table file"), true, {}, {}},
                         optionParam("enable", ParamType::Boolean), optionParam("save", ParamType::Boolean)};
    upload.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")},
                                     {QStringLiteral("table"), QStringLiteral("resources/examples/stage-example.compensation-2d.json")}};
    Command& show = more[2];
    show.api.access = Access::Read;
    show.api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}};
    for (Command* c : {&more[3], &more[4]}) {
        c->api.access = Access::Control;
        c->api.params = {optionParam("save", ParamType::Boolean)};
        c->api.example = QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")}};
    }
    Command& exportCmd = more[5];
    exportCmd.api.access = Access::Compute;
    exportCmd.api.params = {{QStringLiteral("table"), ParamType::File, tr("the 2D compensation table file"), true, {}, {}},
                            optionParam("out", ParamType::File)};
    exportCmd.api.example = QJsonObject{{QStringLiteral("table"), QStringLiteral("resources/examples/stage-example.compensation-2d.json")},
                                        {QStringLiteral("out"), QStringLiteral("stage.compensation-2d.csv")}};
    for (Command& c : more)
        comp.subcommands.push_back(std::move(c));
}

} // namespace app::cli
