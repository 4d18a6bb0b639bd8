#include "widgets/tuning/tuning_screen.h"

#include "device/files/tuning_file.h"
#include "device/jobs/tuning/instrument_target.h"
#include "device/jobs/tuning/model_target.h"
#include "device/telemetry/telemetry_hub.h"
#include "widgets/tuning/gains_panel.h"
#include "widgets/tuning/step_test_panel.h"
#include "widgets/tuning/zn_panel.h"

#include "widgets/wording/wording.h"

#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QStandardPaths>
#include <QTabWidget>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

using namespace motion::control;

namespace {
const char* kLiveConsumer = "tuning";
constexpr double kLiveWindowS = 0.5;
/// A set this many times an active term (or under its inverse) is no adjustment but a new loop: asked first.
constexpr double kFarFactor = 3;

/// "Kp 0.25 → 5 (20×)" for every active term of `now` that `next` takes more than kFarFactor away.
QStringList farTerms(const DiscreteGains& next, const DiscreteGains& now, double periodS)
{
    const ContinuousGains a = toContinuous(now, periodS), b = toContinuous(next, periodS);
    const double was[3] = {a.kp, a.kiPerS, a.kdS}, will[3] = {b.kp, b.kiPerS, b.kdS};
    const QString names[3] = {TuningScreen::tr("Kp"), TuningScreen::tr("Ki"), TuningScreen::tr("Kd")};
    QStringList out;
    for (int i = 0; i < 3; ++i) {
        if (!(was[i] > 0))
            continue;  // an inactive term has no scale to be far from
        const double f = will[i] / was[i];
        if (f > kFarFactor || f < 1 / kFarFactor)
            out << TuningScreen::tr("%1 %2 → %3 (%4×)")
                       .arg(names[i], QLocale().toString(was[i], 'g', 4), QLocale().toString(will[i], 'g', 4), QLocale().toString(f, 'g', 3));
    }
    return out;
}
} // namespace

