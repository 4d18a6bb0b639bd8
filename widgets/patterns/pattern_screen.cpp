#include "widgets/patterns/pattern_screen.h"
#include "widgets/common/button_key.h"

#include "widgets/common/number_field.h"
#include "widgets/wording/wording.h"

#include "device/files/pattern_file.h"
#include "device/files/pattern_run_csv.h"
#include "device/telemetry/telemetry_hub.h"
#include "widgets/patterns/contour_plot.h"
#include "widgets/patterns/pattern_form.h"
#include "widgets/patterns/pattern_preview.h"

#include <QFileInfo>
#include <QComboBox>
#include <QDir>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStandardPaths>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

using dev::jobs::PatternRunner;

using ui::words::duration;

PatternScreen::PatternScreen(QVector<PatternInstrument> instruments, dev::tele::TelemetryHub* hub, QWidget* parent)
    : QWidget(parent), m_instruments(std::move(instruments)), m_hub(hub)
{
    auto* h = new QHBoxLayout(this);
    auto* leftHost = new QWidget(this);
    auto* left = new QVBoxLayout(leftHost);
    left->setContentsMargins(0, 0, 6, 0);
    auto* instRow = new QHBoxLayout;
    instRow->addWidget(new QLabel(tr("Instrument"), leftHost));
    m_instrumentBox = new QComboBox(leftHost);
    for (const auto& in : m_instruments)
        m_instrumentBox->addItem(in.name);
    instRow->addWidget(m_instrumentBox, 1);
    left->addLayout(instRow);
    m_form = new PatternForm(leftHost);
    left->addWidget(m_form);
    m_estimate = new QLabel(leftHost);
    m_estimate->setObjectName(QStringLiteral("patternEstimate"));
    left->addWidget(m_estimate);

    auto* buttons = new QHBoxLayout;
    m_run = new QPushButton(tr("Run"), leftHost);
    m_run->setToolTip(tr("Move to the pattern's start, then run it (F5)"));
    setButtonKey(m_run, QKeySequence(Qt::Key_F5));
    m_pause = new QPushButton(tr("Pause"), leftHost);
    m_pause->setToolTip(tr("Slow down along the path and hold; press again to go on (F6)"));
    setButtonKey(m_pause, QKeySequence(Qt::Key_F6));
    m_abort = new QPushButton(tr("Abort"), leftHost);
    m_abort->setToolTip(tr("Slow down along the path and give the rest up (F8)"));
    setButtonKey(m_abort, QKeySequence(Qt::Key_F8));
    for (QPushButton* b : {m_run, m_pause, m_abort}) {
        b->setMinimumHeight(34);
        buttons->addWidget(b);
    }
    left->addLayout(buttons);
    m_progress = new QProgressBar(leftHost);
    m_progress->setFormat(tr("%v / %m segments"));
    left->addWidget(m_progress);
    m_status = new QLabel(leftHost);
    m_status->setObjectName(QStringLiteral("patternStatus"));
    m_status->setWordWrap(true);
    left->addWidget(m_status);
    m_summary = new QLabel(leftHost);
    m_summary->setObjectName(QStringLiteral("patternSummary"));
    m_summary->setWordWrap(true);
    m_summary->setTextFormat(Qt::RichText);
    left->addWidget(m_summary);
    auto* files = new QHBoxLayout;
    m_load = new QPushButton(tr("Load…"), leftHost);
    auto* load = m_load;
    auto* save = new QPushButton(tr("Save…"), leftHost);
    m_export = new QPushButton(tr("Export run…"), leftHost);
    m_export->setToolTip(tr("The last run's samples as CSV: commanded and measured XY, path distance, contour error"));
    files->addWidget(load);
    files->addWidget(save);
    files->addWidget(m_export);
    left->addLayout(files);
    left->addStretch(1);
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(leftHost);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setMinimumWidth(360);
    scroll->setMaximumWidth(440);
    h->addWidget(scroll);

    auto* rightHost = new QWidget(this);
    auto* right = new QVBoxLayout(rightHost);
    right->setContentsMargins(0, 0, 0, 0);
    auto* viewRow = new QHBoxLayout;
    auto* fit = new QPushButton(tr("Fit"), rightHost);
    fit->setToolTip(tr("Show the whole pattern (wheel: zoom, drag: pan)"));
    viewRow->addWidget(fit);
    viewRow->addSpacing(12);
    auto* stepLabel = new QLabel(tr("Interpolation step"), rightHost);
    viewRow->addWidget(stepLabel);
    m_step = new NumberField(rightHost);
    m_step->setObjectName(QStringLiteral("patternInterpolationStep"));
    m_step->setRange(0.0001, 1);
    m_step->setDisplay('g', 6);
    m_step->setUnit(tr(" mm"));
    m_step->setHelp(tr("Grid of the point-by-point walk drawn when zoomed in (the instrument's resolution by default)"));
    stepLabel->setBuddy(m_step);
    viewRow->addWidget(m_step);
    viewRow->addWidget(new QLabel(tr("zoom in to see the steps"), rightHost));
    viewRow->addStretch(1);
    right->addLayout(viewRow);
    auto* split = new QSplitter(Qt::Vertical, rightHost);
    m_preview = new PatternPreview(split);
    m_contour = new ContourPlot(split);
    split->addWidget(m_preview);
    split->addWidget(m_contour);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 1);
    right->addWidget(split, 1);
    h->addWidget(rightHost, 1);

    m_replan.setSingleShot(true);
    m_replan.setInterval(80);
    connect(&m_replan, &QTimer::timeout, this, &PatternScreen::replan);
    m_redraw.setInterval(100);
    connect(&m_redraw, &QTimer::timeout, this, [this] {
        m_preview->replot(QCustomPlot::rpQueuedReplot);
        m_contour->refresh();
    });
    connect(m_form, &PatternForm::changed, &m_replan, qOverload<>(&QTimer::start));
    connect(m_instrumentBox, &QComboBox::currentIndexChanged, this, &PatternScreen::setInstrument);
    connect(fit, &QPushButton::clicked, m_preview, &PatternPreview::fit);
    connect(m_step, &NumberField::entryChanged, this, [this] {
        if (const auto mm = m_step->value())
            m_preview->setStepMm(*mm);  // an invalid entry keeps the grid drawn and says why
    });
    connect(m_run, &QPushButton::clicked, this, [this] { run(); });
    connect(m_pause, &QPushButton::clicked, this, &PatternScreen::pauseOrResume);
    connect(m_abort, &QPushButton::clicked, this, &PatternScreen::abort);
    auto choose = [this](const QString& title, const QString& filter, bool saving) {
        if (m_chooser)
            return m_chooser(title, filter, saving);
        const QString dir = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation) + QStringLiteral("/BenchPilot");
        QDir().mkpath(dir);
        return saving ? dir + QStringLiteral("/pattern-run.csv") : QString();
    };
    connect(load, &QPushButton::clicked, this, [this, choose] {
        const QString f = choose(tr("Load pattern"), tr("Patterns (*.pattern.json)"), false);
        QString error;
        if (!f.isEmpty() && !loadPattern(f, &error))
            emit problem(error);
    });
    connect(save, &QPushButton::clicked, this, [this, choose] {
        QString f = choose(tr("Save pattern"), tr("Patterns (*.pattern.json)"), true);
        if (f.isEmpty())
            return;
        if (!f.endsWith(QLatin1String(".pattern.json")))
            f += QStringLiteral(".pattern.json");
        QString error;
        if (!savePattern(f, &error))
            emit problem(error);
    });
    connect(m_export, &QPushButton::clicked, this, [this, choose] {
        const QString f = choose(tr("Export run"), tr("CSV (*.csv)"), true);
        QString error;
        if (!f.isEmpty() && !exportRun(f, &error))
            emit problem(error);
    });

    for (int i = 0; i < m_instruments.size(); ++i) {
        const PatternInstrument& in = m_instruments[i];
        connect(in.client, &dev::Instrument::identified, this, [this, i] {
            if (i == m_current)
                setInstrument(i);
        });
        connect(in.client, &dev::Instrument::limitsChanged, this, [this, i] {
            if (i == m_current)
                refreshLimits();
        });
        connect(in.client, &dev::Instrument::stateChanged, this, [this, i](dev::LinkState s) {
            if (i != m_current)
                return;
            if (dev::PathClient* paths = cur().client->paths(); paths && s == dev::LinkState::Ready)
                paths->refreshLimits([this](const auto&) { replan(); });
            if (s != dev::LinkState::Ready)
                m_preview->clearMachinePosition();
            updateButtons();
        });
        connect(in.client, &dev::Instrument::statusChanged, this, [this, i](const dev::InstrumentStatus& st) {
            if (i != m_current || st.axes.size() < 2)
                return;
            m_preview->setMachinePosition({st.axes[0].measured, st.axes[1].measured});
            if (!cur().runner->busy())
                m_preview->replot(QCustomPlot::rpQueuedReplot);
            updateButtons();
        });
        PatternRunner* r = in.runner;
        connect(r, &PatternRunner::stateChanged, this, [this, i](PatternRunner::State s) {
            if (i == m_runOn)
                onRunnerState(s);
        });
        connect(r, &PatternRunner::progress, this, [this, i](std::size_t d, std::size_t t) {
            if (i == m_runOn)
                onProgress(d, t);
        });
        connect(r, &PatternRunner::message, this, [this, i](const motion::msg::Message& m, bool isProblem) {
            if (i != m_runOn)
                return;
            const QString text = ui::words::text(m);
            m_status->setText(text);
            if (isProblem)
                emit problem(QStringLiteral("%1: %2").arg(m_instruments[i].name, text));
        });
        connect(r, &PatternRunner::sampleAdded, this, [this, i](const dev::jobs::PatternRunSample& s) {
            if (i != m_runOn)
                return;
            m_preview->addRunPoint(s.commanded, s.measured);
            m_contour->addSample(s.pathMm, s.contourMm);
            showRunning();
        });
        connect(r, &PatternRunner::finished, this, [this, i](const dev::jobs::PatternRunSummary& s) {
            if (i != m_runOn)
                return;
            m_summary->setText(runSummaryText(s, densityOf(*m_instruments[i].runner)));
            m_redraw.stop();
            m_preview->replot(QCustomPlot::rpQueuedReplot);
            m_contour->refresh();
            wantTelemetry(false);
        });
    }
    if (m_hub)
        connect(m_hub, &dev::tele::TelemetryHub::dataArrived, this, &PatternScreen::onData);
    setInstrument(0);
    m_form->setPattern(motion::plans::Pattern{});
    replan();
    updateButtons();
}

