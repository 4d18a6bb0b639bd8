#include "accuracy_cli.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QJsonDocument>

#include <cmath>

namespace app::cli {
namespace {
QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }
} // namespace

double nm6(double v) { return std::round(v * 1e6) / 1e6; }

QJsonObject messageJson(const motion::msg::Message& m) { return ui::words::toJson(m); }

QJsonObject problemJson(const motion::msg::Problem& p)
{
    QJsonObject o = ui::words::toJson(p);
    // These commands' JSON has always carried the field, and a file's line and column
    // (0: the file as a whole), even when empty; scripts may read them unguarded.
    if (!o.contains(QStringLiteral("field")))
        o.insert(QStringLiteral("field"), QString());
    if (!p.file.empty() && !o.contains(QStringLiteral("line"))) {
        o.insert(QStringLiteral("line"), p.line);
        o.insert(QStringLiteral("column"), p.column);
    }
    return o;
}

void printJson(Invocation& inv, const QJsonObject& o)
{
    inv.printJson(o);  // the API's result is this object, not its text
}

bool reportProblems(Invocation& inv, const motion::msg::Problems& problems, const std::vector<std::pair<QString, QString>>& optionNames)
{
    const bool errors = motion::msg::hasErrors(problems);
    auto optionOf = [&](const std::string& path) {
        const QString p = QString::fromStdString(path);
        for (const auto& [field, option] : optionNames)
            if (p == field || p.startsWith(field + QLatin1Char('.')) || p.startsWith(field + QLatin1Char('[')))
                return option;
        return p;
    };
    if (inv.json()) {
        if (!errors)
            return false;  // warnings travel with the result
        QJsonArray list;
        for (const auto& p : problems) {
            QJsonObject o = problemJson(p);
            if (!optionNames.empty())
                o.insert(QStringLiteral("option"), optionOf(p.path));
            list.append(o);
        }
        printJson(inv, QJsonObject{{QStringLiteral("ok"), false}, {QStringLiteral("problems"), list}});
        return true;
    }
    for (motion::msg::Problem p : problems) {
        if (!optionNames.empty())
            p.path = optionOf(p.path).toStdString();
        const QString line = ui::words::problem(p);
        if (p.isWarning())
            inv.out() << line << "\n";
        else if (!p.file.empty())
            inv.err() << line << "\n";  // FILE:LINE:COLUMN leads, as compilers print it
        else
            inv.report(line);
    }
    inv.out().flush();
    inv.err().flush();
    return errors;
}

int reportFailure(Invocation& inv, const motion::msg::Message& m, int exitCode)
{
    if (inv.json())
        printJson(inv, QJsonObject{{QStringLiteral("ok"), false}, {QStringLiteral("error"), ui::words::toJson(m)}});
    else
        inv.report(ui::words::text(m));
    return exitCode;
}

QJsonObject resultJson(const dev::files::accuracy::AccuracyResult& r)
{
    return QJsonDocument::fromJson(QByteArray::fromStdString(dev::files::accuracy::accuracyResultToJson(r))).object();
}

void printFiguresText(Invocation& inv, const dev::files::accuracy::AccuracyResult& r)
{
    const auto& f = r.evaluation.figures;
    auto um = [](std::optional<double> v) { return v ? QString::number(*v * 1e3, 'f', 2) : QStringLiteral("—"); };
    QTextStream& o = inv.out();
    o << tr("Axis %1, %2, %3 cycles, %4 targets (ISO 230-2, µm)")
             .arg(QString::fromStdString(r.axis), r.evaluation.bidirectional ? tr("bidirectional") : tr("unidirectional"))
             .arg(r.evaluation.cycles)
             .arg(r.evaluation.targets.size())
      << "\n";
    o << QStringLiteral("  A %1   A↑ %2   A↓ %3\n").arg(um(f.aMm), um(f.aUpMm), um(f.aDownMm));
    o << QStringLiteral("  R %1   R↑ %2   R↓ %3\n").arg(um(f.rMm), um(f.rUpMm), um(f.rDownMm));
    o << QStringLiteral("  E %1   E↑ %2   E↓ %3\n").arg(um(f.eMm), um(f.eUpMm), um(f.eDownMm));
    o << QStringLiteral("  M %1   B %2   B̄ %3\n").arg(um(f.mMm), um(f.bMm), um(f.bMeanMm));
    if (!r.tolerances.empty()) {
        const auto verdicts = motion::metrology::judge(r.evaluation, r.tolerances);
        for (const auto& v : verdicts)
            o << QStringLiteral("  %1 %2 µm ≤ %3 µm: %4\n")
                     .arg(QString::fromStdString(v.figure))
                     .arg(v.valueMm * 1e3, 0, 'f', 2)
                     .arg(v.limitMm * 1e3, 0, 'f', 2)
                     .arg(v.pass ? tr("pass") : tr("FAIL"));
    }
    o.flush();
}

QString timeScaleRefusal(Invocation& inv)
{
    if (inv.host().insideGui())
        return tr("--time-scale speeds up benchpilot-cli's own simulator; the GUI's simulators keep their pace");
    return tr("--time-scale speeds up the in-process simulator: use it with --sim");
}

} // namespace app::cli