TuningScreen::TuningScreen(dev::tele::TelemetryHub* hub, QWidget* parent) : QWidget(parent), m_hub(hub)
{
    auto* v = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    top->addWidget(new QLabel(tr("Tune"), this));
    m_target = new QComboBox(this);
    m_target->setObjectName(QStringLiteral("tuningTarget"));
    m_target->setMinimumWidth(160);
    top->addWidget(m_target);
    m_target->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    m_plant = new QLineEdit(QStringLiteral("fopdt:K=2,tau=0.5,L=0.1"), this);
    m_plant->setObjectName(QStringLiteral("plantSpec"));
    m_plant->setToolTip(tr("fopdt:K=..,tau=..,L=.. or lag:K=..,tau=..,n=.. (times in s; Ts=.. sets the loop period, 10 kHz unless given)"));
    m_plant->setMinimumWidth(280);
    top->addWidget(m_plant);
    m_plantError = new QLabel(this);
    m_plantError->setStyleSheet(QStringLiteral("color: #b00020;"));
    top->addWidget(m_plantError);
    m_unavailable = new QLabel(this);
    m_unavailable->setObjectName(QStringLiteral("tuningUnavailable"));
    m_unavailable->setStyleSheet(QStringLiteral("color: #555;"));
    m_unavailable->hide();
    top->addStretch(1);
    m_live = new QLabel(this);
    m_live->setStyleSheet(QStringLiteral("color: #555;"));
    top->addWidget(m_live);
    m_open = new QPushButton(tr("Open results…"), this);
    m_save = new QPushButton(tr("Save results…"), this);
    m_save->setObjectName(QStringLiteral("saveResults"));
    top->addWidget(m_open);
    top->addWidget(m_save);
    v->addLayout(top);
    v->addWidget(m_unavailable);

    auto* split = new QSplitter(Qt::Horizontal, this);
    m_gains = new GainsPanel(split);
    m_tabs = new QTabWidget(split);
    m_steps = new StepTestPanel(m_tabs);
    m_zn = new ZnPanel(m_tabs);
    m_tabs->addTab(m_steps, tr("Step test"));
    m_tabs->addTab(m_zn, tr("Ziegler–Nichols assistant"));
    split->addWidget(m_gains);
    split->addWidget(m_tabs);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 3);
    v->addWidget(split, 1);

    auto* bottom = new QHBoxLayout;
    m_progress = new QProgressBar(this);
    m_progress->setRange(0, 1000);
    m_progress->setMaximumWidth(260);
    m_status = new QLabel(tr("idle"), this);
    m_status->setObjectName(QStringLiteral("tuningStatus"));
    m_status->setWordWrap(true);
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setObjectName(QStringLiteral("tuningAbort"));
    m_resume = new QPushButton(tr("Resume"), this);
    m_resume->setToolTip(tr("Run the interrupted experiment again once the link is back"));
    bottom->addWidget(m_progress);
    bottom->addWidget(m_status, 1);
    bottom->addWidget(m_resume);
    bottom->addWidget(m_abort);
    v->addLayout(bottom);

    m_runner = new dev::TuningRunner(this);
    connect(m_runner, &dev::TuningRunner::stateChanged, this, &TuningScreen::onRunnerState);
    connect(m_runner, &dev::TuningRunner::progress, this, [this](double f, const motion::msg::Message& text) {
        m_progress->setValue(static_cast<int>(std::lround(1000 * f)));
        say(ui::words::text(text));
    });
    connect(m_runner, &dev::TuningRunner::message, this, [this](const motion::msg::Message& m) { say(ui::words::text(m), true); });
    connect(m_runner, &dev::TuningRunner::finished, this, [this](bool ok, const motion::msg::Message& m) { onFinished(ok, ui::words::text(m)); });
    connect(m_runner, &dev::TuningRunner::recordArrived, this, [this](const Record& r, const motion::msg::Message& label, int kind) {
        // The trials and the relay's own cycle; forced runs are points on a frequency
        // response, not something to watch.
        if (kind < 2)
            m_zn->showRun(r, ui::words::text(label));
    });
    connect(m_runner, &dev::TuningRunner::stepTestDone, this, [this](const Record& r, const StepVerdict& m, const motion::msg::Message& label) {
        m_steps->addResult(r, m, QStringLiteral("%1 (%2)").arg(ui::words::text(label), describeGains(m_runGains, m_gains->periodS())));
    });
    connect(m_runner, &dev::TuningRunner::ultimateFound, this, [this](double, double) {
        m_lastResult = m_runner->result();
        m_haveResult = true;
        m_zn->showResult(m_lastResult);
        const auto& o = m_zn->options();
        if (!o.verifyRule.empty())
            m_runGains = dev::TuningRunner::ruleGains(o.verifyRule, m_lastResult.ku, m_lastResult.tuS, m_lastResult.controlPeriodS);
        refreshReady();
    });

    connect(m_target, &QComboBox::currentIndexChanged, this, [this] {
        m_targetPicked = true;
        onTargetChosen();
    });
    connect(m_plant, &QLineEdit::editingFinished, this, [this] {
        if (const Choice* c = choice(); c && c->instrument < 0)
            setModelPlant(m_plant->text());
    });
    connect(m_gains, &GainsPanel::applyRequested, this, [this](const DiscreteGains& g, const QString& src) { applyGains(g, false, src); });
    connect(m_gains, &GainsPanel::revertRequested, this, [this](const DiscreteGains& g, const QString& src) { applyGains(g, false, src); });
    connect(m_gains, &GainsPanel::saveRequested, this, [this](const DiscreteGains& g) { applyGains(g, true, tr("saved as power-up gains")); });
    connect(m_gains, &GainsPanel::readBackRequested, this, &TuningScreen::readGains);
    connect(m_steps, &StepTestPanel::runRequested, this, [this] { runStepTest(); });
    connect(m_zn, &ZnPanel::startRequested, this, [this] { startAssistant(); });
    connect(m_zn, &ZnPanel::abortRequested, this, &TuningScreen::abort);
    connect(m_zn, &ZnPanel::useRule, this, [this](const QString&, const DiscreteGains& g, const QString& source) {
        const Choice* c = choice();
        // A row far from the gains in force gets the question that says how far, in applyGains.
        if (c && c->instrument >= 0 && m_confirm && farTerms(g, m_gains->inForce(), m_gains->periodS()).isEmpty()
            && !m_confirm(tr("Apply these gains to %1?\n%2").arg(c->name, describeGains(g, m_gains->periodS()))))
            return;
        m_gains->setEdited(g);
        applyGains(g, false, source);
    });
    connect(m_abort, &QPushButton::clicked, this, &TuningScreen::abort);
    connect(m_resume, &QPushButton::clicked, this, &TuningScreen::resume);
    connect(m_save, &QPushButton::clicked, this, [this] { saveResults(); });
    connect(m_open, &QPushButton::clicked, this, [this] { loadResults(); });

    m_liveTimer.setInterval(100);
    connect(&m_liveTimer, &QTimer::timeout, this, &TuningScreen::drawLive);
    if (m_hub)
        connect(m_hub, &dev::tele::TelemetryHub::subscriptionChanged, this, [this](int instrument, int rateHz, const motion::msg::Message& m) {
            const QString note = ui::words::text(m);
            const Choice* c = choice();
            if (!c || c->instrument < 0 || m_instruments[c->instrument].index != instrument || !m_liveTimer.isActive())
                return;
            m_live->setText(tr("live at %1 Hz%2; the analysis reads the device's capture at the loop rate")
                                .arg(rateHz)
                                .arg(note.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(note)));
        });
    m_plantSpec = *parsePlant(m_plant->text().toStdString());
    rebuildTargets();
    onRunnerState(dev::TuningRunner::State::Idle);
}

