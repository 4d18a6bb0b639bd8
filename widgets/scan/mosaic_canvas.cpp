#include "widgets/scan/mosaic_canvas.h"

#include "widgets/camera/scale_bar.h"

#include <QKeyEvent>
#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace ui {

namespace {
// About 32 MB of 8-bit blocks of 256 × 256: a full-screen view at any level is a few
// dozen, so panning back and forth over a field or two reads nothing again.
constexpr int kCacheBlocks = 512;
constexpr double kMaxArrowScale = 100;
constexpr double kMaxZoom = 16;  ///< screen pixels per mosaic pixel, at most
constexpr int kFitMarginPx = 8;
/// The cache's unit, in pixels of a level: the writer's TIFF tile, so one block is one read.
constexpr int kBlockPx = 256;

quint64 blockKey(int level, int bx, int by)
{
    return (quint64(quint32(level)) << 48) | (quint64(quint32(by)) << 24) | quint64(quint32(bx));
}

QPointF asPoint(const Eigen::Vector2d& v) { return {v.x(), v.y()}; }
} // namespace

MosaicCanvas::MosaicCanvas(QWidget* parent) : QWidget(parent)
{
    m_cache.setMaxCost(kCacheBlocks);
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void MosaicCanvas::setMosaic(std::shared_ptr<imaging::PyramidReader> reader, const MosaicStageFrame& frame)
{
    m_reader = std::move(reader);
    m_frame = frame;
    m_cache.clear();
    m_blocksRead = 0;
    m_readFailed = false;
    m_low = 0;
    m_high = 65535;
    if (m_reader) {
        if (m_reader->bitsPerSample() == 8)
            m_high = 255;
        // The stretch from the smallest level (at most about 1024² samples): the 0.1 and
        // 99.9 percentiles, so a few saturated or dead pixels do not flatten the picture.
        const int last = static_cast<int>(m_reader->levels().size()) - 1;
        const auto& l = m_reader->levels().back();
        // The middle 2048² at most: a file whose smallest level is still huge (not written
        // by BenchPilot) costs no more than one written here.
        const int sw = std::min(l.width, 2048), sh = std::min(l.height, 2048);
        auto small = m_reader->readRegion(last, (l.width - sw) / 2, (l.height - sh) / 2, sw, sh);
        if (small && !small->px.empty()) {
            std::vector<quint16> v(small->px.begin(), small->px.end());
            const std::size_t lo = v.size() / 1000, hi = v.size() - 1 - v.size() / 1000;
            std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(lo), v.end());
            m_low = v[lo];
            std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(hi), v.end());
            m_high = std::max<quint16>(v[hi], quint16(m_low + 1));
        }
    }
    // Samples to grey once per mosaic, not once per pixel.
    m_lut.resize(65536);
    const double span = double(m_high - m_low);
    for (std::size_t v = 0; v < m_lut.size(); ++v)
        m_lut[v] = static_cast<uchar>(std::clamp((double(v) - m_low) * 255.0 / span + 0.5, 0.0, 255.0));
    // The arrows: the longest correction drawn half a tile long (as on the quality map),
    // but magnified at most kMaxArrowScale times, so corrections of a hundredth of a pixel
    // do not look like a badly placed mosaic over the picture itself.
    double longest = 0;
    for (const auto& t : m_frame.tiles())
        longest = std::max(longest, t.correctionPx.norm());
    const double halfTile = 0.5 * std::min(m_frame.tileWidthPx(), m_frame.tileHeightPx());
    m_arrowScale = longest > 1e-6 ? std::min(kMaxArrowScale, halfTile / longest) : 1;
    fit();
}

double MosaicCanvas::fitZoom() const
{
    if (!m_reader)
        return 1;
    const double w = std::max(1, width() - 2 * kFitMarginPx), h = std::max(1, height() - 2 * kFitMarginPx);
    return std::min(w / m_reader->width(), h / m_reader->height());
}

