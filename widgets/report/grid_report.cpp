// The grid map's report page: set-up, the decomposition's figures (before and after
// compensation when both are known) and the maps side by side, drawn as on the
// Calibration screen.
#include "widgets/report/accuracy_report.h"
#include "widgets/report/grid_map_painter.h"
#include "widgets/report/report_document.h"
#include "widgets/report/report_painter.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QLocale>

#include <algorithm>
#include <cmath>

namespace ui::report {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("ui::report", text); }
QString fixed(double v, int decimals) { return QLocale().toString(v, 'f', decimals); }

std::vector<QStringList> figureRows(const GridReportInput& in)
{
    const bool both = in.before.has_value();
    std::vector<QStringList> rows;
    rows.push_back(both ? QStringList{tr("figure"), tr("before"), tr("after")} : QStringList{tr("figure"), tr("value")});
    auto row = [&](const QString& name, double (*of)(const motion::metrology::GridMapFigures&), int decimals) {
        QStringList r{name};
        if (both)
            r << fixed(of(in.before->figures), decimals);
        r << fixed(of(in.result.figures), decimals);
        rows.push_back(r);
    };
    row(tr("scale X (ppm)"), [](const motion::metrology::GridMapFigures& f) { return f.scaleXPpm; }, 2);
    row(tr("scale Y (ppm)"), [](const motion::metrology::GridMapFigures& f) { return f.scaleYPpm; }, 2);
    row(tr("squareness (µrad)"), [](const motion::metrology::GridMapFigures& f) { return f.squarenessUrad; }, 1);
    row(tr("straightness X (µm)"), [](const motion::metrology::GridMapFigures& f) { return f.straightnessXUm; }, 2);
    row(tr("straightness Y (µm)"), [](const motion::metrology::GridMapFigures& f) { return f.straightnessYUm; }, 2);
    row(tr("error RMS (µm)"), [](const motion::metrology::GridMapFigures& f) { return f.rmsErrorUm; }, 2);
    row(tr("error max (µm)"), [](const motion::metrology::GridMapFigures& f) { return f.maxErrorUm; }, 2);
    row(tr("residual RMS (µm)"), [](const motion::metrology::GridMapFigures& f) { return f.rmsResidualUm; }, 2);
    // The reversal, when a map on the page was read both ways; "—" for one read one way.
    if (!in.result.figures.maxReversalUm && !(both && in.before->figures.maxReversalUm))
        return rows;
    auto reversal = [&](const QString& name, std::optional<double> motion::metrology::GridMapFigures::*of) {
        QStringList r{name};
        if (both)
            r << (in.before->figures.*of ? fixed(*(in.before->figures.*of), 2) : QStringLiteral("—"));
        r << (in.result.figures.*of ? fixed(*(in.result.figures.*of), 2) : QStringLiteral("—"));
        rows.push_back(r);
    };
    reversal(tr("reversal max (µm)"), &motion::metrology::GridMapFigures::maxReversalUm);
    reversal(tr("mean reversal X (µm)"), &motion::metrology::GridMapFigures::meanReversalXUm);
    reversal(tr("mean reversal Y (µm)"), &motion::metrology::GridMapFigures::meanReversalYUm);
    return rows;
}