TuningScreen::~TuningScreen()
{
    if (m_hub)
        m_hub->setWanted(QLatin1String(kLiveConsumer), {}, 0);
}

bool TuningScreen::setModelPlant(const QString& spec, QString* error)
{
    const auto p = parsePlant(spec.toStdString());
    if (!p) {
        m_plantError->setText(ui::words::text(p.error()));
        if (error)
            *error = ui::words::text(p.error());
        return false;
    }
    m_plantError->clear();
    m_plant->setText(QString::fromStdString(p->text()));
    m_plantSpec = *p;
    if (const Choice* c = choice(); c && c->instrument < 0)
        onTargetChosen();
    return true;
}

void TuningScreen::onTargetChosen()
{
    if (m_runner->busy())
        return;
    m_targetObj.reset();
    const Choice* c = choice();
    m_plant->setVisible(c && c->instrument < 0);
    m_plantError->setVisible(c && c->instrument < 0);
    m_zn->clearResult();
    m_haveResult = false;
    if (!c) {
        m_gains->clearTarget(tr("no target"));
        refreshReady();
        return;
    }
    if (c->instrument < 0) {
        m_targetObj = std::make_unique<dev::ModelTarget>(m_plantSpec);
        m_steps->setUnit(QString());
        m_zn->setUnit(QString());
        m_gains->setTarget(QString::fromStdString(m_plantSpec.text()), m_plantSpec.periodS, false, m_modelGains, tr("model defaults"));
        const motion::msg::Message why = whyNoUltimateGain(m_plantSpec);
        if (!why.empty())
            m_zn->clearResult(tr("This plant cannot be tuned by Ziegler–Nichols: %1.").arg(ui::words::text(why)));
    } else {
        Instrument* in = instrumentOf(*c);
        auto target = std::make_unique<dev::InstrumentTarget>(in->tuning, c->axis, in->name);
        connect(target.get(), &dev::TuningTarget::runProgress, this, [this](double, const motion::msg::Message& what) { say(ui::words::text(what)); });
        connect(target.get(), &dev::TuningTarget::testRunning, this, [this](bool running) {
            m_deviceTestRunning = running;
            updateLiveWant();
        });
        m_targetObj = std::move(target);
        m_steps->setUnit(QStringLiteral("mm"));
        m_zn->setUnit(QStringLiteral("mm"));
        m_gains->clearTarget(tr("reading the gains of %1…").arg(c->name));
        readGains();
    }
    refreshReady();
}

