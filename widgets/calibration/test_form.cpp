#include "widgets/calibration/test_form.h"

#include "widgets/calibration/wheel_guard.h"
#include "widgets/common/number_field.h"

#include <QCheckBox>
#include <QComboBox>
#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QRegularExpression>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ui {

using motion::metrology::AxisTest;
using motion::metrology::CircularTest;
using motion::metrology::XyLineTest;

namespace {

/// Combos change only under the keyboard or a focused wheel (house rule).
template <typename Box>
Box* quiet(Box* b)
{
    WheelGuard::guard(b);
    return b;
}

/// What a field holds for the definition: NaN (an int field: 0) while its text is not a
/// valid number; entryProblem() says why and the run waits.
double formNumber(const NumberField* f) { return f->valueOr(std::nan("")); }
int formWhole(const NumberField* f) { return static_cast<int>(f->valueOr(0)); }

} // namespace

// Typed numbers are kept as typed: a "-5" in Feed is shown as invalid with its reason and
// holds the run, never turned into 5 (a spin box's validator dropped the minus).
NumberField* AccuracyTestForm::number(const char* name, double min, double max, double value, int decimals)
{
    auto* b = new NumberField;
    b->setObjectName(QString::fromLatin1(name));
    b->setRange(min, max);
    b->setDisplay('g', std::max(10, decimals + 6));  // every digit a test file has: a rounded display would be saved back
    b->setValue(value);
    connect(b, &NumberField::entryChanged, this, &AccuracyTestForm::changed);
    return b;
}

NumberField* AccuracyTestForm::whole(const char* name, int min, int max, int value)
{
    auto* b = new NumberField;
    if (name)
        b->setObjectName(QString::fromLatin1(name));
    b->setInteger(true);
    b->setRange(min, max);
    b->setValue(value);
    connect(b, &NumberField::entryChanged, this, &AccuracyTestForm::changed);
    return b;
}

AccuracyTestForm::AccuracyTestForm(QWidget* parent) : QWidget(parent)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(0, 0, 0, 0);
    m_kind = quiet(new QComboBox);
    m_kind->setObjectName(QStringLiteral("calibrationKind"));
    m_kind->addItems({QString(), QString(), QString()});
    v->addWidget(m_kind);
    m_pages = new QStackedWidget;
    m_pages->addWidget(buildAxisPage());
    m_pages->addWidget(buildXyPage());
    m_pages->addWidget(buildCirclePage());
    v->addWidget(m_pages);
    connect(m_kind, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
        m_pages->setCurrentIndex(i);
        emit changed();
    });
    retranslateUi();
}

