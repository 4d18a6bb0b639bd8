#include "widgets/scan/stitch_quality_map.h"

#include <QMouseEvent>
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

StitchQualityMap::StitchQualityMap(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("stitchQualityMap"));
    setMouseTracking(false);
}

void StitchQualityMap::setResult(const imaging::StitchResult& r)
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
    // Placement may shift the whole mosaic: corrections are drawn against the mean shift.
    // With a stage model, the arrows show what registration found beyond it: a grating
    // scale would otherwise draw every arrow pointing out of the mosaic.
    const imaging::StageModel& model = r.placement.stageModel;
    QPointF mean, meanCorrection;
    for (std::size_t i = 0; i < m_tiles.size(); ++i) {
        Tile& t = m_tiles[i];
        const Eigen::Vector2d reference = model.used ? model.apply(r.tiles[i].stagePx) : r.tiles[i].stagePx;
        t.correctionPx = t.placedPx - QPointF(reference.x(), reference.y());
        mean += t.placedPx - t.stagePx;
        meanCorrection += t.correctionPx;
    }
    if (!m_tiles.empty()) {
        mean /= static_cast<double>(m_tiles.size());
        meanCorrection /= static_cast<double>(m_tiles.size());
    }
    for (Tile& t : m_tiles) {
        t.placedPx -= mean;
        t.correctionPx -= meanCorrection;
        longest = std::max(longest, std::hypot(t.correctionPx.x(), t.correctionPx.y()));
    }
    for (const imaging::TilePair& p : r.pairs)
        m_pairs.push_back({p.a, p.b, p.reg.ncc, p.reg.status});
    const double wanted = kLongestArrowOfTile * std::max(1.0, m_tileSize.width());
    m_magnification = longest > 1e-9 ? std::max(1.0, std::floor(wanted / longest)) : 1.0;
    update();
}

void StitchQualityMap::clear()
{
    m_tiles.clear();
    m_pairs.clear();
    m_selected = -1;
    m_windowLow = m_windowHigh = -1;
    update();
}

void StitchQualityMap::beginLive(const std::vector<QPointF>& plannedPx, const QSizeF& tileSize)
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
    update();
}

void StitchQualityMap::setLiveTile(int index, QPointF stagePx, QSize size, std::shared_ptr<const imaging::ImageU16> thumbnail)
{
    if (index < 0 || index >= tileCount())
        return;
    Tile& t = m_tiles[static_cast<std::size_t>(index)];
    t.stagePx = t.placedPx = stagePx;
    t.taken = true;
    if (size.isValid())
        m_tileSize = QSizeF(size);
    t.raw = std::move(thumbnail);
    if (t.raw && !t.raw->empty()) {
        widenWindow(*t.raw);
        t.picture = picture(*t.raw);
    }
    update();
}

void StitchQualityMap::setLivePair(const imaging::TilePair& pair)
{
    m_pairs.push_back({pair.a, pair.b, pair.reg.ncc, pair.reg.status});
    update();
}

int StitchQualityMap::picturedTiles() const
{
    int n = 0;
    for (const Tile& t : m_tiles)
        n += !t.picture.isNull();
    return n;
}

void StitchQualityMap::widenWindow(const imaging::ImageU16& raw)
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

QImage StitchQualityMap::picture(const imaging::ImageU16& raw) const
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

void StitchQualityMap::selectTile(int index)
{
    m_selected = index >= 0 && index < tileCount() ? index : -1;
    update();
}

QTransform StitchQualityMap::fit(const QSizeF& size) const
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

int StitchQualityMap::tileAt(const QPointF& point) const
{
    const QTransform t = fit(size());
    bool invertible = false;
    const QPointF px = t.inverted(&invertible).map(point);
    if (!invertible)
        return -1;
    for (int i = tileCount() - 1; i >= 0; --i)
        if (QRectF(m_tiles[static_cast<std::size_t>(i)].stagePx, m_tileSize).contains(px))
            return i;
    return -1;
}

void StitchQualityMap::draw(QPainter& p, const QSizeF& size) const
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

void StitchQualityMap::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    draw(p, size());
}

void StitchQualityMap::mousePressEvent(QMouseEvent* event)
{
    const int i = tileAt(event->position());
    if (i < 0)
        return;
    selectTile(i);
    emit tileClicked(i);
}

QImage StitchQualityMap::render(const QSize& size, const QStringList& legend) const
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
