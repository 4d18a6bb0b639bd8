#include "widgets/report/accuracy_report.h"

#include "widgets/report/report_document.h"
#include "widgets/report/report_painter.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QGuiApplication>
#include <QLocale>

#include <cmath>
#include <map>

namespace ui::report {

using motion::metrology::Direction;
using motion::metrology::Evaluation;
using motion::metrology::Figures;

namespace {

QString tr(const char* text) { return QCoreApplication::translate("ui::report", text); }

QString um(std::optional<double> mm, int decimals = 2)
{
    return mm ? QLocale().toString(*mm * 1e3, 'f', decimals) : QStringLiteral("—");
}

struct AccuracyReportFigures {
    Figures figures;
    std::vector<motion::metrology::Verdict> verdicts;
};

struct FigureRow {
    const char* key;
    const char* label;
};
const FigureRow kFigureRows[] = {
    {"A", "A  positioning accuracy"}, {"A_up", "A↑"}, {"A_down", "A↓"},
    {"E", "E  systematic positioning error"}, {"E_up", "E↑"}, {"E_down", "E↓"},
    {"M", "M  mean positioning error"},
    {"R", "R  repeatability"}, {"R_up", "R↑"}, {"R_down", "R↓"},
    {"B", "B  reversal value"}, {"B_mean", "B̄  mean reversal value"},
};

QString setUpText(const AxisReportInput& in)
{
    QStringList lines;
    lines << tr("Instrument: %1").arg(in.instrument);
    lines << tr("Reference: %1").arg(ui::words::text(in.source));
    const Evaluation& e = in.result.evaluation;
    QStringList targets;
    for (const auto& t : e.targets)
        targets << QLocale().toString(t.targetMm, 'f', 3);
    lines << tr("Axis %1, %2 targets (mm): %3")
                 .arg(QString::fromStdString(in.result.axis))
                 .arg(e.targets.size())
                 .arg(targets.join(QStringLiteral(", ")));
    lines << tr("%1 cycles, %2").arg(e.cycles).arg(e.bidirectional ? tr("bidirectional (ISO 230-2 standard linear cycle)")
                                                                    : tr("unidirectional (approached from below)"));
    if (in.test) {
        const auto& t = *in.test;
        lines << tr("Feed %1, overrun %2, dwell %3; settled within %4 for %5 (timeout %6)")
                     .arg(ui::words::number(t.feedMmS, motion::msg::Unit::MmPerS), ui::words::number(t.overrunMm, motion::msg::Unit::Mm),
                          ui::words::number(t.dwellS, motion::msg::Unit::S), ui::words::number(t.settle.toleranceUm, motion::msg::Unit::Um),
                          ui::words::number(t.settle.windowS, motion::msg::Unit::S), ui::words::number(t.settle.timeoutS, motion::msg::Unit::S));
    }
    if (!in.result.readingsFile.empty())
        lines << tr("Readings: %1").arg(QString::fromStdString(in.result.readingsFile));
    return lines.join(QLatin1Char('\n'));
}

std::vector<QStringList> figuresTable(const AccuracyReportFigures& after, const std::optional<AccuracyReportFigures>& before,
                                      const motion::metrology::AxisTolerances& tol)
{
    (void)tol;
    std::vector<QStringList> rows;
    if (before)
        rows.push_back({tr("Figure"), tr("Before (µm)"), tr("After (µm)"), tr("Improvement")});
    else
        rows.push_back({tr("Figure"), tr("Value (µm)"), tr("Limit (µm)"), tr("Verdict")});
    for (const FigureRow& r : kFigureRows) {
        const auto value = dev::files::accuracy::figureByKey(after.figures, r.key);
        if (!value && !(before && dev::files::accuracy::figureByKey(before->figures, r.key)))
            continue;
        if (before) {
            const auto b = dev::files::accuracy::figureByKey(before->figures, r.key);
            QString gain = QStringLiteral("—");
            if (b && value && std::fabs(*value) > 1e-9 && std::string(r.key) != "B_mean")
                gain = QStringLiteral("%1×").arg(QLocale().toString(std::fabs(*b) / std::fabs(*value), 'f', 1));
            rows.push_back({tr(r.label), um(b), um(value), gain});
            continue;
        }
        QString limit = QStringLiteral("—"), verdict;
        for (const auto& v : after.verdicts)
            if (v.figure == r.key) {
                limit = um(v.limitMm);
                verdict = v.pass ? tr("pass") : tr("FAIL");
            }
        rows.push_back({tr(r.label), um(value), limit, verdict});
    }
    return rows;
}

PlotSpec isoPlot(const Evaluation& e, const std::vector<motion::metrology::Reading>& readings, const QString& suffix = {})
{
    PlotSpec spec;
    spec.xLabel = tr("target (mm)");
    spec.yLabel = tr("deviation (µm)");
    spec.yZero = 0;
    Series upMean{tr("mean ↑") + suffix, {}, QColor(20, 90, 200)};
    Series downMean{tr("mean ↓") + suffix, {}, QColor(200, 60, 30)};
    Series upHi{tr("mean ± 2s"), {}, QColor(20, 90, 200), Qt::DashLine};
    Series upLo{{}, {}, QColor(20, 90, 200), Qt::DashLine};
    Series downHi{{}, {}, QColor(200, 60, 30), Qt::DashLine};
    Series downLo{{}, {}, QColor(200, 60, 30), Qt::DashLine};
    for (const auto& t : e.targets) {
        upMean.points.push_back({t.targetMm, t.meanUpMm * 1e3});
        upHi.points.push_back({t.targetMm, (t.meanUpMm + 2 * t.sUpMm) * 1e3});
        upLo.points.push_back({t.targetMm, (t.meanUpMm - 2 * t.sUpMm) * 1e3});
        if (t.meanDownMm && t.sDownMm) {
            downMean.points.push_back({t.targetMm, *t.meanDownMm * 1e3});
            downHi.points.push_back({t.targetMm, (*t.meanDownMm + 2 * *t.sDownMm) * 1e3});
            downLo.points.push_back({t.targetMm, (*t.meanDownMm - 2 * *t.sDownMm) * 1e3});
        }
    }
    Series upDots{tr("readings ↑"), {}, QColor(20, 90, 200, 150)};
    upDots.markers = true;
    upDots.line = false;
    Series downDots{tr("readings ↓"), {}, QColor(200, 60, 30, 150)};
    downDots.markers = true;
    downDots.line = false;
    for (const auto& r : readings)
        (r.direction == Direction::Up ? upDots : downDots).points.push_back({r.targetMm, r.deviationMm() * 1e3});
    spec.series = {upMean, upHi, upLo};
    if (!downMean.points.empty()) {
        spec.series.push_back(downMean);
        spec.series.push_back(downHi);
        spec.series.push_back(downLo);
    }
    if (!upDots.points.empty())
        spec.series.push_back(upDots);
    if (!downDots.points.empty())
        spec.series.push_back(downDots);
    return spec;
}

} // namespace

bool canRender() { return qobject_cast<QGuiApplication*>(QCoreApplication::instance()) != nullptr; }

namespace {
bool renderAxis(const QString& path, const AxisReportInput& in)
{
    Document doc(path);
    if (!doc.ok())
        return false;
    doc.setTitle(in.title);
    Page page(doc.painter());
    const QString footer = tr("BenchPilot accuracy report · %1 · %2").arg(in.title, in.created);
    page.title(in.title);
    page.paragraph(setUpText(in), 8.5);

    AccuracyReportFigures after{in.result.evaluation.figures, motion::metrology::judge(in.result.evaluation, in.result.tolerances)};
    std::optional<AccuracyReportFigures> before;
    if (in.before)
        before = AccuracyReportFigures{in.before->evaluation.figures, {}};
    page.heading(before ? tr("Figures before and after compensation (ISO 230-2:2014)") : tr("Figures (ISO 230-2:2014)"));
    page.table(figuresTable(after, before, in.result.tolerances), {3.2, 1.3, 1.3, 1.2}, 8, [&](int, int c) {
        return c == 3 && !before ? QColor(20, 20, 20) : QColor(Qt::black);
    });
    if (!in.result.tolerances.empty() && !before) {
        const bool pass = motion::metrology::allPass(after.verdicts);
        page.paragraph(pass ? tr("PASS: every figure judged is within its limit.") : tr("FAIL: a figure is beyond its limit."), 10, true,
                       pass ? QColor(20, 120, 40) : QColor(180, 20, 20));
    } else if (!before) {
        page.paragraph(tr("No tolerances were given: the figures are not judged."), 8.5);
    }
    page.heading(tr("Deviations: mean ± 2s per direction"));
    const double plotH = std::min(95.0, page.room() - 4);
    drawPlot(doc.painter(), QRectF(page.left(), page.y(), page.contentWidth(), plotH), isoPlot(in.result.evaluation, in.readings));
    page.gap(plotH + 2);
    page.footer(footer, doc.pageNumber());

    // Page 2: the table of targets, before/after and the fit.
    doc.newPage();
    page.setY(Page::kMarginMm);
    page.heading(tr("Per target (µm)"));
    std::vector<QStringList> rows{{tr("target (mm)"), QStringLiteral("x̄↑"), QStringLiteral("s↑"), QStringLiteral("x̄↓"), QStringLiteral("s↓"),
                                   QStringLiteral("x̄"), QStringLiteral("B"), QStringLiteral("R")}};
    for (const auto& t : in.result.evaluation.targets)
        rows.push_back({QLocale().toString(t.targetMm, 'f', 3), um(t.meanUpMm), um(t.sUpMm), um(t.meanDownMm), um(t.sDownMm), um(t.meanMm),
                        um(t.reversalMm), um(t.rMm ? t.rMm : std::optional<double>(t.rUpMm))});
    page.table(rows, {1.6, 1, 1, 1, 1, 1, 1, 1}, 7.5);
    if (in.before) {
        page.heading(tr("Before and after"));
        PlotSpec spec;
        spec.xLabel = tr("target (mm)");
        spec.yLabel = tr("mean deviation (µm)");
        spec.yZero = 0;
        Series b{tr("before"), {}, QColor(150, 150, 150)};
        Series a{tr("after"), {}, QColor(20, 120, 40)};
        for (const auto& t : in.before->evaluation.targets)
            b.points.push_back({t.targetMm, t.meanMm * 1e3});
        for (const auto& t : in.result.evaluation.targets)
            a.points.push_back({t.targetMm, t.meanMm * 1e3});
        spec.series = {b, a};
        const double h = std::min(70.0, page.room() - 4);
        drawPlot(doc.painter(), QRectF(page.left(), page.y(), page.contentWidth(), h), spec);
        page.gap(h + 2);
    }
    if (in.fit && page.room() > 60) {
        page.heading(tr("Compensation fit of the mean deviations (seed 002's method)"));
        std::vector<QStringList> fit{{tr("order"), tr("SSE (µm²)"), QStringLiteral("R²"), tr("adjusted R²"), tr("chosen")}};
        for (const auto& f : in.fit->orders) {
            if (!f.available) {
                fit.push_back({QString::number(f.order), tr("not enough points"), {}, {}, {}});
                continue;
            }
            fit.push_back({QString::number(f.order), QLocale().toString(f.sseUm2, 'g', 5), QLocale().toString(f.r2, 'f', 5),
                           QLocale().toString(f.adjustedR2, 'f', 5), f.order == in.fit->chosenOrder ? QStringLiteral("●") : QString()});
        }
        page.table(fit, {1, 1.6, 1.2, 1.4, 0.8}, 7.5);
        if (const auto* c = in.fit->chosen()) {
            static const char* const kPowers[] = {"", "·x", "·x²", "·x³", "·x⁴", "·x⁵"};
            QString curve;
            for (std::size_t k = 0; k < c->polynomial.coefficientsUm.size() && k < 6; ++k) {
                const double v = c->polynomial.coefficientsUm[k];
                const QString digits = QLocale().toString(std::fabs(v), 'g', 6) + QString::fromUtf8(kPowers[k]);
                curve += k == 0 ? (v < 0 ? QStringLiteral("−") : QString()) + digits : (v < 0 ? QStringLiteral(" − ") : QStringLiteral(" + ")) + digits;
            }
            page.paragraph(tr("e(x) = %1 µm, x in mm (order %2%3)")
                               .arg(curve)
                               .arg(c->order)
                               .arg(in.fit->chosenByOperator ? tr(", chosen by the operator") : tr(", chosen by adjusted R²")),
                           8);
            PlotSpec spec;
            spec.xLabel = tr("target (mm)");
            spec.yLabel = tr("residual (µm)");
            spec.yZero = 0;
            Series res{tr("mean deviation − fit"), {}, QColor(90, 40, 160)};
            res.markers = true;
            for (const auto& t : in.result.evaluation.targets)
                res.points.push_back({t.targetMm, t.meanMm * 1e3 - c->polynomial.errorUm(t.targetMm)});
            spec.series = {res};
            const double h = std::min(55.0, page.room() - 4);
            drawPlot(doc.painter(), QRectF(page.left(), page.y(), page.contentWidth(), h), spec);
            page.gap(h + 2);
        }
    }
    page.footer(footer, doc.pageNumber());
    return doc.finish();
}
} // namespace

bool writeAxisReport(const QString& pdfPath, const AxisReportInput& in, QString* error)
{
    return writeAtomically(pdfPath, [&](const QString& temp) { return renderAxis(temp, in); }, error);
}

} // namespace ui::report