QWidget* AccuracyTestForm::buildAxisPage()
{
    auto* page = new QWidget;
    auto* f = new QFormLayout(page);
    f->setContentsMargins(0, 0, 0, 0);
    auto row = [&](const char* source, QWidget* w) {
        auto* l = new QLabel;
        l->setBuddy(w);  // a field's reason names it by its label
        m_worded.push_back({l, source});
        f->addRow(l, w);
    };
    m_axis = quiet(new QComboBox);
    m_axis->setObjectName(QStringLiteral("calibrationAxis"));
    m_axis->addItems({QStringLiteral("X"), QStringLiteral("Y")});
    connect(m_axis, qOverload<int>(&QComboBox::currentIndexChanged), this, &AccuracyTestForm::changed);
    row(QT_TR_NOOP("Axis"), m_axis);
    m_targetMode = quiet(new QComboBox);
    m_targetMode->addItems({QString(), QString()});
    row(QT_TR_NOOP("Targets"), m_targetMode);
    m_start = number("calibrationStart", -10000, 10000, 10, 3);
    m_end = number("calibrationEnd", -10000, 10000, 90, 3);
    m_count = whole("calibrationCount", 2, motion::metrology::kMaxTargets, 9);
    row(QT_TR_NOOP("From (mm)"), m_start);
    row(QT_TR_NOOP("To (mm)"), m_end);
    row(QT_TR_NOOP("Count"), m_count);
    m_irregular = new QCheckBox;
    m_irregular->setChecked(true);
    connect(m_irregular, &QCheckBox::toggled, this, &AccuracyTestForm::changed);
    row(QT_TR_NOOP("Spacing"), m_irregular);
    m_list = new QLineEdit;
    m_list->setObjectName(QStringLiteral("calibrationList"));
    m_list->setEnabled(false);
    connect(m_list, &QLineEdit::textChanged, this, &AccuracyTestForm::changed);
    row(QT_TR_NOOP("List (mm)"), m_list);
    connect(m_targetMode, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
        for (QWidget* w : {static_cast<QWidget*>(m_start), static_cast<QWidget*>(m_end), static_cast<QWidget*>(m_count),
                           static_cast<QWidget*>(m_irregular)})
            w->setEnabled(i == 0);
        m_list->setEnabled(i == 1);
        emit changed();
    });
    m_cycles = whole("calibrationCycles", 2, motion::metrology::kMaxCycles, motion::metrology::kIsoCycles);
    row(QT_TR_NOOP("Cycles"), m_cycles);
    m_bidirectional = new QCheckBox;
    m_bidirectional->setChecked(true);
    connect(m_bidirectional, &QCheckBox::toggled, this, &AccuracyTestForm::changed);
    row(QT_TR_NOOP("Directions"), m_bidirectional);
    m_overrun = number("calibrationOverrun", 0, 100, 1, 3);
    row(QT_TR_NOOP("Overrun (mm)"), m_overrun);
    m_feed = number("calibrationFeed", 0.01, 1000, 5, 2);
    row(QT_TR_NOOP("Feed (mm/s)"), m_feed);
    m_dwell = number("calibrationDwell", 0, 60, 0.5, 2);
    row(QT_TR_NOOP("Dwell (s)"), m_dwell);
    m_settleTol = number("calibrationSettleTol", 0.01, 1000, 1, 2);
    row(QT_TR_NOOP("Settled within (µm)"), m_settleTol);
    m_settleWindow = number("calibrationSettleWindow", 0, 60, 0.2, 2);
    row(QT_TR_NOOP("… for (s)"), m_settleWindow);
    m_settleTimeout = number("calibrationSettleTimeout", 0.01, 600, 10, 1);
    row(QT_TR_NOOP("Settle timeout (s)"), m_settleTimeout);
    m_tolA = number("calibrationTolA", 0, 100, 0, 4);
    m_tolR = number("calibrationTolR", 0, 100, 0, 4);
    row(QT_TR_NOOP("Limit on A (mm)"), m_tolA);
    row(QT_TR_NOOP("Limit on R (mm)"), m_tolR);
    return page;
}

QWidget* AccuracyTestForm::buildXyPage()
{
    auto* page = new QWidget;
    auto* f = new QFormLayout(page);
    f->setContentsMargins(0, 0, 0, 0);
    auto row = [&](const char* source, QWidget* w) {
        auto* l = new QLabel;
        l->setBuddy(w);  // a field's reason names it by its label
        m_worded.push_back({l, source});
        f->addRow(l, w);
    };
    // Seed 000's line: (30, 40) to (150, 200).
    m_fromX = number("calibrationFromX", -10000, 10000, 30, 3);
    m_fromY = number("calibrationFromY", -10000, 10000, 40, 3);
    m_toX = number("calibrationToX", -10000, 10000, 150, 3);
    m_toY = number("calibrationToY", -10000, 10000, 200, 3);
    row(QT_TR_NOOP("From X (mm)"), m_fromX);
    row(QT_TR_NOOP("From Y (mm)"), m_fromY);
    row(QT_TR_NOOP("To X (mm)"), m_toX);
    row(QT_TR_NOOP("To Y (mm)"), m_toY);
    m_xyCount = whole("calibrationXyCount", 2, motion::metrology::kMaxTargets, 5);
    row(QT_TR_NOOP("Targets"), m_xyCount);
    m_xyCycles = whole("calibrationXyCycles", 2, motion::metrology::kMaxCycles, 5);
    row(QT_TR_NOOP("Cycles"), m_xyCycles);
    m_xyFeed = number("calibrationXyFeed", 0.01, 1000, 20, 2);
    row(QT_TR_NOOP("Feed (mm/s)"), m_xyFeed);
    return page;
}