void TuningScreen::readGains()
{
    const Choice* c = choice();
    Instrument* in = c ? instrumentOf(*c) : nullptr;
    if (!in || !in->tuning)
        return;
    const int instrument = c->instrument;
    const int axis = c->axis;
    QPointer<TuningScreen> self(this);
    in->tuning->getGains(axis, [self, instrument, axis](const std::optional<dev::RequestError>& e, const dev::AxisGains& g) {
        if (!self)
            return;
        const Choice* now = self->choice();
        if (!now || now->instrument != instrument || now->axis != axis)
            return;  // another target was chosen meanwhile (a new name for the same one is no other)
        const QString name = now->name;
        if (e) {
            self->m_gains->clearTarget(ui::words::text(e->message));
            return;
        }
        if (auto* t = dynamic_cast<dev::InstrumentTarget*>(self->m_targetObj.get()))
            t->setControlPeriodS(g.controlPeriodS);
        if (self->m_gains->history().isEmpty() || self->m_gains->periodS() != g.controlPeriodS)
            self->m_gains->setTarget(name, g.controlPeriodS, true, g.gains, tr("read from the device"));
        else if (g.gains != self->m_gains->inForce())
            self->m_gains->setInForce(g.gains, tr("read from the device"));
        self->refreshReady();
    });
}

void TuningScreen::applyGains(const DiscreteGains& g, bool save, const QString& source)
{
    const Choice* c = choice();
    if (!c)
        return;
    if (c->instrument < 0) {
        m_modelGains = g;
        m_gains->setInForce(g, source);
        return;
    }
    Instrument* in = instrumentOf(*c);
    if (!in || !in->tuning)
        return;
    const QStringList far = farTerms(g, m_gains->inForce(), m_gains->periodS());
    if (!far.isEmpty() && m_confirm
        && !m_confirm(tr("These gains are far from the ones %1 runs now:\n%2\nA loop this different may oscillate or run away. Apply them?")
                          .arg(c->name, far.join(QLatin1Char('\n')))))
        return;
    QPointer<TuningScreen> self(this);
    const QString name = c->name;
    const int instrument = c->instrument, axis = c->axis;
    ++m_ownGainChanges;
    in->tuning->setGains(c->axis, g, save, [self, g, source, name, instrument, axis](const std::optional<dev::RequestError>& e) {
        if (!self)
            return;
        if (e) {
            --self->m_ownGainChanges;  // refused: no announcement will come
            // The device's own reason ("… the previous ones stay"); the editors keep the rejected set to fix.
            self->say(ui::words::text(e->message), true);
            return;
        }
        if (const Choice* now = self->choice(); now && now->instrument == instrument && now->axis == axis)
            self->m_gains->setInForce(g, source);
        self->say(tr("%1: gains applied (%2)").arg(name, source));
    });
}

bool TuningScreen::runStepTest()
{
    if (!m_targetObj || m_runner->busy())
        return false;
    StepSpec s;
    s.step = m_steps->step();
    s.gains = m_gains->inForce();
    const auto env = m_zn->options().envelope;
    const double a = std::abs(s.step);
    s.envelope = {std::max(env.maxExcursion, 3 * a), std::max(env.maxFollowingError, 2 * a), env.maxDurationS};
    if (m_targetObj->unit() == QLatin1String("mm")) {
        // Ends once settled (two grating counts, the loop's deadband being one), or
        // after a second of a response that keeps hunting inside the band's reach.
        s.settleBand = std::max(2 * m_targetObj->noiseFloor(), 0.02 * a);
        s.settleHoldS = 0.05;
        s.runS = std::min(1.0, 0.9 * env.maxDurationS);
    } else {
        // A model has no noise: run long enough to see it settle, measured in its own time.
        s.runS = std::min(env.maxDurationS * 0.99, m_haveResult ? 30 * m_lastResult.tuS : 20.0);
    }
    m_runGains = s.gains;
    return m_runner->startStepTest(m_targetObj.get(), s, motion::msg::make("tuning.label.step", {motion::msg::integer("step", m_steps->runs() + 1, motion::msg::Unit::None)}));
}

bool TuningScreen::startAssistant()
{
    if (!m_targetObj || m_runner->busy())
        return false;
    m_zn->clearResult(tr("running…"));
    m_haveResult = false;
    auto o = m_zn->options();
    if (m_targetObj->unit() != QLatin1String("mm"))
        o.trialS = o.envelope.maxDurationS;
    return m_runner->startZn(m_targetObj.get(), o);
}