bool renderGrid(const QString& path, const GridReportInput& in)
{
    Document doc(path);
    if (!doc.ok())
        return false;
    doc.setTitle(in.title);
    Page page(doc.painter());
    page.title(in.title);
    QStringList setup{tr("Instrument: %1").arg(in.instrument), tr("Reference: %1").arg(ui::words::text(in.source))};
    if (in.test && in.test->bidirectional)
        setup << tr("%1 × %2 nodes every %3 × %4 on a grid plate of %5 pitch, read both ways: each row approached from below, then "
                    "every node again in reverse order from above. The map and its figures are the mean of the two directions.")
                     .arg(in.test->columns)
                     .arg(in.test->rows)
                     .arg(ui::words::number(in.test->pitchXMm, motion::msg::Unit::Mm), ui::words::number(in.test->pitchYMm, motion::msg::Unit::Mm),
                          ui::words::number(in.test->platePitchMm, motion::msg::Unit::Mm));
    else if (in.test)
        setup << tr("%1 × %2 nodes every %3 × %4 on a grid plate of %5 pitch, each row approached from below")
                     .arg(in.test->columns)
                     .arg(in.test->rows)
                     .arg(ui::words::number(in.test->pitchXMm, motion::msg::Unit::Mm), ui::words::number(in.test->pitchYMm, motion::msg::Unit::Mm),
                          ui::words::number(in.test->platePitchMm, motion::msg::Unit::Mm));
    setup << tr("Plate placement fitted out: offset (%1, %2) µm, rotation %3 µrad")
                 .arg(fixed(in.result.placement.offsetXUm, 2), fixed(in.result.placement.offsetYUm, 2), fixed(in.result.placement.rotationUrad, 1));
    setup << tr("The camera's pixel size scales only each dot's small offset from the image centre: the scales are those of the plate's "
                "certified pitch, which a pixel size calibrated on this same stage cannot reveal.");
    page.paragraph(setup.join(QLatin1Char('\n')), 8.5);
    page.heading(tr("Figures (ISO 230-1 least-squares reference lines)"));
    page.table(figureRows(in), in.before ? std::vector<double>{3, 1.2, 1.2} : std::vector<double>{3, 1.2}, 8);
    page.gap(3);
    std::vector<const motion::metrology::GridMapResult*> maps{&in.result};
    if (in.before)
        maps.insert(maps.begin(), &*in.before);
    // A map read both ways gets a second row: its reversal at every node.
    const bool reversal = std::any_of(maps.begin(), maps.end(), [](const auto* m) { return m->figures.maxReversalUm.has_value(); });
    const double width = page.contentWidth() / static_cast<double>(maps.size());
    const double rowRoom = reversal ? (page.room() - 44) / 2 : page.room() - 22;
    const double size = std::min(width - 4, rowRoom);
    QPainter& p = doc.painter();
    auto drawRow = [&](GridVectors kind) {
        const double mag = gridMagnification(maps, kind);
        const double colourMax = std::max(gridLongestErrorUm(maps, kind), 1e-3);
        p.setFont(pageFont(p, 8, true));
        p.setPen(Qt::black);
        for (std::size_t k = 0; k < maps.size(); ++k) {
            const QRectF cell(page.left() + k * width, page.y(), width - 4, 6);
            const QString which = maps.size() == 1 ? QString() : (k == 0 ? tr("Before: compensation off") : tr("After: the 2D table enabled"));
            const QString what = kind == GridVectors::Reversal ? tr("Reversal map") : tr("Error map");
            p.drawText(cell, Qt::AlignLeft | Qt::AlignVCenter, which.isEmpty() ? what : tr("%1 · %2").arg(what, which));
            if (kind == GridVectors::Reversal && !maps[k]->figures.maxReversalUm)
                p.drawText(QRectF(page.left() + k * width, page.y() + 6, width - 4, size), Qt::AlignCenter, tr("read one way: no reversal"));
            else
                drawGridMap(p, QRectF(page.left() + k * width, page.y() + 6, width - 4, size), *maps[k], mag, colourMax, kind);
        }
        page.setY(page.y() + 8 + size);
        p.setFont(pageFont(p, 7, false));
        drawGridColourBar(p, QRectF(page.left(), page.y(), page.contentWidth() * 0.5, 3), colourMax);
        page.setY(page.y() + 5);
        page.paragraph(kind == GridVectors::Reversal
                           ? tr("Arrows: each node's reversal (forward − reverse), magnified %1×; colour: its length. Its mean along X and "
                                "along Y is the axes' lost motion, which a 2D table cannot correct.")
                                 .arg(fixed(mag * 1000, 0))
                           : tr("Arrows: each node's error with the plate's placement removed, magnified %1×; colour: the error's length, "
                                "one scale for every map on the page.")
                                 .arg(fixed(mag * 1000, 0)),
                       7.5);
    };
    drawRow(GridVectors::Error);
    if (reversal) {
        page.gap(2);
        drawRow(GridVectors::Reversal);
    }
    page.footer(tr("BenchPilot grid map · %1 · %2").arg(in.title, in.created), doc.pageNumber());
    return doc.finish();
}

} // namespace

bool writeGridReport(const QString& pdfPath, const GridReportInput& in, QString* error)
{
    return writeAtomically(pdfPath, [&](const QString& temp) { return renderGrid(temp, in); }, error);
}

} // namespace ui::report