QWidget* AccuracyTestForm::buildCirclePage()
{
    auto* page = new QWidget;
    auto* f = new QFormLayout(page);
    f->setContentsMargins(0, 0, 0, 0);
    auto row = [&](const char* source, QWidget* w) {
        auto* l = new QLabel;
        l->setBuddy(w);  // a field's reason names it by its label
        m_worded.push_back({l, source});
        f->addRow(l, w);
    };
    m_cx = number("calibrationCentreX", -10000, 10000, 50, 3);
    m_cy = number("calibrationCentreY", -10000, 10000, 50, 3);
    m_radius = number("calibrationRadius", 0.01, 1000, 20, 3);
    m_circleFeed = number("calibrationCircleFeed", 0.01, 1000, 5, 2);
    m_lead = number("calibrationLead", 0, 180, 45, 1);
    row(QT_TR_NOOP("Centre X (mm)"), m_cx);
    row(QT_TR_NOOP("Centre Y (mm)"), m_cy);
    row(QT_TR_NOOP("Radius (mm)"), m_radius);
    row(QT_TR_NOOP("Feed (mm/s)"), m_circleFeed);
    row(QT_TR_NOOP("Lead arc (°)"), m_lead);
    m_directions = quiet(new QComboBox);
    m_directions->addItems({QString(), QString(), QString()});
    connect(m_directions, qOverload<int>(&QComboBox::currentIndexChanged), this, &AccuracyTestForm::changed);
    row(QT_TR_NOOP("Directions"), m_directions);
    m_samples = whole("calibrationSamples", 8, 100000, 360);
    row(QT_TR_NOOP("Samples a turn"), m_samples);
    m_tolG = number("calibrationTolG", 0, 100, 0, 4);
    row(QT_TR_NOOP("Limit on G (mm)"), m_tolG);
    return page;
}

void AccuracyTestForm::retranslateUi()
{
    m_kind->setItemText(0, tr("Axis test (ISO 230-2)"));
    m_kind->setItemText(1, tr("Linked XY line (seed 000)"));
    m_kind->setItemText(2, tr("Circular test (ISO 230-4)"));
    m_kind->setToolTip(tr("What kind of test to run"));
    m_targetMode->setItemText(0, tr("evenly from … to"));
    m_targetMode->setItemText(1, tr("a list"));
    m_irregular->setText(tr("ISO 230-2 irregular"));
    m_irregular->setToolTip(tr("Moves each inner target off the even grid by its own amount, so a periodic error "
                               "(a screw's pitch) is not sampled at one phase"));
    m_list->setPlaceholderText(tr("10, 25.5, 40, …"));
    m_bidirectional->setText(tr("both (↑ and ↓)"));
    m_bidirectional->setToolTip(tr("Unticked: every target approached from below only (ISO's unidirectional test)"));
    m_overrun->setToolTip(tr("How far past the end targets the axis goes, so every approach comes from its side"));
    m_settleTol->setToolTip(tr("A reading is taken once the readback has stayed this close for the time below"));
    m_tolA->setToolTip(tr("0: not judged"));
    m_tolR->setToolTip(tr("0: not judged"));
    m_tolG->setToolTip(tr("0: not judged"));
    m_directions->setItemText(0, tr("both"));
    m_directions->setItemText(1, tr("counter-clockwise"));
    m_directions->setItemText(2, tr("clockwise"));
    for (const auto& [label, source] : m_worded)
        label->setText(tr(source));
}

void AccuracyTestForm::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

AccuracyTestForm::Kind AccuracyTestForm::kind() const { return static_cast<Kind>(m_kind->currentIndex()); }

void AccuracyTestForm::setAxes(const QStringList& letters)
{
    const QString was = m_axis->currentText();
    const QSignalBlocker block(m_axis);
    m_axis->clear();
    m_axis->addItems(letters);
    const int i = m_axis->findText(was);
    m_axis->setCurrentIndex(i >= 0 ? i : 0);
}

dev::files::accuracy::AccuracyTest AccuracyTestForm::test() const
{
    switch (kind()) {
    case Kind::Axis: {
        AxisTest t;
        t.axis = m_axis->currentText().toStdString();
        t.name = m_name.empty() ? "accuracy-" + t.axis : m_name;
        if (m_targetMode->currentIndex() == 0) {
            t.grid = motion::metrology::TargetGrid{formNumber(m_start), formNumber(m_end), formWhole(m_count), m_irregular->isChecked()};
        } else {
            for (const QString& w : m_list->text().split(QRegularExpression(QStringLiteral("[,;\\s]+")), Qt::SkipEmptyParts)) {
                bool ok = false;
                const double v = QLocale().toDouble(w, &ok);
                t.targetsMm.push_back(ok ? v : std::nan(""));
            }
        }
        t.cycles = formWhole(m_cycles);
        t.bidirectional = m_bidirectional->isChecked();
        t.overrunMm = formNumber(m_overrun);
        t.feedMmS = formNumber(m_feed);
        t.dwellS = formNumber(m_dwell);
        t.settle = {formNumber(m_settleTol), formNumber(m_settleWindow), formNumber(m_settleTimeout)};
        if (formNumber(m_tolA) > 0)
            t.tolerances.aMm = formNumber(m_tolA);
        if (formNumber(m_tolR) > 0)
            t.tolerances.rMm = formNumber(m_tolR);
        return t;
    }
    case Kind::XyLine: {
        XyLineTest t;
        t.name = m_name.empty() ? "xy-line" : m_name;
        t.fromMm = motion::metrology::XyPoint{formNumber(m_fromX), formNumber(m_fromY)};
        t.toMm = motion::metrology::XyPoint{formNumber(m_toX), formNumber(m_toY)};
        t.count = formWhole(m_xyCount);
        t.cycles = formWhole(m_xyCycles);
        t.feedMmS = formNumber(m_xyFeed);
        return t;
    }
    case Kind::Circle: break;
    }
    CircularTest t;
    t.name = m_name.empty() ? "circle" : m_name;
    t.centreMm = {formNumber(m_cx), formNumber(m_cy)};
    t.radiusMm = formNumber(m_radius);
    t.feedMmS = formNumber(m_circleFeed);
    t.leadArcDeg = formNumber(m_lead);
    t.samplesPerRevolution = formWhole(m_samples);
    t.counterClockwise = m_directions->currentIndex() != 2;
    t.clockwise = m_directions->currentIndex() != 1;
    if (formNumber(m_tolG) > 0)
        t.maxGMm = formNumber(m_tolG);
    return t;
}

