#include "widgets/tuning/zn_panel.h"

#include "widgets/common/number_field.h"
#include "widgets/input_policy.h"
#include "widgets/wording/wording.h"
#include "motion/control/tuning/tuning_rules.h"
#include "widgets/tuning/gains_panel.h"
#include "widgets/tuning/response_plot.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSplitter>
#include <QStackedWidget>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

using motion::control::TuningMethod;

namespace {
// The rules' names live in motion/ (no Qt); listed here so lupdate finds them for tr().
[[maybe_unused]] const char* const kRuleNames[] = {
    QT_TRANSLATE_NOOP("ui::ZnPanel", "Ziegler–Nichols P"),        QT_TRANSLATE_NOOP("ui::ZnPanel", "Ziegler–Nichols PI"),
    QT_TRANSLATE_NOOP("ui::ZnPanel", "Ziegler–Nichols PID"),      QT_TRANSLATE_NOOP("ui::ZnPanel", "Tyreus–Luyben PI"),
    QT_TRANSLATE_NOOP("ui::ZnPanel", "Tyreus–Luyben PID"),        QT_TRANSLATE_NOOP("ui::ZnPanel", "Pessen integral rule PID"),
    QT_TRANSLATE_NOOP("ui::ZnPanel", "Z-N \"some overshoot\" PID"), QT_TRANSLATE_NOOP("ui::ZnPanel", "Z-N \"no overshoot\" PID"),
};
// And where each comes from (motion::control::tuningRules(), in the same order).
[[maybe_unused]] const char* const kRuleSources[] = {
    QT_TRANSLATE_NOOP("ui::ZnPanel", "seed 002 Table 1 (Ziegler & Nichols 1942)"),
    QT_TRANSLATE_NOOP("ui::ZnPanel", "Tyreus & Luyben 1992, Ind. Eng. Chem. Res. 31:2625"),
    QT_TRANSLATE_NOOP("ui::ZnPanel", "Pessen 1994, J. Dyn. Syst. Meas. Control 116:553"),
    QT_TRANSLATE_NOOP("ui::ZnPanel", "Z-N variant as tabulated by Microstar Laboratories"),
};
QString ruleNumber(double v) { return QString::number(v, 'g', 4); }
QString period(double s) { return s < 1 ? ZnPanel::tr("%1 ms").arg(ruleNumber(s * 1000)) : ZnPanel::tr("%1 s").arg(ruleNumber(s)); }
} // namespace

// Typed settings are kept as typed: "-5" or "1e9" is shown as invalid with its reason and
// holds Start, never turned into 5 or 19 (a spin box's validator dropped what it could not take).
NumberField* ZnPanel::spin(const QString& objectName, double min, double max, int decimals, double value)
{
    auto* s = new NumberField(this);
    s->setObjectName(objectName);
    s->setRange(min, max);
    s->setDisplay('g', decimals + 3);
    s->setValue(value);
    s->setMinimumHeight(s->sizeHint().height());  // a form short of room squeezes an entry thin
    return s;
}