PatternScreen::~PatternScreen()
{
    if (m_hub)
        m_hub->setWanted(QStringLiteral("patterns"), {}, 0);
}

dev::jobs::PatternRunner* PatternScreen::runner() const { return cur().runner; }
QString PatternScreen::statusText() const { return m_status->text(); }
QString PatternScreen::summaryText() const { return m_summary->text(); }

motion::path::SampleDensity PatternScreen::densityOf(const dev::jobs::PatternRunner& runner)
{
    std::vector<double> along, times;
    along.reserve(runner.samples().size());
    times.reserve(runner.samples().size());
    for (const dev::jobs::PatternRunSample& s : runner.samples()) {
        along.push_back(s.pathMm);
        times.push_back(s.tS);
    }
    return motion::path::judgeSampleDensity(runner.path(), along, times, runner.summary().maxContourMm);
}

QString PatternScreen::runSummaryText(const dev::jobs::PatternRunSummary& s, const motion::path::SampleDensity& d)
{
    QString text = tr("<b>Contour error</b> max %1 µm (at %2 mm), RMS %3 µm · <b>time</b> %4 · %5 samples at %6 Hz%7")
                       .arg(s.maxContourMm * 1e3, 0, 'f', 2)
                       .arg(s.maxAtPathMm, 0, 'f', 2)
                       .arg(s.rmsContourMm * 1e3, 0, 'f', 2)
                       .arg(duration(s.durationS))
                       .arg(s.samples)
                       .arg(QLocale().toString(d.rateHz, 'g', d.rateHz < 100 ? 2 : 3))
                       .arg(s.complete ? QString() : tr(" · <b>incomplete</b>"));
    if (d.tooSparse) {
        const QString why = d.largestSagMm > std::fabs(s.maxContourMm)
            ? tr("between two samples the path bends up to %1 µm away from the line joining them, more than the "
                 "largest error found: what the machine did there is not seen")
                  .arg(QLocale().toString(d.largestSagMm * 1e3, 'f', 1))
            : tr("%n samples say little of a largest error", nullptr, static_cast<int>(d.samples));
        text += QStringLiteral("<br><span style='color:#b71c1c'>%1</span>").arg(tr("Too few samples for this figure: %1.").arg(why));
    }
    return text;
}
motion::plans::Pattern PatternScreen::pattern() const { return m_form->pattern(); }

