#include "widgets/plots_screen.h"

#include "widgets/channel_picker.h"
#include "widgets/plot_cursors.h"
#include "widgets/plot_export.h"
#include "widgets/plot_panel.h"
#include "widgets/plot_stack.h"
#include "widgets/plot_toolbar.h"
#include "widgets/xy_view.h"

#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QEvent>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSplitter>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <cmath>

namespace ui {
namespace {
const QString kConsumerPlots = QStringLiteral("plots");
const QString kConsumerXy = QStringLiteral("plots-xy");
/// A stream silent for longer than this has stopped: its "now" moves on with host time.
constexpr qint64 kStaleMs = 1000;
} // namespace

PlotsScreen::PlotsScreen(dev::tele::TelemetryHub* hub, QWidget* parent) : QWidget(parent), m_hub(hub), m_source(hub)
{
    auto* top = new QVBoxLayout(this);
    top->setContentsMargins(4, 4, 4, 2);
    auto* bar = new QHBoxLayout;
    m_stack = new PlotStack(&m_source, this);
    m_stack->setObjectName(QStringLiteral("plotStack"));
    m_stack->setTimeRange(-10, 0);
    m_cursors = new PlotCursors(m_stack);
    buildToolbar(bar);
    top->addLayout(bar);

    m_split = new QSplitter(Qt::Horizontal, this);
    m_split->addWidget(m_stack);
    auto* side = new QWidget(m_split);
    auto* sv = new QVBoxLayout(side);
    sv->setContentsMargins(4, 0, 0, 0);
    m_picker = new ChannelPicker(side);
    m_xy = new XyView(&m_source, side);
    m_readout = new CursorReadout(m_cursors, side);
    m_readout->setObjectName(QStringLiteral("cursorReadout"));
    m_readout->setMaximumHeight(180);
    sv->addWidget(m_picker, 2);
    sv->addWidget(m_xy, 3);
    sv->addWidget(m_readout, 1);
    m_split->addWidget(side);
    m_split->setStretchFactor(0, 3);
    m_split->setStretchFactor(1, 1);
    m_split->setSizes({1000, 380});
    top->addWidget(m_split, 1);

    auto* statusRow = new QHBoxLayout;
    m_status = new QLabel(this);
    m_status->setObjectName(QStringLiteral("plotsStatus"));
    m_status->setTextFormat(Qt::RichText);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("plotsMessage"));
    m_message->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    statusRow->addWidget(m_status, 1);
    statusRow->addWidget(m_message, 1);
    top->addLayout(statusRow);

    for (int i = 0; i < 2; ++i)
        m_stack->addPanel();  // three plots to start with
    m_picker->setPlotCount(plotCount());
    showPlotInPicker(0);

    m_frame.setSingleShot(true);
    m_frame.setInterval(kFrameMs);
    connect(&m_frame, &QTimer::timeout, this, &PlotsScreen::redraw);
    m_statusTimer.setInterval(250);
    connect(&m_statusTimer, &QTimer::timeout, this, [this] {
        refreshPicker();
        updateStatus();
    });
    m_statusTimer.start();

    connect(m_picker, &ChannelPicker::channelToggled, this, [this](int plot, const dev::tele::ChannelKey& key, bool on) {
        if (on)
            addChannel(plot, key);
        else
            removeChannel(plot, key);
    });
    connect(m_picker, &ChannelPicker::currentPlotChanged, this, &PlotsScreen::showPlotInPicker);
    connect(m_stack, &PlotStack::panelClicked, this, &PlotsScreen::showPlotInPicker);
    connect(m_stack, &PlotStack::userMovedTime, this, [this] {
        if (!m_paused) {
            setPaused(true);
            tell(tr("Paused: the time axis was moved. Resume returns to the live view."), false);
        }
        scheduleRedraw();
    });
    connect(m_stack, &PlotStack::userMovedValues, this, [this] { m_autoY->setChecked(false); });
    connect(m_cursors, &PlotCursors::changed, this, [this] { m_cursorsButton->setChecked(m_cursors->isVisible()); });

