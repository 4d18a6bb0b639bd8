#include "widgets/report/stitch_quality_drawing.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
constexpr double kMarginPx = 16;
/// The largest correction is drawn this fraction of a tile's width long.
constexpr double kLongestArrowOfTile = 0.5;

QColor pairColour(imaging::PairStatus status, double ncc)
{
    switch (status) {
    case imaging::PairStatus::Accepted: {
        // From a dull to a bright green as the score goes from 0.3 to 1.
        const double t = std::clamp((ncc - 0.3) / 0.7, 0.0, 1.0);
        return QColor::fromRgbF(static_cast<float>(0.55 - 0.45 * t), static_cast<float>(0.65 + 0.1 * t), static_cast<float>(0.45 - 0.35 * t));
    }
    case imaging::PairStatus::Outlier: return QColor(210, 40, 40);
    default: return QColor(150, 150, 150);
    }
}
} // namespace

const char* pairVerdictTerm(imaging::PairStatus status)
{
    switch (status) {
    case imaging::PairStatus::Accepted: return "scan.pair.accepted";
    case imaging::PairStatus::LowScore: return "scan.pair.low_score";
    case imaging::PairStatus::Ambiguous: return "scan.pair.ambiguous";
    case imaging::PairStatus::AtBound: return "scan.pair.at_bound";
    case imaging::PairStatus::NoOverlap: return "scan.pair.no_overlap";
    case imaging::PairStatus::Outlier: return "scan.pair.outlier";
    }
    return "scan.pair.no_overlap";
}

std::vector<Eigen::Vector2d> qualityArrowsPx(const imaging::StitchResult& r)
{
    const std::size_t n = std::min(r.tiles.size(), r.placement.positionsPx.size());
    const imaging::StageModel& model = r.placement.stageModel;
    std::vector<Eigen::Vector2d> arrows(n);
    Eigen::Vector2d mean(0, 0);
    for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector2d reference = model.used ? model.apply(r.tiles[i].stagePx) : r.tiles[i].stagePx;
        arrows[i] = r.placement.positionsPx[i] - reference;
        mean += arrows[i];
    }
    if (n > 0)
        mean /= static_cast<double>(n);
    for (Eigen::Vector2d& a : arrows)
        a -= mean;
    return arrows;
}

// The summary's words keep the Mosaic tab's context (ui::StitchPanel), where they are translated.
QStringList stitchSummaryLines(const imaging::StitchResult& r, const StitchSummaryFigures& figures)
{
    int accepted = 0, byStage = 0;
    for (const imaging::TilePair& pair : r.pairs)
        accepted += pair.reg.accepted();
    for (bool s : r.placement.placedByStage)
        byStage += s;
    const int pairs = static_cast<int>(r.pairs.size());
    const int notTrusted = pairs - accepted - r.placement.rejectedPairs;
    const double um = figures.pixelUm;
    QStringList lines;
    lines << QCoreApplication::translate("ui::StitchPanel", "%1 tiles, %2 pairs: %3 trusted, %4 rejected as outliers, %5 not trusted; %6 tiles placed by the stage (hatched)")
                 .arg(r.tiles.size())
                 .arg(pairs)
                 .arg(accepted)
                 .arg(r.placement.rejectedPairs)
                 .arg(notTrusted)
                 .arg(byStage);
    const imaging::StageModel& model = r.placement.stageModel;
    if (!model.used) {
        lines << QCoreApplication::translate("ui::StitchPanel", "Correction from the stage: RMS %1 px (%2 µm), worst %3 px (%4 µm); arrows drawn ×%5")
                     .arg(r.placement.rmsCorrectionPx, 0, 'f', 2)
                     .arg(r.placement.rmsCorrectionPx * um, 0, 'f', 2)
                     .arg(r.placement.worstCorrectionPx, 0, 'f', 2)
                     .arg(r.placement.worstCorrectionPx * um, 0, 'f', 2)
                     .arg(figures.magnification, 0, 'f', 0);
    } else {
        lines << QCoreApplication::translate("ui::StitchPanel", "Correction from the stage: RMS %1 px (%2 µm), worst %3 px (%4 µm)")
                     .arg(r.placement.rmsCorrectionPx, 0, 'f', 2)
                     .arg(r.placement.rmsCorrectionPx * um, 0, 'f', 2)
                     .arg(r.placement.worstCorrectionPx, 0, 'f', 2)
                     .arg(r.placement.worstCorrectionPx * um, 0, 'f', 2);
        lines << QCoreApplication::translate("ui::StitchPanel", "Stage against camera, fitted from %1 pairs: scale x %2 ppm, y %3 ppm, shear %4 µrad; "
                    "beyond it RMS %5 px (%6 µm), worst %7 px, as the arrows show ×%8")
                     .arg(model.pairs)
                     .arg(model.scaleXPpm(), 0, 'f', 0)
                     .arg(model.scaleYPpm(), 0, 'f', 0)
                     .arg(model.shearUrad(), 0, 'f', 0)
                     .arg(r.placement.rmsBeyondModelPx, 0, 'f', 2)
                     .arg(r.placement.rmsBeyondModelPx * um, 0, 'f', 2)
                     .arg(r.placement.worstBeyondModelPx, 0, 'f', 2)
                     .arg(figures.magnification, 0, 'f', 0);
    }
    lines << QCoreApplication::translate("ui::StitchPanel", "Mosaic %1 × %2 px in %3 s").arg(r.frame.width).arg(r.frame.height).arg(figures.seconds, 0, 'f', 1);
    if (figures.live)
        lines << QCoreApplication::translate("ui::StitchPanel", "Stitched live during the scan: placed %1 s after the last tile, the files written %2 s after it")
                     .arg(figures.livePlacedAfterS, 0, 'f', 1)
                     .arg(figures.seconds, 0, 'f', 1);
    if (r.cameraCheck && r.planCamera)
        for (const motion::msg::Message& m : imaging::geometryAdvice(*r.cameraCheck, *r.planCamera))
            lines << QCoreApplication::translate("ui::StitchPanel", "Check the plan's camera: %1").arg(ui::words::text(m));
    return lines;
}