ZnPanel::ZnPanel(QWidget* parent) : QWidget(parent)
{
    // Settings and the oscillation side by side; the result and the rules table
    // below them at full width (a rule's source needs the room).
    auto* outer = new QVBoxLayout(this);
    auto* split = new QSplitter(Qt::Vertical, this);
    outer->addWidget(split);
    auto* upper = new QWidget(split);
    auto* top = new QHBoxLayout(upper);
    top->setContentsMargins(0, 0, 0, 0);
    auto* left = new QVBoxLayout;
    auto* form = new QFormLayout;
    m_method = new QComboBox(this);
    m_method->setObjectName(QStringLiteral("znMethod"));
    m_method->addItem(tr("Ultimate gain (P only, Kp raised)"));
    m_method->addItem(tr("Relay (Åström–Hägglund)"));
    form->addRow(tr("Method"), m_method);
    m_excursion = spin(QStringLiteral("maxExcursion"), 0.001, 1e6, 3, 50);
    m_following = spin(QStringLiteral("maxFollowingError"), 0.001, 1e6, 3, 50);
    m_duration = spin(QStringLiteral("maxDuration"), 0.01, 600, 2, 2);
    m_duration->setUnit(tr(" s"));
    form->addRow(tr("Max excursion"), m_excursion);
    form->addRow(tr("Max following error"), m_following);
    form->addRow(tr("Max duration"), m_duration);
    left->addLayout(form);

    m_methodPages = new QStackedWidget(this);
    auto* ugPage = new QWidget(m_methodPages);
    auto* ugForm = new QFormLayout(ugPage);
    ugForm->setContentsMargins(0, 0, 0, 0);
    m_trialStep = spin(QStringLiteral("trialStep"), 0.001, 1e6, 3, 20);
    m_startKp = spin(QStringLiteral("startKp"), 0.0001, 1e6, 4, 0.25);
    m_kpMax = spin(QStringLiteral("kpMax"), 0.001, 1e6, 3, 100);
    ugForm->addRow(tr("Trial step"), m_trialStep);
    ugForm->addRow(tr("First Kp"), m_startKp);
    ugForm->addRow(tr("Largest Kp"), m_kpMax);
    auto* relayPage = new QWidget(m_methodPages);
    auto* relayForm = new QFormLayout(relayPage);
    relayForm->setContentsMargins(0, 0, 0, 0);
    m_amplitude = spin(QStringLiteral("relayAmplitude"), 0.001, 1e6, 3, 20);
    m_hysteresis = spin(QStringLiteral("hysteresis"), 0, 1e6, 3, 1);
    m_refine = new QCheckBox(tr("Refine to the phase crossover"), relayPage);
    m_refine->setChecked(true);
    m_refine->setToolTip(tr("Short forced runs measure the loop at chosen frequencies until two points bracket −180°; "
                            "without it only the classic describing-function estimate is given"));
    relayForm->addRow(tr("Amplitude d"), m_amplitude);
    relayForm->addRow(tr("Hysteresis ε"), m_hysteresis);
    relayForm->addRow(m_refine);
    m_methodPages->addWidget(ugPage);
    m_methodPages->addWidget(relayPage);
    left->addWidget(m_methodPages);

    auto* verifyForm = new QFormLayout;
    m_verify = new QComboBox(this);
    m_verify->setObjectName(QStringLiteral("verifyRule"));
    m_verify->addItem(tr("no verification"), QString());
    for (const auto& r : motion::control::tuningRules())
        m_verify->addItem(ui::words::term(std::string("tuning.rule.") + r.id), QString::fromLatin1(r.id));
    m_verify->setCurrentIndex(m_verify->findData(QStringLiteral("zn-pid")));
    verifyForm->addRow(tr("Verify with"), m_verify);
    left->addLayout(verifyForm);

    auto* buttons = new QHBoxLayout;
    m_start = new QPushButton(tr("Start"), this);
    m_start->setObjectName(QStringLiteral("znStart"));
    m_abort = new QPushButton(tr("Abort"), this);
    m_abort->setObjectName(QStringLiteral("znAbort"));
    buttons->addWidget(m_start);
    buttons->addWidget(m_abort);
    left->addLayout(buttons);
    auto* note = new QLabel(tr("Trials run inside 60 % of the envelope. Trial gains live only inside a test: the gains "
                               "in force change when you press “Use these”."),
                            this);
    note->setWordWrap(true);
    note->setStyleSheet(QStringLiteral("color: #555;"));
    left->addWidget(note);
    left->addStretch(1);
    top->addLayout(left);

    m_plot = new ResponsePlot(ResponsePlot::Mode::Oscillation, upper);
    top->addWidget(m_plot, 1);
    auto* lower = new QWidget(split);
    auto* lv = new QVBoxLayout(lower);
    lv->setContentsMargins(0, 0, 0, 0);
    m_result = new QLabel(lower);
    m_result->setObjectName(QStringLiteral("znResult"));
    m_result->setWordWrap(true);
    m_result->setTextInteractionFlags(Qt::TextSelectableByMouse);
    lv->addWidget(m_result);
    // Where a rule comes from is in its name's tooltip: the table holds what a person applies.
    m_rules = new QTableWidget(0, 8, lower);
    m_rules->setObjectName(QStringLiteral("rulesTable"));
    m_rules->setHorizontalHeaderLabels({tr("Rule"), tr("Kp"), tr("Ki [1/s]"), tr("Kd [s]"), tr("kp"), tr("ki / period"),
                                        tr("kd / period"), QString()});
    m_rules->verticalHeader()->setVisible(false);
    m_rules->verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 10);
    m_rules->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_rules->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_rules->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    lv->addWidget(m_rules, 1);
    split->addWidget(upper);
    split->addWidget(lower);
    // Short of room (a laptop, results shown), the rules table scrolls; the settings keep
    // their height instead of being squeezed thin.
    upper->setMinimumHeight(upper->minimumSizeHint().height());
    split->setChildrenCollapsible(false);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);

    connect(m_method, &QComboBox::currentIndexChanged, m_methodPages, &QStackedWidget::setCurrentIndex);
    connect(m_method, &QComboBox::currentIndexChanged, this, [this] { refresh(); });
    for (auto* f : findChildren<NumberField*>())
        connect(f, &NumberField::entryChanged, this, [this] { refresh(); });
    connect(m_start, &QPushButton::clicked, this, &ZnPanel::startRequested);
    connect(m_abort, &QPushButton::clicked, this, &ZnPanel::abortRequested);
    setUnit(QStringLiteral("mm"));
    clearResult();
}