    if (m_hub) {
        connect(m_hub, &dev::tele::TelemetryHub::dataArrived, this, [this](int instrument) {
            if (instrument >= 0 && instrument < 2)
                m_arrival[instrument].start();
            if (!m_paused)
                scheduleRedraw();
        });
        connect(m_hub, &dev::tele::TelemetryHub::subscriptionChanged, this, [this](int instrument, int rateHz, const motion::msg::Message& note) {
            m_rates[instrument] = rateHz;
            m_notes[instrument] = note;
            updateStatus();
        });
        connect(m_hub, &dev::tele::TelemetryHub::problem, this, [this](const motion::msg::Message& m) {
            // A device clock that started again is news, not a fault: it must not stay red for minutes.
            tell(ui::words::text(m), m.id != "telemetry.clock_restarted");
        });
    }
    setWindowS(kDefaultWindowS);
    refreshPicker();
    updateWanted();
    updateStatus();
}

PlotsScreen::~PlotsScreen()
{
    if (m_hub) {
        m_hub->setWanted(kConsumerPlots, {}, 0);
        m_hub->setWanted(kConsumerXy, {}, 0);
    }
}

void PlotsScreen::buildToolbar(QHBoxLayout* bar)
{
    auto* tools = new PlotToolbar(kDefaultRateHz, kRawCsvLimitSamples, this);
    bar->addWidget(tools);
    m_window = tools->window;
    m_rate = tools->rate;
    m_pause = tools->pause;
    m_autoY = tools->autoY;
    m_cursorsButton = tools->cursors;
    m_xyButton = tools->xy;
    m_addPlot = tools->addPlot;
    m_removePlot = tools->removePlot;
    m_record = tools->record;
    m_exportCsv = tools->exportCsv;
    m_exportPng = tools->exportPng;
    m_exportPdf = tools->exportPdf;
    m_exportHistory = tools->exportHistory;
    m_exportHistory->setVisible(m_hub && m_hub->historyEnabled());
    connect(tools->historySpans, &QMenu::triggered, this, [this](QAction* a) { exportHistory(a->data().toDouble()); });
    connect(m_window, qOverload<int>(&QComboBox::activated), this, [this](int i) { setWindowS(m_window->itemData(i).toDouble()); });
    connect(m_rate, qOverload<int>(&QComboBox::activated), this, [this] { updateWanted(); });
    connect(m_pause, &QPushButton::toggled, this, &PlotsScreen::setPaused);
    connect(m_autoY, &QPushButton::toggled, this, &PlotsScreen::setAutoScaleY);
    connect(m_cursorsButton, &QPushButton::toggled, this, &PlotsScreen::setCursorsVisible);
    connect(m_xyButton, &QPushButton::toggled, this, &PlotsScreen::setXyVisible);
    connect(m_addPlot, &QPushButton::clicked, this, [this] { addPlot(); });
    connect(m_removePlot, &QPushButton::clicked, this, [this] { removePlot(m_picker->currentPlot()); });
    connect(m_record, &QPushButton::clicked, this, [this](bool on) {
        if (on)
            startRecording();
        else
            stopRecording();
    });
    connect(m_exportCsv, &QPushButton::clicked, this, [this] { exportCsv(); });
    connect(m_exportPng, &QPushButton::clicked, this, [this] { exportPng(); });
    connect(m_exportPdf, &QPushButton::clicked, this, [this] { exportPdf(); });
}

int PlotsScreen::plotCount() const { return m_stack->panelCount(); }

int PlotsScreen::addPlot()
{
    m_stack->addPanel();
    m_picker->setPlotCount(plotCount());
    showPlotInPicker(plotCount() - 1);
    scheduleRedraw();
    return plotCount() - 1;
}