void StitchQualityDrawing::setResult(const imaging::StitchResult& r)
{
    // The live scan's thumbnails stay with the tiles they belong to.
    std::vector<Tile> before;
    if (m_tiles.size() == r.tiles.size())
        before.swap(m_tiles);
    m_tiles.clear();
    m_pairs.clear();
    m_selected = -1;
    m_tileSize = QSizeF(r.tileWidth, r.tileHeight);
    double longest = 0;
    for (std::size_t i = 0; i < r.tiles.size() && i < r.placement.positionsPx.size(); ++i) {
        Tile t;
        t.stagePx = QPointF(r.tiles[i].stagePx.x(), r.tiles[i].stagePx.y());
        t.placedPx = QPointF(r.placement.positionsPx[i].x(), r.placement.positionsPx[i].y());
        t.byStage = i < r.placement.placedByStage.size() && r.placement.placedByStage[i];
        if (i < before.size()) {
            t.raw = before[i].raw;
            t.picture = before[i].picture;
        }
        m_tiles.push_back(t);
    }
    const std::vector<Eigen::Vector2d> arrows = qualityArrowsPx(r);
    QPointF mean;
    for (std::size_t i = 0; i < m_tiles.size(); ++i) {
        m_tiles[i].correctionPx = QPointF(arrows[i].x(), arrows[i].y());
        mean += m_tiles[i].placedPx - m_tiles[i].stagePx;
    }
    if (!m_tiles.empty())
        mean /= static_cast<double>(m_tiles.size());
    for (Tile& t : m_tiles) {
        t.placedPx -= mean;
        longest = std::max(longest, std::hypot(t.correctionPx.x(), t.correctionPx.y()));
    }
    for (const imaging::TilePair& p : r.pairs)
        m_pairs.push_back({p.a, p.b, p.reg.ncc, p.reg.status});
    const double wanted = kLongestArrowOfTile * std::max(1.0, m_tileSize.width());
    m_magnification = longest > 1e-9 ? std::max(1.0, std::floor(wanted / longest)) : 1.0;
}

void StitchQualityDrawing::clear()
{
    m_tiles.clear();
    m_pairs.clear();
    m_selected = -1;
    m_windowLow = m_windowHigh = -1;
}

void StitchQualityDrawing::beginLive(const std::vector<QPointF>& plannedPx, const QSizeF& tileSize)
{
    clear();
    m_tileSize = tileSize;
    m_magnification = 1;
    for (const QPointF& p : plannedPx) {
        Tile t;
        t.stagePx = t.placedPx = p;
        t.taken = false;
        m_tiles.push_back(t);
    }
}

