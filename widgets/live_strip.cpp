#include "widgets/live_strip.h"

#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

LiveStrip::LiveStrip(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("liveStrip"));
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    auto* row = new QHBoxLayout;
    auto* title = new QLabel(tr("Live: position and following error of axis"), this);
    m_axisChooser = new QComboBox(this);
    m_axisChooser->setObjectName(QStringLiteral("stripAxis"));
    m_axisChooser->setToolTip(tr("The axis plotted below; jogging an axis also chooses it"));
    m_axisChooser->setFocusPolicy(Qt::ClickFocus);
    title->setBuddy(m_axisChooser);
    m_note = new QLabel(this);
    m_note->setStyleSheet(QStringLiteral("color:#555;"));
    row->addWidget(title);
    row->addWidget(m_axisChooser);
    row->addSpacing(12);
    row->addWidget(m_note, 1);
    v->addLayout(row);
    m_stack = new PlotStack(&m_source, this);
    m_stack->setObjectName(QStringLiteral("liveStripPlot"));
    m_stack->setInteractions({});  // always live: nothing to pan or zoom
    m_stack->setFocusPolicy(Qt::NoFocus);
    m_stack->setTimeTitle(tr("Time (s)"));
    m_stack->addPanel();
    m_stack->setTimeRange(-kWindowS, 0);
    m_stack->setMinimumHeight(200);
    v->addWidget(m_stack, 1);

    m_frame.setSingleShot(true);
    m_frame.setInterval(kFrameMs);
    connect(&m_frame, &QTimer::timeout, this, &LiveStrip::redraw);
    connect(m_axisChooser, qOverload<int>(&QComboBox::activated), this, &LiveStrip::setAxis);
}

LiveStrip::~LiveStrip()
{
    if (m_hub)
        m_hub->setWanted(consumer(), {}, 0);
}

QString LiveStrip::consumer() const { return QStringLiteral("jog-strip-%1").arg(m_instrument); }

void LiveStrip::setTelemetry(dev::tele::TelemetryHub* hub, int instrument)
{
    if (m_hub) {
        m_hub->setWanted(consumer(), {}, 0);
        disconnect(m_hub, nullptr, this, nullptr);
    }
    m_hub = hub;
    m_source.setHub(hub);
    m_instrument = instrument;
    if (m_hub)
        connect(m_hub, &dev::tele::TelemetryHub::dataArrived, this, [this](int i) {
            if (i == m_instrument && isVisible() && !m_frame.isActive())
                m_frame.start();
        });
    rebuildChannels();
}

void LiveStrip::setAxes(const QStringList& letters)
{
    m_axisChooser->clear();
    for (const QString& l : letters)
        m_axisChooser->addItem(l);
    m_axis = std::clamp(m_axis, 0, std::max(0, int(letters.size()) - 1));
    m_axisChooser->setCurrentIndex(m_axis);
    rebuildChannels();
}

void LiveStrip::setAxis(int axis)
{
    if (axis < 0 || (m_axisChooser->count() > 0 && axis >= m_axisChooser->count()) || axis == m_axis)
        return;
    m_axis = axis;
    m_axisChooser->setCurrentIndex(axis);
    rebuildChannels();
}

QVector<dev::tele::ChannelKey> LiveStrip::channels() const
{
    const auto a = static_cast<std::uint8_t>(m_axis);
    return {dev::tele::ChannelKey{m_instrument, {a, dev::proto::ChannelKind::Commanded}},
            dev::tele::ChannelKey{m_instrument, {a, dev::proto::ChannelKind::Measured}},
            dev::tele::ChannelKey{m_instrument, {a, dev::proto::ChannelKind::FollowingError}}};
}

void LiveStrip::rebuildChannels()
{
    for (int p = 0; p < m_stack->panelCount(); ++p)
        for (const auto& k : m_stack->panel(p)->channels())
            m_stack->removeChannel(p, k);
    if (m_hub && m_axisChooser->count() > 0) {
        const auto ch = channels();
        m_stack->addChannel(0, ch[0]);
        m_stack->addChannel(0, ch[1]);
        m_stack->addChannel(1, ch[2]);
    }
    updateWanted();
    if (isVisible())
        m_frame.start();
}

void LiveStrip::updateWanted()
{
    if (!m_hub)
        return;
    if (isVisible() && m_axisChooser->count() > 0)
        m_hub->setWanted(consumer(), channels(), kRateHz);
    else
        m_hub->setWanted(consumer(), {}, 0);  // nobody looks: the link carries nothing for us
}

void LiveStrip::redraw()
{
    if (!m_hub || !isVisible())
        return;
    m_note->setText(m_hub->paused() ? tr("Plots screen paused: this strip stops once that pause has filled its window")
                                    : QString());
    const double now = m_hub->latestTimeS(m_instrument);
    const double window = std::min(kWindowS, m_hub->windowS());
    m_stack->setTimeRange(-window, 0);
    m_stack->setAnchors(m_instrument == 0 ? now : std::nan(""), m_instrument == 1 ? now : std::nan(""));
    m_stack->redraw();
    ++m_frames;
}

void LiveStrip::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    updateWanted();
    m_frame.start();
}

void LiveStrip::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    updateWanted();
}

} // namespace ui