bool PlotsScreen::removePlot(int index)
{
    if (!m_stack->removePanel(index))
        return false;
    m_picker->setPlotCount(plotCount());
    showPlotInPicker(std::min(index, plotCount() - 1));
    updateWanted();
    scheduleRedraw();
    return true;
}

bool PlotsScreen::addChannel(int plot, const dev::tele::ChannelKey& key)
{
    if (!m_stack->addChannel(plot, key))
        return false;
    if (plot == m_picker->currentPlot())
        m_picker->showChecked(m_stack->panel(plot)->channels());
    updateWanted();
    scheduleRedraw();
    return true;
}

bool PlotsScreen::removeChannel(int plot, const dev::tele::ChannelKey& key)
{
    if (!m_stack->removeChannel(plot, key))
        return false;
    if (plot == m_picker->currentPlot())
        m_picker->showChecked(m_stack->panel(plot)->channels());
    updateWanted();
    scheduleRedraw();
    return true;
}

void PlotsScreen::showPlotInPicker(int index)
{
    if (index < 0 || index >= plotCount())
        return;
    m_picker->setCurrentPlot(index);
    m_picker->showChecked(m_stack->panel(index)->channels());
    m_picker->revealChecked();
    m_stack->setHighlightedPanel(index);
    m_removePlot->setEnabled(plotCount() > 1);
    m_stack->replot(QCustomPlot::rpQueuedReplot);
}

void PlotsScreen::setWindowS(double seconds)
{
    seconds = std::clamp(seconds, 1.0, 600.0);
    if (m_hub)
        m_hub->setWindowS(seconds);
    int best = 0;
    for (int i = 0; i < m_window->count(); ++i)
        if (std::abs(m_window->itemData(i).toDouble() - seconds) < std::abs(m_window->itemData(best).toDouble() - seconds))
            best = i;
    m_window->setCurrentIndex(best);
    m_stack->setTimeRange(-seconds, 0);
    scheduleRedraw();
}

double PlotsScreen::windowS() const { return m_hub ? m_hub->windowS() : m_window->currentData().toDouble(); }

void PlotsScreen::setPaused(bool paused)
{
    if (paused == m_paused)
        return;
    m_paused = paused;
    if (m_hub)
        m_hub->setPaused(paused);
    if (paused && m_hub) {
        // Freeze at the hub's pause instant: the hub keeps [pausedAt − window, pausedAt].
        double anchors[2];
        for (int i = 0; i < 2; ++i) {
            anchors[i] = m_hub->pausedAtS(i);
            if (std::isnan(anchors[i]))
                anchors[i] = m_stack->anchorS(i);
        }
        m_stack->setAnchors(anchors[0], anchors[1]);
    }
    {
        const QSignalBlocker block(m_pause);
        m_pause->setChecked(paused);
    }
    m_pause->setText(paused ? tr("Resume") : tr("Pause"));
    updateWanted();
    updateStatus();
    scheduleRedraw();
}

void PlotsScreen::setRateHz(int rateHz)
{
    int best = 0;
    for (int i = 0; i < m_rate->count(); ++i)
        if (std::abs(m_rate->itemData(i).toInt() - rateHz) < std::abs(m_rate->itemData(best).toInt() - rateHz))
            best = i;
    m_rate->setCurrentIndex(best);
    updateWanted();
}

int PlotsScreen::rateHz() const { return m_rate->currentData().toInt(); }

void PlotsScreen::setAutoScaleY(bool on)
{
    m_stack->setAutoScaleValues(on);
    if (m_autoY->isChecked() != on)
        m_autoY->setChecked(on);
    scheduleRedraw();
}

void PlotsScreen::setCursorsVisible(bool on)
{
    if (m_cursors->isVisible() != on)
        m_cursors->setVisible(on);
    m_stack->replot(QCustomPlot::rpQueuedReplot);
}

