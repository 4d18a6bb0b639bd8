#include "widgets/camera/live_view.h"

#include "widgets/camera/focus_plot.h"

#include <QCheckBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QResizeEvent>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

/// The picture and what is drawn over it; the LiveView owns the state.
class LiveCanvas : public QWidget {
public:
    explicit LiveCanvas(LiveView* view) : QWidget(view), m_view(view)
    {
        setMinimumSize(160, 60);  // on a 768-pixel display under the Jog screen's axes; it takes any room left
        setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
        setAttribute(Qt::WA_OpaquePaintEvent);
    }

    QRectF pictureRect() const
    {
        const ProcessedFrame& f = m_view->m_shown;
        if (!f.frameSize.isValid() || f.frameSize.isEmpty())
            return {};
        QSizeF s = QSizeF(f.frameSize).scaled(QSizeF(size()), Qt::KeepAspectRatio);
        return QRectF(QPointF((width() - s.width()) / 2, (height() - s.height()) / 2), s);
    }

protected:
    void resizeEvent(QResizeEvent* e) override
    {
        m_view->m_processor->setTargetSize(e->size() * devicePixelRatioF());
        QWidget::resizeEvent(e);
    }

    void paintEvent(QPaintEvent*) override
    {
        QPainter p(this);
        p.fillRect(rect(), QColor(0x20, 0x20, 0x20));
        const ProcessedFrame& f = m_view->m_shown;
        QFont small = font();
        small.setPointSizeF(std::max(7.0, small.pointSizeF() - 0.5));
        p.setFont(small);
        if (f.image.isNull()) {
            p.setPen(QColor(0xbd, 0xbd, 0xbd));
            p.drawText(rect().adjusted(12, 12, -12, -12), Qt::AlignCenter | Qt::TextWordWrap,
                       m_view->m_message.isEmpty() ? LiveView::tr("No picture: open a camera.") : m_view->m_message);
            return;
        }
        const QRectF pic = pictureRect();
        p.setRenderHint(QPainter::SmoothPixmapTransform);
        p.drawImage(pic, f.image);
        // The crosshair marks the field's centre: the point the stage position is of.
        const QPointF c = pic.center();
        const double arm = std::min(pic.width(), pic.height()) * 0.06;
        for (const auto& [colour, w] : {std::pair{QColor(0, 0, 0, 160), 3.0}, std::pair{QColor(0xff, 0xeb, 0x3b), 1.0}}) {
            p.setPen(QPen(colour, w));
            p.drawLine(QPointF(c.x() - arm, c.y()), QPointF(c.x() - arm / 4, c.y()));
            p.drawLine(QPointF(c.x() + arm / 4, c.y()), QPointF(c.x() + arm, c.y()));
            p.drawLine(QPointF(c.x(), c.y() - arm), QPointF(c.x(), c.y() - arm / 4));
            p.drawLine(QPointF(c.x(), c.y() + arm / 4), QPointF(c.x(), c.y() + arm));
        }
        const QFontMetrics fm(small);
        auto label = [&](const QRectF& box, int align, const QString& text) {
            const QRectF used = fm.boundingRect(box.toRect(), int(align), text).adjusted(-4, -2, 4, 2);
            p.fillRect(used, QColor(0, 0, 0, 150));
            p.setPen(Qt::white);
            p.drawText(box, align, text);
        };
        const QRectF inner = pic.adjusted(8, 6, -8, -6);
        label(inner, Qt::AlignLeft | Qt::AlignTop, m_view->overlayText());
        const ScaleBar bar = m_view->scaleBar();
        if (bar.lengthUm > 0) {
            const QPointF end(inner.left() + bar.lengthPx, inner.bottom() - fm.height() - 6);
            const QRectF barRect(QPointF(inner.left(), end.y() - 3), QPointF(end.x(), end.y() + 3));
            p.fillRect(barRect.adjusted(-1, -1, 1, 1), QColor(0, 0, 0, 160));
            p.fillRect(barRect, Qt::white);
            label(QRectF(inner.left(), end.y() + 5, std::max(bar.lengthPx, 80.0), fm.height() + 2), Qt::AlignLeft | Qt::AlignTop,
                  LiveView::tr("%1 µm").arg(bar.lengthUm, 0, 'g', 4));
        } else {
            label(inner, Qt::AlignLeft | Qt::AlignBottom, LiveView::tr("Pixel size not known: no scale bar"));
        }
    }

private:
    LiveView* m_view;
};

