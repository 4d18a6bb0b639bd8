#include "widgets/scan/stitch_quality_map.h"

#include <QMouseEvent>
#include <QPainter>

namespace ui {

StitchQualityMap::StitchQualityMap(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("stitchQualityMap"));
    setMouseTracking(false);
}

void StitchQualityMap::setResult(const imaging::StitchResult& result)
{
    m_drawing.setResult(result);
    update();
}

void StitchQualityMap::clear()
{
    m_drawing.clear();
    update();
}

void StitchQualityMap::selectTile(int index)
{
    m_drawing.selectTile(index);
    update();
}

void StitchQualityMap::beginLive(const std::vector<QPointF>& plannedPx, const QSizeF& tileSize)
{
    m_drawing.beginLive(plannedPx, tileSize);
    update();
}

void StitchQualityMap::setLiveTile(int index, QPointF stagePx, QSize size, std::shared_ptr<const imaging::ImageU16> thumbnail)
{
    if (m_drawing.setLiveTile(index, stagePx, size.isValid() ? QSizeF(size) : QSizeF(), std::move(thumbnail)))
        update();
}

void StitchQualityMap::setLivePair(const imaging::TilePair& pair)
{
    m_drawing.setLivePair(pair);
    update();
}

void StitchQualityMap::paintEvent(QPaintEvent*)
{
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    m_drawing.draw(p, size());
}

void StitchQualityMap::mousePressEvent(QMouseEvent* event)
{
    const int i = tileAt(event->position());
    if (i < 0)
        return;
    selectTile(i);
    emit tileClicked(i);
}

} // namespace ui