void PlotsScreen::setXyVisible(bool on)
{
    m_xy->setVisible(on);
    if (m_xyButton->isChecked() != on)
        m_xyButton->setChecked(on);
    updateWanted();
    scheduleRedraw();
}

void PlotsScreen::updateWanted()
{
    if (!m_hub)
        return;
    const bool wanted = isVisible() || m_paused;
    m_hub->setWanted(kConsumerPlots, wanted ? m_stack->allChannels() : QVector<dev::tele::ChannelKey>{}, rateHz());
    m_hub->setWanted(kConsumerXy, wanted && m_xyButton->isChecked() ? m_xy->channels() : QVector<dev::tele::ChannelKey>{}, rateHz());
}

void PlotsScreen::refreshPicker()
{
    if (!m_hub)
        return;
    for (int instrument : m_hub->instruments()) {
        const auto available = m_hub->availableChannels(instrument);
        QVector<ChannelPicker::Entry> entries;
        for (const auto& k : available)
            entries << ChannelPicker::Entry{k, m_hub->channelName(k), m_hub->channelUnit(k)};
        m_picker->setInstrumentChannels(instrument, m_hub->instrumentName(instrument), entries);
        applyDefaults(instrument, available);
    }
    m_xy->setInstrument(m_xy->instrument());  // the unit is known once the stage is identified
}

void PlotsScreen::applyDefaults(int instrument, const QVector<dev::tele::ChannelKey>& available)
{
    if (instrument < 0 || instrument > 1 || m_defaultsApplied[instrument] || available.isEmpty())
        return;
    m_defaultsApplied[instrument] = true;
    using K = dev::proto::ChannelKind;
    auto key = [instrument](int axis, K kind) { return dev::tele::ChannelKey{instrument, dev::proto::ChannelRef{std::uint8_t(axis), kind}}; };
    // The stage: positions on the first plot, following errors on the second; the
    // analyzer's measured positions on the third. A plot someone already filled is left alone.
    QVector<QPair<int, dev::tele::ChannelKey>> wanted;
    if (instrument == 1) {
        for (int axis : {0, 1}) {
            wanted << qMakePair(0, key(axis, K::Commanded)) << qMakePair(0, key(axis, K::Measured));
            wanted << qMakePair(1, key(axis, K::FollowingError));
        }
    } else {
        for (int axis : {0, 1, 2})
            wanted << qMakePair(2, key(axis, K::Measured));
    }
    for (const auto& [plot, k] : wanted)
        if (plot < plotCount() && available.contains(k)
            && (m_stack->panel(plot)->channels().isEmpty() || m_stack->panel(plot)->channels().first().instrument == instrument))
            m_stack->addChannel(plot, k);
    showPlotInPicker(m_picker->currentPlot());
    updateWanted();
    scheduleRedraw();
}

double PlotsScreen::liveAnchor(int instrument) const
{
    double latest = m_hub ? m_hub->latestTimeS(instrument) : std::nan("");
    // A stream that stopped (link lost, telemetry off) slides off the plot with host time.
    if (!std::isnan(latest) && m_arrival[instrument].isValid() && m_arrival[instrument].elapsed() > kStaleMs)
        latest += m_arrival[instrument].elapsed() / 1000.0;
    return latest;
}

void PlotsScreen::scheduleRedraw()
{
    if (!m_frame.isActive())
        m_frame.start();
}

void PlotsScreen::redraw()
{
    if (!isVisible())
        return;  // showEvent draws
    if (!m_paused) {
        m_stack->setTimeRange(-windowS(), 0);
        m_stack->setAnchors(liveAnchor(0), liveAnchor(1));
    }
    m_stack->redraw();
    if (m_xy->isVisible()) {
        const QCPRange r = m_stack->timeRange();
        m_xy->refresh(m_stack->anchorS(m_xy->instrument()), r.lower, r.upper);
    }
    m_readout->refresh();
    ++m_frames;
}

void PlotsScreen::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    updateWanted();
    scheduleRedraw();
}

