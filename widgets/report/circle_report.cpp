// The circular test's report page: set-up, ISO 230-4 figures and the polar plot with
// the deviation from the least-squares circle magnified.
#include "widgets/report/accuracy_report.h"
#include "widgets/report/report_document.h"
#include "widgets/report/report_painter.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QLocale>

#include <cmath>

namespace ui::report {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("ui::report", text); }
QString um(double mm) { return QLocale().toString(mm * 1e3, 'f', 2); }

void drawPolar(QPainter& p, const QRectF& rect, const CircleReportInput& in, double magnification)
{
    const double R = in.test.radiusMm;
    const QPointF c = rect.center();
    const double scale = 0.42 * std::min(rect.width(), rect.height()) / (R * 1.25);  // mm of page per mm of plot radius
    p.setFont(pageFont(p, 6.5, false));
    // The nominal circle and rings at ± one 1-2-5 step of magnified deviation.
    p.setPen(QPen(QColor(150, 150, 150), 0.25, Qt::DashLine));
    p.drawEllipse(c, R * scale, R * scale);
    p.setPen(QPen(QColor(220, 220, 220), 0.15));
    for (int k = 0; k < 12; ++k) {
        const double a = k * 3.141592653589793 / 6;
        p.drawLine(c, c + QPointF(std::cos(a), -std::sin(a)) * R * 1.2 * scale);
    }
    const QColor colors[2] = {QColor(20, 90, 200), QColor(200, 60, 30)};
    int n = 0;
    for (const auto& run : in.evaluation.runs) {
        const auto pts = motion::metrology::polarPlot(run, R, magnification);
        p.setPen(QPen(colors[n % 2], 0.35));
        for (std::size_t k = 1; k <= pts.size() && pts.size() > 1; ++k) {
            const auto& a = pts[k - 1];
            const auto& b = pts[k % pts.size()];
            p.drawLine(c + QPointF(std::cos(a.angleRad), -std::sin(a.angleRad)) * a.plotRadiusMm * scale,
                       c + QPointF(std::cos(b.angleRad), -std::sin(b.angleRad)) * b.plotRadiusMm * scale);
        }
        p.drawText(QRectF(rect.left(), rect.top() + 4 * n, 80, 4), Qt::AlignLeft | Qt::AlignVCenter,
                   run.rotation == motion::metrology::Rotation::Cw ? tr("— clockwise") : tr("— counter-clockwise"));
        ++n;
    }
    p.setPen(Qt::black);
    p.drawText(QRectF(rect.left(), rect.bottom() - 4, rect.width(), 4), Qt::AlignLeft | Qt::AlignVCenter,
               tr("radius %1, deviation from the least-squares circle magnified %2×; dashed: the nominal circle")
                   .arg(ui::words::number(R, motion::msg::Unit::Mm))
                   .arg(magnification, 0, 'g', 6));
}

bool renderCircle(const QString& path, const CircleReportInput& in)
{
    Document doc(path);
    if (!doc.ok())
        return false;
    doc.setTitle(in.title);
    Page page(doc.painter());
    page.title(in.title);
    const auto& t = in.test;
    page.paragraph(tr("Instrument: %1\nPlane %2, centre (%3, %4), radius %5, feed %6, lead arc %7; %8 samples a revolution")
                       .arg(in.instrument, QString::fromStdString(t.axes), ui::words::number(t.centreMm.xMm, motion::msg::Unit::Mm),
                            ui::words::number(t.centreMm.yMm, motion::msg::Unit::Mm), ui::words::number(t.radiusMm, motion::msg::Unit::Mm),
                            ui::words::number(t.feedMmS, motion::msg::Unit::MmPerS), ui::words::number(t.leadArcDeg, motion::msg::Unit::Deg))
                       .arg(t.samplesPerRevolution),
                   8.5);
    page.heading(tr("Figures (ISO 230-4, µm)"));
    std::vector<QStringList> rows{{tr("figure"), tr("value (µm)"), tr("limit (µm)"), tr("verdict")}};
    auto verdict = [](double v, const std::optional<double>& limit) {
        return limit ? (v <= *limit + 1e-12 ? tr("pass") : tr("FAIL")) : QString();
    };
    for (const auto& run : in.evaluation.runs) {
        const QString dir = run.rotation == motion::metrology::Rotation::Cw ? tr("clockwise") : tr("counter-clockwise");
        rows.push_back({tr("G circular deviation, %1").arg(dir), um(run.circularDeviationMm), t.maxGMm ? um(*t.maxGMm) : QStringLiteral("—"),
                        verdict(run.circularDeviationMm, t.maxGMm)});
        rows.push_back({tr("radial deviation, %1: min … max").arg(dir),
                        QStringLiteral("%1 … %2").arg(um(run.radialDeviationMinMm), um(run.radialDeviationMaxMm)), QStringLiteral("—"), {}});
    }
    if (in.evaluation.bidirectionalDeviationMm)
        rows.push_back({tr("G(b) bidirectional circular deviation"), um(*in.evaluation.bidirectionalDeviationMm), QStringLiteral("—"), {}});
    if (in.evaluation.hysteresisMm)
        rows.push_back({tr("H circular hysteresis"), um(*in.evaluation.hysteresisMm), t.maxHMm ? um(*t.maxHMm) : QStringLiteral("—"),
                        verdict(*in.evaluation.hysteresisMm, t.maxHMm)});
    page.table(rows, {3.4, 1.6, 1, 1}, 8);
    const double size = std::min(page.contentWidth(), page.room() - 8);
    drawPolar(doc.painter(), QRectF(page.left(), page.y(), page.contentWidth(), size),
              in, motion::metrology::autoMagnification(in.evaluation, t.radiusMm));
    page.footer(tr("BenchPilot circular test · %1 · %2").arg(in.title, in.created), doc.pageNumber());
    return doc.finish();
}

} // namespace

bool writeCircleReport(const QString& pdfPath, const CircleReportInput& in, QString* error)
{
    return writeAtomically(pdfPath, [&](const QString& temp) { return renderCircle(temp, in); }, error);
}

} // namespace ui::report