bool StitchQualityDrawing::setLiveTile(int index, QPointF stagePx, QSizeF size, std::shared_ptr<const imaging::ImageU16> thumbnail)
{
    if (index < 0 || index >= tileCount())
        return false;
    Tile& t = m_tiles[static_cast<std::size_t>(index)];
    t.stagePx = t.placedPx = stagePx;
    t.taken = true;
    if (size.isValid())
        m_tileSize = size;
    t.raw = std::move(thumbnail);
    if (t.raw && !t.raw->empty()) {
        widenWindow(*t.raw);
        t.picture = picture(*t.raw);
    }
    return true;
}

void StitchQualityDrawing::setLivePair(const imaging::TilePair& pair)
{
    m_pairs.push_back({pair.a, pair.b, pair.reg.ncc, pair.reg.status});
}

int StitchQualityDrawing::picturedTiles() const
{
    int n = 0;
    for (const Tile& t : m_tiles)
        n += !t.picture.isNull();
    return n;
}

void StitchQualityDrawing::widenWindow(const imaging::ImageU16& raw)
{
    std::vector<std::uint16_t> v = raw.px;
    const auto at = [&](double share) {
        const auto k = static_cast<std::ptrdiff_t>(share * static_cast<double>(v.size() - 1));
        std::nth_element(v.begin(), v.begin() + k, v.end());
        return static_cast<int>(v[static_cast<std::size_t>(k)]);
    };
    const int low = at(0.01), high = at(0.99);
    if (m_windowLow >= 0 && low >= m_windowLow && high <= m_windowHigh)
        return;
    m_windowLow = m_windowLow < 0 ? low : std::min(m_windowLow, low);
    m_windowHigh = std::max({m_windowHigh, high, m_windowLow + 1});
    for (Tile& t : m_tiles)
        if (t.raw && !t.raw->empty())
            t.picture = picture(*t.raw);
}

QImage StitchQualityDrawing::picture(const imaging::ImageU16& raw) const
{
    QImage out(raw.width, raw.height, QImage::Format_Grayscale8);
    const double scale = 255.0 / std::max(1, m_windowHigh - m_windowLow);
    for (int y = 0; y < raw.height; ++y) {
        uchar* line = out.scanLine(y);
        const std::uint16_t* in = raw.row(y);
        for (int x = 0; x < raw.width; ++x)
            line[x] = static_cast<uchar>(std::clamp((in[x] - m_windowLow) * scale, 0.0, 255.0));
    }
    return out;
}

void StitchQualityDrawing::selectTile(int index)
{
    m_selected = index >= 0 && index < tileCount() ? index : -1;
}

QTransform StitchQualityDrawing::fit(const QSizeF& size) const
{
    if (m_tiles.empty())
        return {};
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (const Tile& t : m_tiles) {
        x0 = std::min(x0, t.stagePx.x());
        y0 = std::min(y0, t.stagePx.y());
        x1 = std::max(x1, t.stagePx.x() + m_tileSize.width());
        y1 = std::max(y1, t.stagePx.y() + m_tileSize.height());
    }
    const double w = std::max(1.0, x1 - x0), h = std::max(1.0, y1 - y0);
    const double s = std::min((size.width() - 2 * kMarginPx) / w, (size.height() - 2 * kMarginPx) / h);
    const double ox = (size.width() - s * w) / 2 - s * x0, oy = (size.height() - s * h) / 2 - s * y0;
    return QTransform(s, 0, 0, s, ox, oy);
}

int StitchQualityDrawing::tileAt(const QPointF& point, const QSizeF& size) const
{
    const QTransform t = fit(size);
    bool invertible = false;
    const QPointF px = t.inverted(&invertible).map(point);
    if (!invertible)
        return -1;
    for (int i = tileCount() - 1; i >= 0; --i)
        if (QRectF(m_tiles[static_cast<std::size_t>(i)].stagePx, m_tileSize).contains(px))
            return i;
    return -1;
}