void PlotsScreen::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    updateWanted();
}

void PlotsScreen::updateStatus()
{
    m_status->setText(statusText());
}

void PlotsScreen::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        updateStatus();
    QWidget::changeEvent(event);
}

QString PlotsScreen::statusText() const
{
    if (!m_hub)
        return QString();
    QStringList parts;
    for (int i : m_hub->instruments()) {
        const int rate = m_rates.value(i, m_hub->subscribedRateHz(i));
        QString s = tr("<b>%1</b>: %2 · %3 samples").arg(m_hub->instrumentName(i).toHtmlEscaped(),
                                                        rate > 0 ? tr("%1 Hz").arg(rate) : tr("not streaming"))
                        .arg(m_hub->samplesReceived(i));
        const quint64 lost = m_hub->lostSamples(i);
        s += lost ? tr(" · <span style='color:#b71c1c'><b>%1 lost</b></span>").arg(lost) : tr(" · 0 lost");
        if (m_hub->heldBackSamples(i))
            s += tr(" · %1 not kept while paused").arg(m_hub->heldBackSamples(i));
        const QString note = ui::words::text(m_notes.value(i));
        if (!note.isEmpty())
            s += QStringLiteral(" · <i>%1</i>").arg(note.toHtmlEscaped());
        parts << s;
    }
    const QString history = historyText();
    if (!history.isEmpty())
        parts << history.toHtmlEscaped();
    if (m_paused)
        parts << tr("<b>paused</b>");
    if (m_hub->recording())
        parts << tr("<span style='color:#b71c1c'>● recording %1 rows to %2</span>")
                     .arg(m_hub->recordedRows())
                     .arg(QFileInfo(m_hub->recordingPath()).fileName().toHtmlEscaped());
    return parts.join(QStringLiteral(" &nbsp;|&nbsp; "));
}