void PatternScreen::setPattern(const motion::plans::Pattern& p)
{
    m_form->setPattern(p);
    replan();
    m_preview->fit();
}

void PatternScreen::setInstrument(int index)
{
    if (index < 0 || index >= m_instruments.size())
        return;
    m_current = index;
    if (m_instrumentBox->currentIndex() != index) {
        const QSignalBlocker block(m_instrumentBox);
        m_instrumentBox->setCurrentIndex(index);
    }
    const auto& id = cur().client->identity();
    m_form->setZAvailable(cur().client->capabilities().testFlag(dev::Capability::CoupledXyThenZ));
    if (!id.axes.isEmpty())
        m_step->setValue(id.axes[0].resolution > 0 ? id.axes[0].resolution : 0.001);
    refreshLimits();
    replan();
    updateButtons();
}

void PatternScreen::refreshLimits()
{
    const auto& id = cur().client->identity();
    if (id.axes.size() < 2)
        return;
    const motion::path::Box travel{id.axes[0].travelMin, id.axes[1].travelMin, id.axes[0].travelMax, id.axes[1].travelMax};
    motion::path::Box soft = travel;
    const auto& lim = cur().client->softLimits();
    if (lim.size() >= 2)
        soft = {lim[0].min, lim[1].min, lim[0].max, lim[1].max};
    m_preview->setLimits(travel, soft);
    replan();
}