double ZnPanel::toTarget(double shown) const { return m_unit == QLatin1String("mm") ? shown / 1000.0 : shown; }
double ZnPanel::toShown(double target) const { return m_unit == QLatin1String("mm") ? target * 1000.0 : target; }

void ZnPanel::setUnit(const QString& unit)
{
    const QString suffix = unit == QLatin1String("mm") ? tr(" µm") : QString();
    for (auto* s : {m_excursion, m_following, m_trialStep, m_amplitude, m_hysteresis})
        s->setUnit(suffix);
    if (unit == m_unit)
        return;
    auto o = options();
    m_unit = unit;
    if (unit == QLatin1String("mm")) {
        o.envelope = {0.05, 0.05, 2};
        o.step = 0.02;
        o.relayAmplitude = 0.02;
        o.hysteresis = 0.001;
        o.startKp = 0.25;
        o.kpMax = 100;
    } else {
        o.envelope = {3, 3, 600};
        o.step = 1;
        o.relayAmplitude = 0.2;
        o.hysteresis = 0.002;
        o.startKp = 0.1;
        o.kpMax = 1000;
    }
    setOptions(o);
    m_plot->setUnit(unit);
}

dev::TuningRunner::ZnOptions ZnPanel::options() const
{
    dev::TuningRunner::ZnOptions o;
    o.method = m_method->currentIndex() == 1 ? TuningMethod::Relay : TuningMethod::UltimateGain;
    // Start is held while a shown field is invalid (refresh()); NaN is what no run accepts.
    const auto typed = [](const NumberField* f) { return f->valueOr(std::nan("")); };
    o.envelope = {toTarget(typed(m_excursion)), toTarget(typed(m_following)), typed(m_duration)};
    o.step = toTarget(typed(m_trialStep));
    o.startKp = typed(m_startKp);
    o.kpMax = typed(m_kpMax);
    o.relayAmplitude = toTarget(typed(m_amplitude));
    o.hysteresis = toTarget(typed(m_hysteresis));
    o.refine = m_refine->isChecked();
    o.verifyRule = m_verify->currentData().toString().toStdString();
    o.verifyStep = o.step;
    o.trialS = std::min(0.3, o.envelope.maxDurationS);
    return o;
}

void ZnPanel::setOptions(const dev::TuningRunner::ZnOptions& o)
{
    m_method->setCurrentIndex(o.method == TuningMethod::Relay ? 1 : 0);
    m_excursion->setValue(toShown(o.envelope.maxExcursion));
    m_following->setValue(toShown(o.envelope.maxFollowingError));
    m_duration->setValue(o.envelope.maxDurationS);
    m_trialStep->setValue(toShown(o.step));
    m_startKp->setValue(o.startKp);
    m_kpMax->setValue(o.kpMax);
    m_amplitude->setValue(toShown(o.relayAmplitude));
    m_hysteresis->setValue(toShown(o.hysteresis));
    m_refine->setChecked(o.refine);
    const int v = m_verify->findData(QString::fromStdString(o.verifyRule));
    m_verify->setCurrentIndex(v >= 0 ? v : 0);
}

void ZnPanel::clearResult(const QString& note)
{
    m_shown = {};
    m_result->setText(note.isEmpty() ? tr("Ku and Tu appear here once a method has run.") : note);
    m_rules->setRowCount(0);
}