void StitchQualityDrawing::draw(QPainter& p, const QSizeF& size) const
{
    p.setRenderHint(QPainter::Antialiasing);
    if (m_tiles.empty())
        return;
    const QTransform t = fit(size);
    auto centre = [&](const Tile& tile) { return tile.stagePx + QPointF(m_tileSize.width() / 2, m_tileSize.height() / 2); };
    // Tiles where the stage put them, those placed by the stage hatched.
    // Thumbnails first, each where the tile was placed, under every outline.
    for (const Tile& tile : m_tiles)
        if (!tile.picture.isNull())
            p.drawImage(t.mapRect(QRectF(tile.placedPx, m_tileSize)), tile.picture);
    for (std::size_t i = 0; i < m_tiles.size(); ++i) {
        const Tile& tile = m_tiles[i];
        const QRectF r = t.mapRect(QRectF(tile.stagePx, m_tileSize)).adjusted(1, 1, -1, -1);
        if (!tile.taken) {  // still to come in a live scan
            p.setPen(QPen(QColor(170, 170, 170), 1, Qt::DotLine));
            p.setBrush(Qt::NoBrush);
            p.drawRect(r);
            continue;
        }
        p.setPen(QPen(QColor(120, 120, 120), 1));
        if (tile.byStage)
            p.setBrush(QBrush(QColor(240, 150, 40), Qt::BDiagPattern));
        else
            p.setBrush(tile.picture.isNull() ? QBrush(QColor(235, 240, 248)) : QBrush(Qt::NoBrush));
        p.drawRect(r);
        if (tile.byStage) {
            p.setPen(QPen(QColor(220, 120, 20), 2));
            p.setBrush(Qt::NoBrush);
            p.drawRect(r);
        }
    }
    // Pairs between neighbours' centres.
    for (const Pair& pair : m_pairs) {
        if (pair.a < 0 || pair.b < 0 || pair.a >= tileCount() || pair.b >= tileCount())
            continue;
        QPen pen(pairColour(pair.status, pair.ncc), pair.status == imaging::PairStatus::Accepted ? 3 : 2);
        if (pair.status != imaging::PairStatus::Accepted && pair.status != imaging::PairStatus::Outlier)
            pen.setStyle(Qt::DashLine);
        p.setPen(pen);
        p.drawLine(t.map(centre(m_tiles[static_cast<std::size_t>(pair.a)])), t.map(centre(m_tiles[static_cast<std::size_t>(pair.b)])));
    }
    // Each tile's correction, magnified, from its centre.
    p.setPen(QPen(QColor(30, 60, 160), 2));
    p.setBrush(QColor(30, 60, 160));
    for (const Tile& tile : m_tiles) {
        if (!tile.taken)
            continue;
        const QPointF from = t.map(centre(tile));
        const QPointF to = t.map(centre(tile) + tile.correctionPx * m_magnification);
        const QPointF d = to - from;
        const double len = std::hypot(d.x(), d.y());
        p.drawEllipse(from, 2.5, 2.5);
        if (len < 1.5)
            continue;
        p.drawLine(from, to);
        const QPointF u = d / len, n(-u.y(), u.x());
        const double head = std::min(8.0, len / 2);
        QPainterPath arrow;
        arrow.moveTo(to);
        arrow.lineTo(to - u * head + n * head / 2);
        arrow.lineTo(to - u * head - n * head / 2);
        arrow.closeSubpath();
        p.drawPath(arrow);
    }
    // The selected tile last, over its neighbours' outlines and the pairs.
    if (m_selected >= 0 && m_selected < tileCount()) {
        p.setPen(QPen(QColor(0, 120, 215), 3));
        p.setBrush(Qt::NoBrush);
        p.drawRect(t.mapRect(QRectF(m_tiles[static_cast<std::size_t>(m_selected)].stagePx, m_tileSize)));
    }
}

QImage StitchQualityDrawing::render(const QSize& size, const QStringList& legend) const
{
    QImage image(size, QImage::Format_RGB32);
    image.fill(Qt::white);
    QPainter p(&image);
    QFont font = p.font();
    font.setPixelSize(14);
    p.setFont(font);
    const int lineH = QFontMetrics(font).height();
    const int top = static_cast<int>(kMarginPx) + lineH * static_cast<int>(legend.size());
    p.setPen(Qt::black);
    for (int i = 0; i < legend.size(); ++i)
        p.drawText(QPointF(kMarginPx, kMarginPx + lineH * (i + 0.8)), legend[i]);
    p.translate(0, top);
    draw(p, QSizeF(size.width(), std::max(1, size.height() - top)));
    return image;
}

} // namespace ui