void PatternScreen::replan()
{
    const motion::plans::Pattern p = m_form->pattern();
    m_path = motion::plans::plan(p);
    const bool fitNow = m_preview->path().empty() && !m_path.empty();
    m_preview->setPath(m_path);
    if (fitNow)
        m_preview->fit();
    if (m_path.empty()) {
        m_estimate->setText(tr("The pattern has problems (see above)."));
        updateButtons();
        return;
    }
    const double len = motion::path::pathLengthMm(m_path);
    // Before a run the contour-error plot spans the path on screen, as the run's will (it
    // showed 0 … 5 mm for a 31 mm circle); a run's trace stays until the next run.
    if (m_contour->samples() == 0) {
        m_contour->setPathLength(len);
        m_contour->refresh();
    }
    QString text = tr("%1 segments, %2 mm; estimated %3 at %4 mm/s")
                       .arg(m_path.size())
                       .arg(len, 0, 'f', 2)
                       .arg(duration(cur().runner->estimatedS(m_path)))
                       .arg(p.feedMmS);
    const auto& lim = cur().client->softLimits();
    if (lim.size() >= 2) {
        if (auto v = motion::plans::outsideLimits(m_path, {lim[0].min, lim[1].min, lim[0].max, lim[1].max}))
            text += QStringLiteral("<br><span style='color:#b71c1c'>%1</span>")
                        .arg(tr("Leaves the soft limits: %1").arg(ui::words::text(v->message)));
    }
    m_estimate->setText(text);
    updateButtons();
}

void PatternScreen::updateButtons()
{
    PatternRunner* r = cur().runner;
    const bool mine = m_runOn == m_current;
    const auto st = r->state();
    const bool busy = r->busy();
    // Disabled with its reason when the instrument cannot run paths at all (not connected,
    // or a device without a path queue).
    const motion::msg::Message why = cur().client->whyNot(dev::Capability::PathQueue);
    const dev::PathClient* paths = cur().client->paths();
    const bool canRun = why.empty() && paths && paths->available();
    m_run->setEnabled(!busy && !m_path.empty() && canRun && !cur().client->status().estop);
    m_run->setToolTip(why.empty() ? tr("Move to the pattern's start, then run it (F5)") : ui::words::text(why));
    m_pause->setEnabled(mine && (st == PatternRunner::State::Running || st == PatternRunner::State::Paused
                                 || st == PatternRunner::State::Interrupted || st == PatternRunner::State::Approaching));
    const QString pauseText = mine && (st == PatternRunner::State::Paused || st == PatternRunner::State::Interrupted)
                                  ? tr("Resume")  // the word the run's messages use ("reconnect, then press Resume")
                                  : tr("Pause");
    if (m_pause->text() != pauseText)
        m_pause->setText(pauseText);
    m_abort->setEnabled(mine && (busy || st == PatternRunner::State::Interrupted));
    m_export->setEnabled(m_runOn >= 0 && !m_instruments[m_runOn].runner->samples().empty());
    m_instrumentBox->setEnabled(!busy);
    // The pattern on screen is the one that runs: no other is loaded over it.
    const bool anyBusy = std::any_of(m_instruments.begin(), m_instruments.end(), [](const PatternInstrument& i) { return i.runner->busy(); });
    m_load->setEnabled(!anyBusy);
    m_load->setToolTip(anyBusy ? tr("A pattern is running: another can be loaded once it has ended.") : QString());
}