void MosaicCanvas::fit()
{
    if (m_reader) {
        m_zoom = std::min(kMaxZoom, fitZoom());
        m_centre = QPointF(m_reader->width() / 2.0, m_reader->height() / 2.0);
    }
    m_fitted = true;
    chooseLevel();
    update();
    emit viewChanged();
}

void MosaicCanvas::chooseLevel()
{
    m_level = 0;
    if (!m_reader)
        return;
    const auto& levels = m_reader->levels();
    for (std::size_t k = 1; k < levels.size(); ++k)
        if (levels[k].scale * m_zoom <= 1.0001)
            m_level = static_cast<int>(k);
}

void MosaicCanvas::clampView()
{
    if (!m_reader)
        return;
    // Zoom out no further than a quarter of the fitted size; the centre stays over the mosaic.
    m_zoom = std::clamp(m_zoom, std::min(kMaxZoom, fitZoom() / 4), kMaxZoom);
    m_centre.setX(std::clamp(m_centre.x(), 0.0, double(m_reader->width())));
    m_centre.setY(std::clamp(m_centre.y(), 0.0, double(m_reader->height())));
    chooseLevel();
}

void MosaicCanvas::zoomBy(double factor, const QPointF& anchor)
{
    if (!m_reader || !(factor > 0))
        return;
    const QPointF under = toMosaic(anchor);
    m_zoom *= factor;
    m_fitted = false;
    clampView();
    // Keep `under` beneath the anchor.
    m_centre = under - (anchor - QPointF(width() / 2.0, height() / 2.0)) / m_zoom;
    clampView();
    update();
    emit viewChanged();
}

void MosaicCanvas::panBy(const QPointF& screenPx)
{
    if (!m_reader)
        return;
    m_centre -= screenPx / m_zoom;
    m_fitted = false;
    clampView();
    update();
    emit viewChanged();
}

QPointF MosaicCanvas::toMosaic(const QPointF& w) const { return m_centre + (w - QPointF(width() / 2.0, height() / 2.0)) / m_zoom; }
QPointF MosaicCanvas::toWidget(const QPointF& m) const { return (m - m_centre) * m_zoom + QPointF(width() / 2.0, height() / 2.0); }

void MosaicCanvas::setShowTiles(bool on)
{
    m_showTiles = on;
    update();
}

void MosaicCanvas::setShowQuality(bool on)
{
    m_showQuality = on;
    update();
}

void MosaicCanvas::setStageMm(const std::optional<QPointF>& mm)
{
    if (mm == m_stageMm)
        return;
    m_stageMm = mm;
    update();
}

double MosaicCanvas::scaleBarUm() const
{
    if (!m_reader || width() <= 0)
        return 0;
    return scaleBarFor(m_frame.pixelUm(), std::max(1, int(std::lround(width() / m_zoom))), width()).lengthUm;
}

const QImage* MosaicCanvas::block(int level, int bx, int by)
{
    const quint64 key = blockKey(level, bx, by);
    if (const QImage* hit = m_cache.object(key))
        return hit;
    const int bw = kBlockPx, bh = kBlockPx;
    auto px = m_reader->readRegion(level, bx * bw, by * bh, bw, bh);
    ++m_blocksRead;
    if (!px) {
        if (!m_readFailed) {
            m_readFailed = true;
            emit problem(px.problems());
        }
        return nullptr;
    }
    auto* image = new QImage(px->width, px->height, QImage::Format_Grayscale8);
    for (int y = 0; y < px->height; ++y) {
        const std::uint16_t* src = px->row(y);
        uchar* dst = image->scanLine(y);
        for (int x = 0; x < px->width; ++x)
            dst[x] = m_lut[src[x]];
    }
    m_cache.insert(key, image, 1);
    return m_cache.object(key);
}