void TuningScreen::abort() { m_runner->abort(); }

bool TuningScreen::resume()
{
    if (!m_runner->resume()) {
        say(tr("cannot resume yet: the link must be back (connect the instrument) and the same target chosen"), true);
        return false;
    }
    return true;
}

void TuningScreen::onRunnerState(dev::TuningRunner::State s)
{
    const bool busy = s == dev::TuningRunner::State::Running;
    m_gains->setBusy(busy);
    m_steps->setBusy(busy);
    m_zn->setBusy(busy);
    m_target->setEnabled(!busy);
    m_plant->setEnabled(!busy);
    m_abort->setEnabled(busy || s == dev::TuningRunner::State::Interrupted);
    m_resume->setEnabled(s == dev::TuningRunner::State::Interrupted);
    if (busy)
        m_progress->setValue(0);
    updateLiveWant();
    refreshReady();
}

void TuningScreen::onFinished(bool ok, const QString& text)
{
    say(text, !ok);
    // A test that diverged under the gains in force leaves the device under the set
    // before them (it announces the change while the run is busy): show what is in force.
    if (const Choice* c = choice(); c && c->instrument >= 0)
        readGains();
    if (ok && m_haveResult)
        m_lastResult = m_runner->result();  // with its verification
    if (m_haveResult)
        m_zn->showResult(m_lastResult);
    rebuildTargets();
    refreshReady();
}

void TuningScreen::refreshReady()
{
    const bool ready = m_targetObj && m_targetObj->ready();
    m_steps->setReady(ready);
    m_zn->setReady(ready && (!dynamic_cast<dev::ModelTarget*>(m_targetObj.get()) || whyNoUltimateGain(m_plantSpec).empty()));
    m_save->setEnabled(m_haveResult && !m_runner->busy());
    m_open->setEnabled(!m_runner->busy());
    m_resume->setEnabled(m_runner->state() == dev::TuningRunner::State::Interrupted && m_targetObj && m_targetObj->ready());
}

void TuningScreen::say(const QString& text, bool isProblem)
{
    m_lastStatus = text;
    m_status->setText(text);
    m_status->setStyleSheet(isProblem ? QStringLiteral("color: #b00020;") : QString());
    if (isProblem)
        emit problem(text);
}

QString TuningScreen::statusText() const { return m_lastStatus; }

void TuningScreen::updateLiveWant()
{
    const Choice* c = choice();
    const bool live = m_hub && isVisible() && m_runner->busy() && m_deviceTestRunning && c && c->instrument >= 0;
    if (!live) {
        if (m_hub)
            m_hub->setWanted(QLatin1String(kLiveConsumer), {}, 0);
        m_liveTimer.stop();
        m_live->clear();
        return;
    }
    const int index = m_instruments[c->instrument].index;
    const auto axis = static_cast<std::uint8_t>(c->axis);
    m_hub->setWanted(QLatin1String(kLiveConsumer),
                     {dev::tele::ChannelKey{index, {axis, dev::proto::ChannelKind::Commanded}}, dev::tele::ChannelKey{index, {axis, dev::proto::ChannelKind::Measured}},
                      dev::tele::ChannelKey{index, {axis, dev::proto::ChannelKind::ControllerU}}},
                     1000);
    m_liveStartS = m_hub->latestTimeS(index);
    m_liveTimer.start();
}