bool PatternScreen::run()
{
    PatternRunner* r = cur().runner;
    if (r->busy() || m_path.empty())
        return false;
    dev::jobs::PatternRunner::Options o;
    o.zMm = m_form->pattern().zMm;
    QStringList problems;
    for (const motion::msg::Message& m : r->preflight(m_path, o))
        problems << ui::words::text(m);
    if (!problems.isEmpty()) {
        m_status->setText(problems.join(QLatin1Char('\n')));
        emit problem(QStringLiteral("%1: %2").arg(cur().name, problems.join(QLatin1Char(' '))));
        return false;
    }
    const auto& id = cur().client->identity();
    const double travel = std::max(id.axes[0].travelMax - id.axes[0].travelMin, id.axes[1].travelMax - id.axes[1].travelMin);
    const double far = r->approachDistanceMm(m_path);
    if (far > kFarMoveShare * travel) {
        const auto start = m_path.front().start;
        const Confirm& ask = m_confirmLongMove ? m_confirmLongMove : m_confirm;
        if (ask && !ask(tr("Move %1 %2 mm to the pattern's start (%3, %4) and run %5 segments (%6 mm)?")
                         .arg(cur().name)
                         .arg(far, 0, 'f', 1)
                         .arg(start.x, 0, 'f', 3)
                         .arg(start.y, 0, 'f', 3)
                         .arg(m_path.size())
                         .arg(motion::path::pathLengthMm(m_path), 0, 'f', 1)))
            return false;
    }
    m_runOn = m_current;
    m_preview->clearRun();
    m_contour->clear();
    m_contour->setPathLength(motion::path::pathLengthMm(m_path));
    m_summary->clear();
    m_lastSampleS = -1;
    wantTelemetry(true);
    m_redraw.start();
    if (!r->start(m_path, o)) {
        wantTelemetry(false);
        m_redraw.stop();
        return false;
    }
    updateButtons();
    return true;
}

void PatternScreen::pauseOrResume()
{
    if (m_runOn < 0)
        return;
    PatternRunner* r = m_instruments[m_runOn].runner;
    if (r->state() == PatternRunner::State::Paused || r->state() == PatternRunner::State::Interrupted) {
        wantTelemetry(true);
        m_redraw.start();
        r->resume();
    } else {
        r->pause();
    }
}

void PatternScreen::abort()
{
    if (m_runOn >= 0)
        m_instruments[m_runOn].runner->abort();
}

void PatternScreen::onRunnerState(PatternRunner::State s)
{
    QString text = ui::words::term(PatternRunner::stateTerm(s));
    if (s == PatternRunner::State::Approaching)
        text = tr("Moving to the start…");
    if (s != PatternRunner::State::Interrupted && s != PatternRunner::State::Failed)
        m_status->setText(text.left(1).toUpper() + text.mid(1));
    updateButtons();
}

void PatternScreen::onProgress(std::size_t done, std::size_t total)
{
    m_progress->setMaximum(static_cast<int>(total));
    m_progress->setValue(static_cast<int>(done));
    showRunning();
}

void PatternScreen::showRunning()
{
    if (m_runOn < 0)
        return;
    const PatternRunner* r = m_instruments[m_runOn].runner;
    // Where the machine is (its measured position along the path), not the last segment the
    // device reported finished: that lags a whole segment behind.
    if (r->state() == PatternRunner::State::Running)
        m_status->setText(tr("Running: segment %1 of %2, %3 mm done, about %4 left")
                              .arg(r->currentSegment() + 1)
                              .arg(r->totalSegments())
                              .arg(r->pathDoneMm(), 0, 'f', 1)
                              .arg(duration(r->remainingS())));
}