void MosaicCanvas::drawMosaic(QPainter& p)
{
    const auto& l = m_reader->levels()[static_cast<std::size_t>(m_level)];
    const int bw = kBlockPx, bh = kBlockPx;
    const double sx = double(m_reader->width()) / l.width, sy = double(m_reader->height()) / l.height;
    const QPointF a = toMosaic(QPointF(0, 0)), b = toMosaic(QPointF(width(), height()));
    const int bx0 = std::max(0, int(std::floor(a.x() / sx / bw))), bx1 = std::min((l.width - 1) / bw, int(std::floor(b.x() / sx / bw)));
    const int by0 = std::max(0, int(std::floor(a.y() / sy / bh))), by1 = std::min((l.height - 1) / bh, int(std::floor(b.y() / sy / bh)));
    // Pixels drawn larger than they are stay square (what is measured is what is seen);
    // smaller, they are smoothed.
    p.setRenderHint(QPainter::SmoothPixmapTransform, l.scale * m_zoom < 1);
    for (int by = by0; by <= by1; ++by)
        for (int bx = bx0; bx <= bx1; ++bx) {
            const QImage* image = block(m_level, bx, by);
            const QRectF target(bx * bw * sx, by * bh * sy, (image ? image->width() : bw) * sx, (image ? image->height() : bh) * sy);
            if (image)
                p.drawImage(target, *image);
            else
                p.fillRect(target, QBrush(QColor(0xc6, 0x28, 0x28), Qt::DiagCrossPattern));
        }
}

void MosaicCanvas::drawOverlay(QPainter& p) const
{
    const double tw = m_frame.tileWidthPx(), th = m_frame.tileHeightPx();
    if (m_showQuality)
        for (const auto& t : m_frame.tiles())
            if (t.placedByStage)
                p.fillRect(QRectF(asPoint(t.topLeftPx), QSizeF(tw, th)), QBrush(QColor(0xef, 0x6c, 0x00, 200), Qt::BDiagPattern));
    if (m_showTiles) {
        QPen pen(QColor(0x4f, 0xc3, 0xf7, 200), 1);
        pen.setCosmetic(true);
        p.setPen(pen);
        p.setBrush(Qt::NoBrush);
        for (const auto& t : m_frame.tiles())
            p.drawRect(QRectF(asPoint(t.topLeftPx), QSizeF(tw, th)));
    }
    if (m_showQuality) {
        for (const auto& t : m_frame.tiles()) {
            const QPointF c = asPoint(t.topLeftPx) + QPointF(tw / 2, th / 2);
            const QPointF d = asPoint(t.correctionPx) * m_arrowScale;
            QPen pen(t.placedByStage ? QColor(0xef, 0x6c, 0x00) : QColor(0xff, 0xd5, 0x4f), 2);
            pen.setCosmetic(true);
            p.setPen(pen);
            if (t.placedByStage) {
                // Flagged: a ring where the arrow would start, so it reads without colour too.
                const double r = 6 / m_zoom;
                p.drawEllipse(c, r, r);
                continue;
            }
            p.drawLine(c, c + d);
            const double len = std::hypot(d.x(), d.y());
            if (len * m_zoom > 4) {
                const QPointF u = d / len, n(-u.y(), u.x());
                const double head = 7 / m_zoom;
                QPainterPath arrow;
                arrow.moveTo(c + d);
                arrow.lineTo(c + d - u * head + n * head * 0.5);
                arrow.lineTo(c + d - u * head - n * head * 0.5);
                arrow.closeSubpath();
                p.fillPath(arrow, pen.color());
            }
        }
    }
    if (m_stageMm) {
        // The stage's field of view now, and a cross at its centre.
        const Eigen::Vector2d at = m_frame.mosaicPxAt({m_stageMm->x(), m_stageMm->y()});
        const QPointF c = asPoint(at);
        QPen pen(QColor(0xe9, 0x1e, 0x63), 2);
        pen.setCosmetic(true);
        p.setPen(pen);
        p.setBrush(Qt::NoBrush);
        p.drawRect(QRectF(c - QPointF((tw - 1) / 2, (th - 1) / 2), QSizeF(tw, th)));
        const double arm = 12 / m_zoom;
        p.drawLine(c - QPointF(arm, 0), c + QPointF(arm, 0));
        p.drawLine(c - QPointF(0, arm), c + QPointF(0, arm));
    }
}