void AccuracyTestForm::setTest(const dev::files::accuracy::AccuracyTest& test)
{
    {
        // One changed() for the whole definition, not one a field (and none mid-way).
        const QSignalBlocker block(this);
        fill(test);
    }
    emit changed();
}

void AccuracyTestForm::fill(const dev::files::accuracy::AccuracyTest& test)
{
    m_name = std::visit([](const auto& t) { return t.name; }, test);
    if (const auto* a = std::get_if<AxisTest>(&test)) {
        m_kind->setCurrentIndex(0);
        const int i = m_axis->findText(QString::fromStdString(a->axis));
        if (i >= 0)
            m_axis->setCurrentIndex(i);
        if (a->grid) {
            m_targetMode->setCurrentIndex(0);
            m_start->setValue(a->grid->startMm);
            m_end->setValue(a->grid->endMm);
            m_count->setValue(a->grid->count);
            m_irregular->setChecked(a->grid->irregular);
        } else {
            m_targetMode->setCurrentIndex(1);
            QStringList words;
            for (double v : a->targetsMm)
                words << QLocale().toString(v, 'g', 10);
            m_list->setText(words.join(QStringLiteral(", ")));
        }
        m_cycles->setValue(a->cycles);
        m_bidirectional->setChecked(a->bidirectional);
        m_overrun->setValue(a->overrunMm);
        m_feed->setValue(a->feedMmS);
        m_dwell->setValue(a->dwellS);
        m_settleTol->setValue(a->settle.toleranceUm);
        m_settleWindow->setValue(a->settle.windowS);
        m_settleTimeout->setValue(a->settle.timeoutS);
        m_tolA->setValue(a->tolerances.aMm.value_or(0));
        m_tolR->setValue(a->tolerances.rMm.value_or(0));
    } else if (const auto* x = std::get_if<XyLineTest>(&test)) {
        m_kind->setCurrentIndex(1);
        const auto points = motion::metrology::pointsOf(*x);
        if (!points.empty()) {
            m_fromX->setValue(points.front().xMm);
            m_fromY->setValue(points.front().yMm);
            m_toX->setValue(points.back().xMm);
            m_toY->setValue(points.back().yMm);
            m_xyCount->setValue(static_cast<int>(points.size()));
        }
        m_xyCycles->setValue(x->cycles);
        m_xyFeed->setValue(x->feedMmS);
    } else if (const auto* c = std::get_if<CircularTest>(&test)) {
        m_kind->setCurrentIndex(2);
        m_cx->setValue(c->centreMm.xMm);
        m_cy->setValue(c->centreMm.yMm);
        m_radius->setValue(c->radiusMm);
        m_circleFeed->setValue(c->feedMmS);
        m_lead->setValue(c->leadArcDeg);
        m_samples->setValue(c->samplesPerRevolution);
        m_directions->setCurrentIndex(c->clockwise && c->counterClockwise ? 0 : (c->counterClockwise ? 1 : 2));
        m_tolG->setValue(c->maxGMm.value_or(0));
    }
    m_pages->setCurrentIndex(m_kind->currentIndex());
}

QString AccuracyTestForm::entryProblem() const { return NumberField::firstProblemUnder(m_pages->currentWidget()); }

motion::msg::Problems AccuracyTestForm::problems() const
{
    return std::visit([](const auto& t) { return motion::metrology::validate(t); }, test());
}

void AccuracyTestForm::setEditable(bool editable)
{
    m_kind->setEnabled(editable);
    m_pages->setEnabled(editable);
}

} // namespace ui