void TuningScreen::drawLive()
{
    const Choice* c = choice();
    if (!m_hub || !c || c->instrument < 0 || m_tabs->currentWidget() != m_zn)
        return;
    const int index = m_instruments[c->instrument].index;
    const auto axis = static_cast<std::uint8_t>(c->axis);
    const dev::tele::ChannelStore* y = m_hub->store(dev::tele::ChannelKey{index, {axis, dev::proto::ChannelKind::Measured}});
    const dev::tele::ChannelStore* u = m_hub->store(dev::tele::ChannelKey{index, {axis, dev::proto::ChannelKind::ControllerU}});
    if (!y || !u || y->empty() || u->empty())
        return;
    const double newest = y->lastTime();
    const double from = std::max(newest - kLiveWindowS, std::isnan(m_liveStartS) ? -1e300 : m_liveStartS);
    QVector<double> t, ym, um;
    const double y0 = y->at(y->lowerBound(from)).value;
    const double u0 = u->at(u->lowerBound(from)).value;
    for (std::size_t i = y->lowerBound(from); i < y->size(); ++i) {
        const auto s = y->at(i);
        t << s.tS - from;
        ym << s.value - y0;  // mm, as the store holds it (the plot shows µm)
        const auto n = u->nearest(s.tS);
        um << (n ? (n->value - u0) / 1000.0 : 0.0);  // the store holds µm
    }
    m_zn->showLive(t, ym, um, tr("live: %1").arg(c->name));
}

bool TuningScreen::saveResults(const QString& given)
{
    if (!m_haveResult)
        return false;
    QString path = given;
    if (path.isEmpty() && m_chooser)
        path = m_chooser(tr("Save tuning results"), tr("Tuning results (*.tuning.json)"), true);
    if (path.isEmpty())
        return false;
    motion::msg::Message error;
    if (!dev::files::saveTuningFile(path, m_lastResult, &error)) {
        say(ui::words::text(error), true);
        return false;
    }
    say(tr("tuning results saved to %1").arg(QDir::toNativeSeparators(path)));
    return true;
}

bool TuningScreen::loadResults(const QString& given)
{
    if (m_runner->busy()) {
        // The results on screen are the ones the running job fills in: none is opened over them.
        say(tr("A tuning run is under way: results can be opened once it has ended."), true);
        return false;
    }
    QString path = given;
    if (path.isEmpty() && m_chooser)
        path = m_chooser(tr("Open tuning results"), tr("Tuning results (*.tuning.json)"), false);
    if (path.isEmpty())
        return false;
    dev::files::json::Problems problems;
    const auto r = dev::files::loadTuningFile(path, &problems);
    if (!r) {
        say(ui::words::fileProblems(problems, QFileInfo(path).fileName()).join(QLatin1Char('\n')), true);
        return false;
    }
    m_lastResult = *r;
    m_haveResult = true;
    m_zn->showResult(*r);
    m_tabs->setCurrentWidget(m_zn);
    const QString on = QString::fromStdString(r->target);
    say(on == currentTarget() ? tr("results of %1 loaded").arg(on)
                              : tr("results of %1 loaded; the rules' gains are for its loop period (%2 ms), applied to %3 as they are")
                                    .arg(on)
                                    .arg(r->controlPeriodS * 1000)
                                    .arg(currentTarget()));
    refreshReady();
    return true;
}

QVariantMap TuningScreen::saveState() const
{
    const auto o = m_zn->options();
    QVariantMap m;
    m[QStringLiteral("target")] = currentTarget();
    m[QStringLiteral("plant")] = m_plant->text();
    m[QStringLiteral("method")] = o.method == TuningMethod::Relay ? QStringLiteral("relay") : QStringLiteral("ultimate-gain");
    m[QStringLiteral("tab")] = m_tabs->currentIndex();
    return m;
}

void TuningScreen::restoreState(const QVariantMap& m)
{
    if (m.contains(QStringLiteral("plant")))
        setModelPlant(m.value(QStringLiteral("plant")).toString());
    auto o = m_zn->options();
    o.method = m.value(QStringLiteral("method")).toString() == QLatin1String("relay") ? TuningMethod::Relay : TuningMethod::UltimateGain;
    m_zn->setOptions(o);
    m_tabs->setCurrentIndex(m.value(QStringLiteral("tab"), 0).toInt());
    // The instrument saved may not have answered yet: its axis is taken when it does.
    m_savedTarget = m.value(QStringLiteral("target")).toString();
    selectTarget(m_savedTarget);
}

void TuningScreen::showEvent(QShowEvent* event)
{
    QWidget::showEvent(event);
    updateLiveWant();
}

void TuningScreen::hideEvent(QHideEvent* event)
{
    QWidget::hideEvent(event);
    updateLiveWant();
}

} // namespace ui
