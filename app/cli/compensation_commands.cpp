// benchpilot-cli compensation fit | upload | show | enable | disable | export (docs/accuracy.md):
//   fit INPUT --order auto|N [--out FILE] [--json]   INPUT: a result JSON or a position_mm,error_um CSV
//   upload --axis X FILE                              a compensation file to the device (installed disabled)
//   show|enable|disable --axis X [--save]             what the device holds; enable or disable it
//   export --format linuxcnc|csv [FILE | --axis X]    a compensation file's or the device's, for other tools
#include "accuracy_cli.h"
#include "cli_session.h"
#include "command.h"

#include "device/client/compensation_client.h"
#include "device/files/accuracy/accuracy_result_file.h"
#include "device/files/accuracy/compensation/compensation_exports.h"
#include "device/files/accuracy/compensation/compensation_file.h"
#include "device/files/accuracy/error_curve_csv.h"
#include "device/files/text_file.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QJsonArray>

#include <cmath>

namespace app::cli {
namespace {

using motion::metrology::CompensationModel;

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

QJsonArray numbers(const std::vector<double>& v)
{
    QJsonArray a;
    for (double x : v)
        a.append(x);
    return a;
}

QJsonObject fitJson(const motion::metrology::PolynomialFit& f)
{
    return QJsonObject{{QStringLiteral("order"), f.order},
                       {QStringLiteral("available"), f.available},
                       {QStringLiteral("coefficients_um"), numbers(f.polynomial.coefficientsUm)},
                       {QStringLiteral("sse"), f.sseUm2},
                       {QStringLiteral("r2"), f.r2},
                       {QStringLiteral("adj_r2"), f.adjustedR2}};
}

QJsonObject modelJson(int axis, const QString& letter, const dev::AxisCompensation& c)
{
    QJsonObject o{{QStringLiteral("axis"), letter},
                  {QStringLiteral("present"), c.model.has_value()},
                  {QStringLiteral("enabled"), c.enabled},
                  {QStringLiteral("applied"), c.applied},
                  {QStringLiteral("saved"), c.saved}};
    (void)axis;
    if (!c.model)
        return o;
    const CompensationModel& m = *c.model;
    o.insert(QStringLiteral("backlash_um"), m.backlashUm);
    if (m.kind == CompensationModel::Kind::Polynomial) {
        o.insert(QStringLiteral("kind"), QStringLiteral("polynomial"));
        o.insert(QStringLiteral("polynomial"), QJsonObject{{QStringLiteral("coefficients_um"), numbers(m.polynomial.coefficientsUm)},
                                                          {QStringLiteral("valid_from_mm"), m.validFromMm},
                                                          {QStringLiteral("valid_to_mm"), m.validToMm}});
    } else {
        QJsonArray points;
        for (const auto& p : m.table)
            points.append(QJsonObject{{QStringLiteral("nominal_mm"), p.nominalMm},
                                      {QStringLiteral("correction_up_um"), p.correctionUpUm},
                                      {QStringLiteral("correction_down_um"), p.correctionDownUm}});
        o.insert(QStringLiteral("kind"), QStringLiteral("table"));
        o.insert(QStringLiteral("table"), QJsonObject{{QStringLiteral("per_direction"), m.perDirection}, {QStringLiteral("points"), points}});
    }
    return o;
}

int fit(Invocation& inv)
{
    if (inv.arguments().size() != 1)
        return inv.usage(tr("give one result JSON or error-curve CSV"));
    const QString path = inv.path(inv.arguments().front());
    std::optional<int> order;
    const QString orderText = inv.value(QStringLiteral("order"));
    if (!orderText.isEmpty() && orderText != QLatin1String("auto")) {
        bool ok = false;
        order = orderText.toInt(&ok);
        if (!ok)
            return inv.usage(tr("--order '%1': auto or 1 to 5").arg(orderText));
    }
    std::vector<motion::metrology::FitPoint> points;
    std::string axis = inv.value(QStringLiteral("axis")).toUpper().toStdString();
    double backlashUm = 0;
    std::optional<motion::metrology::Evaluation> evaluation;
    std::string text;
    motion::msg::Message error;
    if (!dev::files::readText(path, &text, &error))
        return reportFailure(inv, error, Usage);
    const std::string name = QFileInfo(path).fileName().toStdString();
    const auto firstChar = text.find_first_not_of(" \t\r\n\xEF\xBB\xBF");
    if (firstChar != std::string::npos && text[firstChar] == '{') {
        const auto read = dev::files::accuracy::accuracyResultFromJson(text, name);
        if (reportProblems(inv, read.problems) || !read.result)
            return Usage;
        points = dev::files::accuracy::fitPointsOf(read.result->evaluation);
        backlashUm = motion::metrology::backlashUmFrom(read.result->evaluation);
        if (axis.empty())
            axis = read.result->axis;
        evaluation = read.result->evaluation;
    } else {
        const auto read = dev::files::accuracy::errorCurveFromCsv(text, name);
        if (reportProblems(inv, read.problems))
            return Usage;
        points = read.points;
    }
    if (axis.empty())
        axis = "X";
    const auto table = motion::metrology::fitPolynomials(points, order);
    if (reportProblems(inv, table.problems, {{QString(), QStringLiteral("--order")}}) || !table.chosen())
        return Usage;
    const auto& chosen = *table.chosen();
    double from = 1e300, to = -1e300;
    for (const auto& p : points) {
        from = std::min(from, p.positionMm);
        to = std::max(to, p.positionMm);
    }
    QJsonArray files;
    const QString kind = inv.value(QStringLiteral("kind")).isEmpty() ? QStringLiteral("polynomial") : inv.value(QStringLiteral("kind"));
    if (kind != QLatin1String("polynomial") && kind != QLatin1String("table"))
        return inv.usage(tr("--kind '%1': polynomial or table").arg(kind));
    if (inv.isSet(QStringLiteral("out"))) {
        dev::files::accuracy::CompensationFile file;
        if (kind == QLatin1String("table")) {
            if (!evaluation)
                return inv.usage(tr("--kind table needs a result JSON: a table is made from each target's means"));
            file.model = motion::metrology::tableModel(axis, *evaluation, inv.isSet(QStringLiteral("per-direction")));
        } else {
            file.model = motion::metrology::polynomialModel(axis, chosen.polynomial, from, to, backlashUm);
            file.fit = dev::files::accuracy::FitRecord{chosen.order, chosen.sseUm2, chosen.r2, chosen.adjustedR2, static_cast<int>(chosen.points),
                                                table.chosenByOperator};
        }
        file.source = name;
        const auto problems = motion::metrology::validate(file.model);
        if (reportProblems(inv, problems))
            return Refused;
        const QString out = inv.path(inv.value(QStringLiteral("out")));
        if (!dev::files::accuracy::saveCompensationFile(out, file, &error))
            return reportFailure(inv, error, Refused);
        files.append(out);
    }
    QJsonArray orders;
    for (const auto& f : table.orders)
        orders.append(fitJson(f));
    const QJsonObject out{{QStringLiteral("axis"), QString::fromStdString(axis)},
                          {QStringLiteral("order"), chosen.order},
                          {QStringLiteral("chosen_by"), table.chosenByOperator ? QStringLiteral("operator") : QStringLiteral("adjusted-r2")},
                          {QStringLiteral("coefficients_um"), numbers(chosen.polynomial.coefficientsUm)},
                          {QStringLiteral("sse"), chosen.sseUm2},
                          {QStringLiteral("r2"), chosen.r2},
                          {QStringLiteral("adj_r2"), chosen.adjustedR2},
                          {QStringLiteral("points"), static_cast<int>(chosen.points)},
                          {QStringLiteral("valid_from_mm"), from},
                          {QStringLiteral("valid_to_mm"), to},
                          {QStringLiteral("backlash_um"), backlashUm},
                          {QStringLiteral("orders"), orders},
                          {QStringLiteral("files"), files}};
    if (inv.json()) {
        printJson(inv, out);
        return Ok;
    }
    inv.out() << tr("order  SSE (µm²)        R²         adjusted R²") << "\n";
    for (const auto& f : table.orders)
        inv.out() << QStringLiteral("%1%2  %3  %4  %5\n")
                         .arg(f.order == chosen.order ? QStringLiteral("*") : QStringLiteral(" "))
                         .arg(f.order)
                         .arg(f.available ? QString::number(f.sseUm2, 'g', 6) : tr("n/a"), -14)
                         .arg(f.available ? QString::number(f.r2, 'f', 6) : QString(), -9)
                         .arg(f.available ? QString::number(f.adjustedR2, 'f', 6) : QString());
    QStringList terms;
    for (std::size_t k = 0; k < chosen.polynomial.coefficientsUm.size(); ++k)
        terms << QStringLiteral("%1·x^%2").arg(chosen.polynomial.coefficientsUm[k], 0, 'g', 6).arg(k);
    inv.out() << tr("e(x) = %1 µm over %2 … %3 mm; backlash %4 µm").arg(terms.join(QStringLiteral(" + "))).arg(from).arg(to).arg(backlashUm, 0, 'f', 2)
              << "\n";
    for (const auto& f : files)
        inv.out() << tr("wrote %1").arg(f.toString()) << "\n";
    return Ok;
}

/// The device's compensation part and the axis: nullptr after reporting why.
dev::CompensationClient* deviceCompensation(Invocation& inv, int* axis)
{
    if (!inv.isSet(QStringLiteral("axis")) || inv.value(QStringLiteral("axis")).size() != 1) {
        inv.usage(tr("give the axis: --axis X"));
        return nullptr;
    }
    CliSession* session = inv.session();
    if (!session)
        return nullptr;
    dev::Instrument* instrument = session->instrument();
    if (!instrument->can(dev::Capability::Compensation) || !instrument->compensation()) {
        reportFailure(inv, instrument->whyNot(dev::Capability::Compensation), Refused);
        return nullptr;
    }
    *axis = instrument->identity().axisIndex(inv.value(QStringLiteral("axis")).toUpper().at(0));
    if (*axis < 0 || !instrument->compensation()->compensableAxes().contains(*axis)) {
        reportFailure(inv, motion::msg::make("accuracy.run.no_such_axis", {motion::msg::verbatim("axis", inv.value(QStringLiteral("axis")).toStdString())}), Usage);
        return nullptr;
    }
    return instrument->compensation();
}

int waitRequest(Invocation& inv, const std::function<void(dev::Instrument::Callback)>& send)
{
    bool done = false;
    std::optional<dev::RequestError> error;
    send([&](const std::optional<dev::RequestError>& e) {
        error = e;
        done = true;
    });
    if (!spinUntil([&] { return done; }, 30000))
        return reportFailure(inv, motion::msg::make("accuracy.run.link_lost"), LinkTrouble);
    if (error) {
        const motion::msg::Message m = motion::msg::make("compensation.device_refused", {motion::msg::nested("detail", error->message)});
        return reportFailure(inv, m, error->kind == dev::RequestError::Kind::LinkDown || error->kind == dev::RequestError::Kind::Timeout ? LinkTrouble : Refused);
    }
    return Ok;
}

int readBack(Invocation& inv, dev::CompensationClient* c, int axis, dev::AxisCompensation* out)
{
    bool done = false;
    std::optional<dev::RequestError> error;
    c->read(axis, [&](const std::optional<dev::RequestError>& e, const dev::AxisCompensation& got) {
        error = e;
        *out = got;
        done = true;
    });
    if (!spinUntil([&] { return done; }, 30000))
        return reportFailure(inv, motion::msg::make("accuracy.run.link_lost"), LinkTrouble);
    if (error)
        return reportFailure(inv, motion::msg::make("compensation.device_refused", {motion::msg::nested("detail", error->message)}), Refused);
    return Ok;
}

void printShown(Invocation& inv, int axis, const dev::AxisCompensation& c)
{
    const QString letter = inv.value(QStringLiteral("axis")).toUpper();
    if (inv.json()) {
        printJson(inv, modelJson(axis, letter, c));
        return;
    }
    if (!c.model) {
        inv.out() << tr("axis %1: no compensation").arg(letter) << "\n";
        return;
    }
    const auto& m = *c.model;
    QString what = m.kind == CompensationModel::Kind::Polynomial
        ? tr("polynomial of order %1 over %2 … %3 mm").arg(m.polynomial.coefficientsUm.size() - 1).arg(m.validFromMm).arg(m.validToMm)
        : tr("table of %1 points%2").arg(m.table.size()).arg(m.perDirection ? tr(" per direction") : QString());
    inv.out() << tr("axis %1: %2, backlash %3 µm; %4%5%6")
                     .arg(letter, what)
                     .arg(m.backlashUm, 0, 'f', 2)
                     .arg(c.enabled ? tr("enabled") : tr("disabled"))
                     .arg(c.enabled && !c.applied ? tr(" (applied once the axis is homed)") : QString())
                     .arg(c.saved ? tr(", kept for power-up") : QString())
              << "\n";
}

int upload(Invocation& inv)
{
    if (inv.arguments().size() != 1)
        return inv.usage(tr("give one compensation file"));
    const auto read = dev::files::accuracy::loadCompensationFile(inv.path(inv.arguments().front()));
    if (reportProblems(inv, read.problems) || !read.compensation)
        return Usage;
    int axis = -1;
    dev::CompensationClient* c = deviceCompensation(inv, &axis);
    if (!c)
        return inv.session() ? Refused : LinkTrouble;
    if (int rc = waitRequest(inv, [&](auto cb) { c->upload(axis, read.compensation->model, cb); }))
        return rc;
    if (inv.isSet(QStringLiteral("enable")))
        if (int rc = waitRequest(inv, [&](auto cb) { c->setEnabled(axis, true, inv.isSet(QStringLiteral("save")), cb); }))
            return rc;
    dev::AxisCompensation got;
    if (int rc = readBack(inv, c, axis, &got))
        return rc;
    printShown(inv, axis, got);
    return Ok;
}

int show(Invocation& inv)
{
    int axis = -1;
    dev::CompensationClient* c = deviceCompensation(inv, &axis);
    if (!c)
        return Refused;
    dev::AxisCompensation got;
    if (int rc = readBack(inv, c, axis, &got))
        return rc;
    printShown(inv, axis, got);
    return Ok;
}

int setEnabled(Invocation& inv, bool on)
{
    int axis = -1;
    dev::CompensationClient* c = deviceCompensation(inv, &axis);
    if (!c)
        return Refused;
    if (int rc = waitRequest(inv, [&](auto cb) { c->setEnabled(axis, on, inv.isSet(QStringLiteral("save")), cb); }))
        return rc;
    dev::AxisCompensation got;
    if (int rc = readBack(inv, c, axis, &got))
        return rc;
    printShown(inv, axis, got);
    return Ok;
}

int exportCompensation(Invocation& inv)
{
    const QString format = inv.value(QStringLiteral("format"));
    if (format != QLatin1String("linuxcnc") && format != QLatin1String("csv"))
        return inv.usage(tr("--format '%1': linuxcnc or csv").arg(format));
    CompensationModel model;
    if (!inv.arguments().isEmpty()) {
        const auto read = dev::files::accuracy::loadCompensationFile(inv.path(inv.arguments().front()));
        if (reportProblems(inv, read.problems) || !read.compensation)
            return Usage;
        model = read.compensation->model;
    } else {
        int axis = -1;
        dev::CompensationClient* c = deviceCompensation(inv, &axis);
        if (!c)
            return Refused;
        dev::AxisCompensation got;
        if (int rc = readBack(inv, c, axis, &got))
            return rc;
        if (!got.model)
            return reportFailure(inv, motion::msg::make("compensation.none_on_device", {motion::msg::verbatim("axis", inv.value(QStringLiteral("axis")).toStdString())}), Refused);
        model = *got.model;
    }
    std::string text;
    if (format == QLatin1String("csv")) {
        text = dev::files::accuracy::compensationCsv(model);
    } else {
        const QString type = inv.value(QStringLiteral("type"));
        if (type != QLatin1String("0") && type != QLatin1String("1"))
            return inv.usage(tr("--type '%1': 0 (positions reached) or 1 (corrections)").arg(type));
        text = dev::files::accuracy::linuxcncCompensation(model, type == QLatin1String("0") ? dev::files::accuracy::LinuxcncCompType::ActualPositions
                                                                                     : dev::files::accuracy::LinuxcncCompType::Corrections);
    }
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

void addCompensationCommands(std::vector<Command>& list)
{
    const QCommandLineOption axis = option("axis", "the axis", "letter");
    const QCommandLineOption save = option("save", "also keep it for power-up on the device");
    Command comp{QStringLiteral("compensation"), tr("axis error compensation: fit, keep on the device, export"), QString(), QString(), {}, {}, {}};
    comp.subcommands = {
        {QStringLiteral("fit"), tr("fit error polynomials of orders 1–5 to a result or an error curve"), tr("INPUT"),
         tr("INPUT is a result JSON of 'accuracy run' or 'accuracy analyze', or a CSV with position_mm,error_um. The order is "
            "chosen by adjusted R² unless --order names one; --out writes the compensation file."),
         {option("order", "auto or 1 to 5", "order", "auto"), option("out", "write the compensation file", "file"),
          option("kind", "polynomial or table (a table needs a result JSON)", "kind", "polynomial"),
          option("per-direction", "a table with a column per approach direction"), option("axis", "the axis, if the input does not say", "letter")},
         &fit, {}},
        {QStringLiteral("upload"), tr("send a compensation file to the device (installed disabled)"), tr("FILE"), QString(),
         {axis, option("enable", "enable it once installed"), save}, &upload, {}},
        {QStringLiteral("show"), tr("the device's compensation of an axis"), QString(), QString(), {axis}, &show, {}},
        {QStringLiteral("enable"), tr("enable the device's compensation of an axis"), QString(), QString(), {axis, save},
         [](Invocation& inv) { return setEnabled(inv, true); }, {}},
        {QStringLiteral("disable"), tr("disable the device's compensation of an axis"), QString(), QString(), {axis, save},
         [](Invocation& inv) { return setEnabled(inv, false); }, {}},
        {QStringLiteral("export"), tr("a compensation as CSV or a LinuxCNC compensation file"), tr("[FILE]"),
         tr("Exports FILE, or the device's compensation of --axis when no FILE is given. LinuxCNC: --type 0 writes the "
            "positions the joint reaches, --type 1 the corrections (COMP_FILE_TYPE)."),
         {option("format", "linuxcnc or csv", "format"), option("type", "LinuxCNC's COMP_FILE_TYPE, 0 or 1", "n", "1"),
          option("out", "write here instead of standard output", "file"), axis},
         &exportCompensation, {}},
    };
    const QJsonObject onStageX{{QStringLiteral("instrument"), QStringLiteral("stage")}, {QStringLiteral("axis"), QStringLiteral("X")}};
    ApiParam order = optionParam("order", ParamType::Text);
    order.choices = QStringList{QStringLiteral("auto"), QStringLiteral("1"), QStringLiteral("2"), QStringLiteral("3"), QStringLiteral("4"),
                                QStringLiteral("5")};
    ApiParam kind = optionParam("kind", ParamType::Text);
    kind.choices = QStringList{QStringLiteral("polynomial"), QStringLiteral("table")};
    ApiParam format = optionParam("format", ParamType::Text);
    format.choices = QStringList{QStringLiteral("linuxcnc"), QStringLiteral("csv")};
    ApiParam type = optionParam("type", ParamType::Text);
    type.choices = QStringList{QStringLiteral("0"), QStringLiteral("1")};
    for (Command& c : comp.subcommands) {
        ApiSpec& a = c.api;
        a.params << optionParam("axis", ParamType::Axis);
        if (c.name == QLatin1String("fit")) {
            a.access = Access::Compute;
            a.params.prepend({QStringLiteral("input"), ParamType::File, tr("a result JSON, or a CSV with position_mm,error_um"), true, {}, {}});
            a.params << order << kind << optionParam("out", ParamType::File);
            a.example = QJsonObject{{QStringLiteral("input"), QStringLiteral("resources/examples/stage-x-interferometer.accuracy-result.json")},
                                    {QStringLiteral("order"), QStringLiteral("auto")}, {QStringLiteral("out"), QStringLiteral("x.compensation.json")}};
        } else if (c.name == QLatin1String("upload")) {
            a.access = Access::Control;
            a.params.prepend({QStringLiteral("file"), ParamType::File, tr("the compensation file"), true, {}, {}});
            a.example = onStageX;
            a.example.insert(QStringLiteral("file"), QStringLiteral("resources/examples/stage-x-fit.compensation.json"));
            a.example.insert(QStringLiteral("enable"), true);
        } else if (c.name == QLatin1String("show")) {
            a.access = Access::Read;
            a.example = onStageX;
        } else if (c.name == QLatin1String("export")) {
            // Reads the device's compensation when no file is given.
            a.access = Access::Read;
            a.params.prepend({QStringLiteral("file"), ParamType::File, tr("a compensation file; the device's when left out"), false, {}, {}});
            a.params << format << type << optionParam("out", ParamType::File);
            a.example = onStageX;
            a.example.insert(QStringLiteral("format"), QStringLiteral("csv"));
        } else {  // enable, disable
            a.access = Access::Control;
            a.example = onStageX;
        }
    }
    list.push_back(comp);
}

} // namespace app::cli