QString PlotsScreen::chooseFile(const QString& title, const QString& filter, const QString& suffix)
{
    if (m_chooser)
        return m_chooser(title, filter);
    QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
    if (dir.isEmpty())
        dir = QDir::homePath();
    return QDir(dir).filePath(QStringLiteral("BenchPilot/plots-%1.%2")
                                  .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")), suffix));
}

void PlotsScreen::tell(const QString& text, bool isProblem)
{
    m_lastMessage = text;
    m_message->setText(text);
    m_message->setStyleSheet(isProblem ? QStringLiteral("color:#b71c1c;") : QString());
    m_messageProblem = isProblem;
    // News fades like the banner's notes; a problem stays until the next message.
    if (!isProblem)
        QTimer::singleShot(kNoteFadeMs, m_message, [this, text] {
            if (m_lastMessage == text && !m_messageProblem)
                m_message->clear();
        });
    if (isProblem)
        emit problem(text);
    else
        emit message(text);
}

bool PlotsScreen::exportCsv(const QString& path)
{
    const QString file = path.isEmpty() ? chooseFile(tr("Export the visible range as CSV"), tr("CSV files (*.csv)"), QStringLiteral("csv")) : path;
    if (file.isEmpty())
        return false;
    const CsvExportResult r = ui::exportCsv(*m_stack, file);
    if (!r.ok) {
        tell(r.error, true);
        return false;
    }
    tell(r.decimated ? tr("Exported the decimated view (%1 rows, min/max per pixel column) to %2").arg(r.rows).arg(QDir::toNativeSeparators(file))
                     : tr("Exported %1 rows of raw samples to %2").arg(r.rows).arg(QDir::toNativeSeparators(file)),
         false);
    return true;
}

bool PlotsScreen::exportPng(const QString& path)
{
    const QString file = path.isEmpty() ? chooseFile(tr("Export the plots as PNG"), tr("PNG pictures (*.png)"), QStringLiteral("png")) : path;
    if (file.isEmpty())
        return false;
    QString error;
    if (!ui::exportPng(*m_stack, file, &error)) {
        tell(error, true);
        return false;
    }
    tell(tr("Saved the plots to %1").arg(QDir::toNativeSeparators(file)), false);
    return true;
}

bool PlotsScreen::exportPdf(const QString& path)
{
    const QString file = path.isEmpty() ? chooseFile(tr("Export the plots as PDF"), tr("PDF documents (*.pdf)"), QStringLiteral("pdf")) : path;
    if (file.isEmpty())
        return false;
    QString error;
    if (!ui::exportPdf(*m_stack, file, &error)) {
        tell(error, true);
        return false;
    }
    tell(tr("Saved the plots to %1").arg(QDir::toNativeSeparators(file)), false);
    return true;
}

QString PlotsScreen::historyText() const
{
    if (!m_hub || !m_hub->historyEnabled())
        return QString();
    double spanS = 0;
    bool heldBack = false;
    for (int i : m_hub->instruments()) {
        spanS = std::max(spanS, m_hub->historySpanS(i));
        heldBack = heldBack || m_hub->historyHeldBack(i);
    }
    QString text = tr("last %1 recorded").arg(ui::words::duration(std::floor(spanS)));
    if (heldBack)
        text += tr(" (plotted channels only: the link carries no more)");
    return text;
}

bool PlotsScreen::exportHistory(double spanS, const QString& path)
{
    if (!m_hub || !m_hub->historyEnabled())
        return false;
    const QString file = path.isEmpty() ? chooseFile(tr("Export the recorded history as CSV"), tr("CSV files (*.csv)"), QStringLiteral("csv")) : path;
    if (file.isEmpty())
        return false;
    QDir().mkpath(QFileInfo(file).absolutePath());
    motion::msg::Message error;
    quint64 rows = 0;
    if (!m_hub->exportHistory(file, spanS, &error, &rows)) {
        tell(ui::words::text(error), true);
        return false;
    }
    tell(tr("Exported %1 rows of recorded history (%2 channels) to %3")
             .arg(rows)
             .arg(m_hub->historyChannels().size())
             .arg(QDir::toNativeSeparators(file)),
         false);
    return true;
}

bool PlotsScreen::startRecording(const QString& path)
{
    auto setButton = [this](bool on) {
        const QSignalBlocker block(m_record);
        m_record->setChecked(on);
        m_record->setText(on ? tr("● Stop recording") : tr("Record…"));
    };
    if (!m_hub || m_hub->recording()) {
        setButton(m_hub && m_hub->recording());
        return false;
    }
    QVector<dev::tele::ChannelKey> channels = m_stack->allChannels();
    if (m_xyButton->isChecked())
        for (const auto& k : m_xy->channels())
            if (!channels.contains(k))
                channels << k;
    const QString file = path.isEmpty() ? chooseFile(tr("Record telemetry to CSV"), tr("CSV files (*.csv)"), QStringLiteral("csv")) : path;
    if (file.isEmpty()) {
        setButton(false);
        return false;
    }
    QDir().mkpath(QFileInfo(file).absolutePath());
    motion::msg::Message error;
    if (!m_hub->startRecording(file, channels, &error)) {
        setButton(false);
        tell(ui::words::text(error), true);
        return false;
    }
    setButton(true);
    tell(tr("Recording %1 channels to %2").arg(channels.size()).arg(QDir::toNativeSeparators(file)), false);
    updateStatus();
    return true;
}

void PlotsScreen::stopRecording()
{
    {
        const QSignalBlocker block(m_record);
        m_record->setChecked(false);
        m_record->setText(tr("Record…"));
    }
    if (!m_hub || !m_hub->recording())
        return;
    const QString file = m_hub->recordingPath();
    const quint64 rows = m_hub->recordedRows();
    m_hub->stopRecording();
    tell(tr("Recorded %1 rows to %2").arg(rows).arg(QDir::toNativeSeparators(file)), false);
    updateStatus();
}

} // namespace ui