void MosaicCanvas::drawScaleBar(QPainter& p) const
{
    const ScaleBar bar = scaleBarFor(m_frame.pixelUm(), std::max(1, int(std::lround(width() / m_zoom))), width());
    if (bar.lengthUm <= 0)
        return;
    const QLocale locale;
    const QString label = bar.lengthUm >= 1000 ? tr("%1 mm").arg(locale.toString(bar.lengthUm / 1000, 'g', 4))
                                               : tr("%1 µm").arg(locale.toString(bar.lengthUm, 'g', 4));
    const QRectF box(12, height() - 40, std::max(bar.lengthPx, 60.0) + 12, 30);
    p.fillRect(box, QColor(0, 0, 0, 150));
    p.fillRect(QRectF(box.left() + 6, box.bottom() - 10, bar.lengthPx, 4), Qt::white);
    p.setPen(Qt::white);
    p.drawText(QRectF(box.left() + 6, box.top() + 2, box.width() - 12, 16), Qt::AlignLeft | Qt::AlignVCenter, label);
}

void MosaicCanvas::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), QColor(0x26, 0x32, 0x38));
    if (!m_reader) {
        p.setPen(QColor(0xb0, 0xbe, 0xc5));
        p.drawText(rect().adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap,
                   tr("The mosaic shows here after a stitch: zoom with the wheel, drag to pan, double-click to move the stage there."));
        return;
    }
    p.save();
    p.translate(width() / 2.0, height() / 2.0);
    p.scale(m_zoom, m_zoom);
    p.translate(-m_centre);
    drawMosaic(p);
    p.setRenderHint(QPainter::Antialiasing, true);
    drawOverlay(p);
    p.restore();
    drawScaleBar(p);
}

void MosaicCanvas::resizeEvent(QResizeEvent* event)
{
    QWidget::resizeEvent(event);
    if (m_fitted && m_reader)
        fit();
    else
        clampView();
}

void MosaicCanvas::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (steps != 0)
        zoomBy(std::pow(1.25, steps), event->position());
    event->accept();
}

void MosaicCanvas::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton)
        m_dragFrom = event->position().toPoint();
    QWidget::mousePressEvent(event);
}

void MosaicCanvas::mouseMoveEvent(QMouseEvent* event)
{
    if (m_dragFrom && (event->buttons() & Qt::LeftButton)) {
        const QPoint now = event->position().toPoint();
        panBy(QPointF(now - *m_dragFrom));
        m_dragFrom = now;
        setCursor(Qt::ClosedHandCursor);
    }
    if (m_reader) {
        const QPointF m = toMosaic(event->position());
        const bool inside = m.x() >= 0 && m.y() >= 0 && m.x() < m_reader->width() && m.y() < m_reader->height();
        emit cursorMoved(inside ? std::optional<QPointF>(m) : std::nullopt);
    }
}

void MosaicCanvas::mouseReleaseEvent(QMouseEvent* event)
{
    m_dragFrom.reset();
    unsetCursor();
    QWidget::mouseReleaseEvent(event);
}

void MosaicCanvas::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton || !m_reader)
        return;
    const QPointF m = toMosaic(event->position());
    if (m.x() >= 0 && m.y() >= 0 && m.x() < m_reader->width() && m.y() < m_reader->height())
        emit doubleClicked(m);
}

void MosaicCanvas::keyPressEvent(QKeyEvent* event)
{
    const double stepX = width() / 10.0, stepY = height() / 10.0;
    switch (event->key()) {
    case Qt::Key_Left: panBy({stepX, 0}); break;
    case Qt::Key_Right: panBy({-stepX, 0}); break;
    case Qt::Key_Up: panBy({0, stepY}); break;
    case Qt::Key_Down: panBy({0, -stepY}); break;
    default: QWidget::keyPressEvent(event); return;
    }
    event->accept();
}

void MosaicCanvas::leaveEvent(QEvent* event)
{
    emit cursorMoved(std::nullopt);
    QWidget::leaveEvent(event);
}

} // namespace ui