LiveView::LiveView(QWidget* parent) : QWidget(parent), m_processor(new LiveViewProcessor(this))
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    auto* bar = m_bar = new QHBoxLayout;
    m_pause = new QPushButton;
    m_pause->setObjectName(QStringLiteral("livePause"));
    m_pause->setCheckable(true);
    connect(m_pause, &QPushButton::toggled, this, &LiveView::setPaused);
    m_autoContrast = new QCheckBox;
    m_autoContrast->setObjectName(QStringLiteral("liveAutoContrast"));
    m_autoContrast->setChecked(true);
    connect(m_autoContrast, &QCheckBox::toggled, this, &LiveView::setAutoContrast);
    m_levelsLabel = new QLabel;
    m_levelsLabel->setObjectName(QStringLiteral("liveLevels"));
    bar->addWidget(m_pause);
    bar->addWidget(m_autoContrast);
    bar->addWidget(m_levelsLabel, 1);
    v->addLayout(bar);
    m_canvas = new LiveCanvas(this);
    v->addWidget(m_canvas, 1);
    auto* focusRow = new QHBoxLayout;
    m_focusLabel = new QLabel;
    m_focusLabel->setObjectName(QStringLiteral("liveFocus"));
    m_focusLabel->setMinimumWidth(150);
    m_focusPlot = new FocusPlot;
    focusRow->addWidget(m_focusLabel);
    focusRow->addWidget(m_focusPlot, 1);
    v->addLayout(focusRow);
    connect(m_processor, &LiveViewProcessor::ready, this, &LiveView::onReady);
    retranslateUi();
}

void LiveView::showFrame(const dev::camera::Frame& frame)
{
    if (m_paused || !isVisible())
        return;  // nothing is computed for a picture nobody sees
    ++m_taken;
    m_processor->submit(frame);
}

void LiveView::onReady(const ProcessedFrame& frame)
{
    if (frame.image.isNull())
        return;
    m_shown = frame;
    m_focusPlot->add(frame.focus);
    updateReadouts();
    m_canvas->update();
}

void LiveView::clear(const QString& message)
{
    m_shown = ProcessedFrame{};
    m_message = message;
    m_focusPlot->clear();
    updateReadouts();
    m_canvas->update();
}

void LiveView::setPaused(bool paused)
{
    if (m_paused == paused)
        return;
    m_paused = paused;
    m_pause->setChecked(paused);
    retranslateUi();
    emit pausedChanged(paused);
}

void LiveView::setAutoContrast(bool on)
{
    if (m_processor->autoContrast() == on)
        return;
    m_processor->setAutoContrast(on);
    m_autoContrast->setChecked(on);
    emit autoContrastChanged(on);
}

bool LiveView::autoContrast() const { return m_processor->autoContrast(); }

void LiveView::setFallbackPixelUm(double um)
{
    m_fallbackPixelUm = um > 0 ? um : 0;
    m_canvas->update();
}

void LiveView::setStagePosition(const std::optional<QPointF>& mm)
{
    if (m_stageMm == mm)
        return;
    m_stageMm = mm;
    m_canvas->update();
}

double LiveView::pixelUm() const { return m_shown.pixelUm > 0 ? m_shown.pixelUm : m_fallbackPixelUm; }

QRectF LiveView::pictureRect() const { return m_canvas->pictureRect(); }

ScaleBar LiveView::scaleBar() const { return scaleBarFor(pixelUm(), m_shown.frameSize.width(), pictureRect().width()); }

const QVector<double>& LiveView::focusHistory() const { return m_focusPlot->history(); }

QString LiveView::overlayText() const
{
    QStringList lines;
    lines << (m_stageMm ? tr("X %1  Y %2 mm").arg(m_stageMm->x(), 0, 'f', 3).arg(m_stageMm->y(), 0, 'f', 3)
                        : tr("Stage position not known"));
    if (m_shown.frameSize.isValid())
        lines << tr("%1 × %2 px · %3-bit · frame %4")
                     .arg(m_shown.frameSize.width())
                     .arg(m_shown.frameSize.height())
                     .arg(m_shown.bitDepth)
                     .arg(m_shown.sequence);
    return lines.join(QLatin1Char('\n'));
}

void LiveView::updateReadouts()
{
    if (m_shown.image.isNull()) {
        m_focusLabel->setText(tr("Focus: —"));
        m_levelsLabel->clear();
        return;
    }
    m_focusLabel->setText(tr("Focus: %1").arg(m_shown.focus * 1e4, 0, 'f', 2));
    m_focusLabel->setToolTip(tr("Variance of the Laplacian (× 10⁴) of a downscaled copy: higher is sharper. "
                                "Turn the focus until it peaks."));
    m_levelsLabel->setText(tr("Levels %1–%2 of %3")
                               .arg(m_shown.stretch.low)
                               .arg(m_shown.stretch.high)
                               .arg((1 << std::clamp(m_shown.bitDepth, 1, 16)) - 1));
}

void LiveView::retranslateUi()
{
    m_pause->setText(m_paused ? tr("Resume") : tr("Pause"));
    m_pause->setToolTip(tr("Hold the picture still, or take frames again"));
    m_autoContrast->setText(tr("Auto contrast"));
    m_autoContrast->setToolTip(tr("Stretch the levels so the darkest and brightest 0.1 % of the pixels clip; off, the full bit depth "
                                  "maps black to white"));
    updateReadouts();
    m_canvas->update();
}

void LiveView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace ui