QString ZnPanel::verificationText(const motion::control::TuningResult& r)
{
    using motion::control::StepOutcome;
    const auto& v = *r.verification;
    const auto* rule = motion::control::findRule(v.rule);
    const QString name = rule ? ui::words::term(std::string("tuning.rule.") + rule->id) : QString::fromStdString(v.rule);
    const bool mm = r.unit == "mm";
    // A metric the response did not give (a run cut short) is said so, never "nan %".
    const QString overshoot = std::isfinite(v.metrics.overshootPct) ? tr("%1 %").arg(ruleNumber(v.metrics.overshootPct)) : tr("not measured");
    // The verdict is the step test's (judgeStep): a run that "completed" inside a wide
    // band may still never have come to rest, and that is said first.
    switch (v.metrics.outcome) {
    case StepOutcome::Unstable:
        return tr("<br>Verification with %1: <b>unstable</b> (%2)").arg(name, ui::words::tuningOutcome(v.outcome));
    case StepOutcome::LimitCycle: {
        const auto& lc = v.limitCycle;
        if (mm)
            return tr("<br>Verification with %1: <b>never comes to rest</b>: a limit cycle of ±%2 µm every %3 remains "
                      "(a still axis reads at most %4 µm peak to peak on its grating); overshoot %5")
                .arg(name, QString::number(lc.amplitude * 1000, 'f', 1), period(lc.periodS), QString::number(lc.threshold * 1000, 'f', 1), overshoot);
        return tr("<br>Verification with %1: <b>never comes to rest</b>: a limit cycle of ±%2 every %3 remains; overshoot %4")
            .arg(name, ruleNumber(lc.amplitude), period(lc.periodS), overshoot);
    }
    case StepOutcome::DidNotSettle:
    case StepOutcome::Settled: break;
    }
    QString text = v.metrics.outcome == StepOutcome::Settled
        ? tr("<br>Verification with %1: overshoot %2, %3").arg(name, overshoot, ui::words::tuningOutcome(v.outcome))
        : tr("<br>Verification with %1: <b>did not settle</b> within 2 % of its step; overshoot %2").arg(name, overshoot);
    if (mm)
        text += v.settledInside5umS >= 0 ? tr(", inside ±5 µm of the target from %1 ms").arg(ruleNumber(v.settledInside5umS * 1000))
                                         : tr(", <b>never inside ±5 µm</b>");
    return text;
}

QString ZnPanel::resultText() const { return m_result->text(); }

void ZnPanel::showResult(const motion::control::TuningResult& r)
{
    m_shown = r;
    QString text = tr("<b>Ku = %1, Tu = %2</b> (%3 on %4, %5 runs)")
                       .arg(ruleNumber(r.ku), period(r.tuS), r.method == "relay" ? tr("relay") : tr("ultimate gain"),
                            QString::fromStdString(r.target))
                       .arg(r.runs);
    if (r.kuDescribing)
        text += tr("<br>Classic describing function: Ku = %1, Tu = %2 — %3")
                    .arg(ruleNumber(*r.kuDescribing), period(r.tuRelayS.value_or(0)),
                         r.refined ? tr("refined above from the measured phase crossover") : tr("not refined"));
    if (r.verification)
        text += verificationText(r);
    m_result->setText(text);
    m_rules->setRowCount(0);
    for (const auto& rule : motion::control::tuningRules()) {
        const auto c = motion::control::applyRule(rule, r.ku, r.tuS);
        const auto d = motion::control::toDiscrete(c, r.controlPeriodS);
        const int row = m_rules->rowCount();
        m_rules->insertRow(row);
        const QString cells[7] = {ui::words::term(std::string("tuning.rule.") + rule.id), ruleNumber(c.kp), ruleNumber(c.kiPerS), ruleNumber(c.kdS), ruleNumber(d.kp), ruleNumber(d.ki), ruleNumber(d.kd)};
        for (int col = 0; col < 7; ++col)
            m_rules->setItem(row, col, new QTableWidgetItem(cells[col]));
        m_rules->item(row, 0)->setToolTip(tr("Source: %1").arg(tr(rule.source)));
        auto* use = new QPushButton(tr("Use these"), m_rules);
        use->setObjectName(QStringLiteral("use_%1").arg(QLatin1String(rule.id)));
        const QString id = QString::fromLatin1(rule.id);
        const QString source = tr("Z-N %1: %2").arg(r.method == "relay" ? tr("relay") : tr("ultimate gain"), ui::words::term(std::string("tuning.rule.") + rule.id));
        connect(use, &QPushButton::clicked, this, [this, id, d, source] { emit useRule(id, d, source); });
        use->setMaximumHeight(m_rules->verticalHeader()->defaultSectionSize() - 2);
        m_rules->setCellWidget(row, 7, use);
    }
    refresh();
}

void ZnPanel::showRun(const motion::control::Record& record, const QString& label) { m_plot->addRun(record, label); }

void ZnPanel::showLive(const QVector<double>& tS, const QVector<double>& measured, const QVector<double>& output, const QString& title)
{
    m_plot->setLive(tS, measured, output, title);
}

void ZnPanel::setBusy(bool busy)
{
    m_busy = busy;
    refresh();
}

void ZnPanel::setReady(bool ready)
{
    m_ready = ready;
    refresh();
}

void ZnPanel::refresh()
{
    setEnabledOr(m_start, NumberField::firstProblemUnder(this));
    if (!m_ready || m_busy)
        m_start->setEnabled(false);
    m_abort->setEnabled(m_busy);
    for (int row = 0; row < m_rules->rowCount(); ++row)
        if (auto* w = m_rules->cellWidget(row, 7))
            w->setEnabled(!m_busy && m_ready);
}

} // namespace ui