void PatternScreen::wantTelemetry(bool want)
{
    if (!m_hub)
        return;
    if (!want || m_runOn < 0) {
        m_hub->setWanted(QStringLiteral("patterns"), {}, 0);
        return;
    }
    const int i = m_instruments[m_runOn].hubIndex;
    QVector<dev::tele::ChannelKey> keys;
    for (std::uint8_t axis : {std::uint8_t(0), std::uint8_t(1)})
        for (auto kind : {dev::proto::ChannelKind::Commanded, dev::proto::ChannelKind::Measured})
            keys << dev::tele::ChannelKey{i, {axis, kind}};
    m_hub->setWanted(QStringLiteral("patterns"), keys, kTelemetryHz);
}

void PatternScreen::onData(int hubIndex)
{
    if (m_runOn < 0 || !m_hub || hubIndex != m_instruments[m_runOn].hubIndex)
        return;
    auto store = [&](std::uint8_t axis, dev::proto::ChannelKind k) { return m_hub->store({hubIndex, {axis, k}}); };
    const dev::tele::ChannelStore* xm = store(0, dev::proto::ChannelKind::Measured);
    const dev::tele::ChannelStore* ym = store(1, dev::proto::ChannelKind::Measured);
    const dev::tele::ChannelStore* xc = store(0, dev::proto::ChannelKind::Commanded);
    const dev::tele::ChannelStore* yc = store(1, dev::proto::ChannelKind::Commanded);
    if (!xm || !ym || !xc || !yc || xm->empty())
        return;
    PatternRunner* r = m_instruments[m_runOn].runner;
    // Every sample newer than the last one handed on; the four channels share their sample times.
    for (std::size_t k = m_lastSampleS < 0 ? 0 : xm->lowerBound(m_lastSampleS + 1e-7); k < xm->size(); ++k) {
        const dev::tele::Sample x = xm->at(k);
        const auto y = ym->nearest(x.tS), cx = xc->nearest(x.tS), cy = yc->nearest(x.tS);
        if (!y || !cx || !cy)
            continue;
        r->addSample(x.tS, {cx->value, cy->value}, {x.value, y->value});
        m_lastSampleS = x.tS;
    }
}

bool PatternScreen::exportRun(const QString& path, QString* error)
{
    if (m_runOn < 0 || m_instruments[m_runOn].runner->samples().empty()) {
        if (error)
            *error = tr("There is no run to export yet.");
        return false;
    }
    motion::msg::Message why;
    if (dev::files::savePatternRunCsv(path, m_instruments[m_runOn].runner->samples(), &why))
        return true;
    if (error)
        *error = ui::words::text(why);
    return false;
}

bool PatternScreen::savePattern(const QString& path, QString* error)
{
    if (const QString typed = m_form->entryProblem(); !typed.isEmpty()) {
        if (error)
            *error = typed;  // a file never gets a number nobody typed
        return false;
    }
    motion::msg::Message why;
    if (dev::files::savePatternFile(path, m_form->pattern(), &why))
        return true;
    if (error)
        *error = ui::words::text(why);
    return false;
}

bool PatternScreen::loadPattern(const QString& path, QString* error)
{
    if (runner() && runner()->busy()) {
        // The pattern on screen is the one that runs.
        if (error)
            *error = tr("A pattern is running: another can be loaded once it has ended.");
        return false;
    }
    motion::plans::Pattern p;
    dev::files::json::Problems problems;
    if (!dev::files::loadPatternFile(path, &p, &problems)) {
        if (error)
            *error = ui::words::fileProblems(problems, QFileInfo(path).fileName()).join(QLatin1Char('\n'));
        return false;
    }
    setPattern(p);
    return true;
}

void PatternScreen::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    QTimer::singleShot(0, m_preview, &PatternPreview::fit);
}

void PatternScreen::hideEvent(QHideEvent* event)
{
    // A running pattern keeps its telemetry (its contour must be judged); an idle screen lets go.
    if (m_runOn < 0 || !m_instruments[m_runOn].runner->busy())
        wantTelemetry(false);
    QWidget::hideEvent(event);
}

} // namespace ui
