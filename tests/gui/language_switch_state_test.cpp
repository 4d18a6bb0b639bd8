// A language switch rewords; it never rebuilds state away. Every screen is given
// something to hold (tuning results and applied gain sets, a scan plan being
// edited, calibration results, a recipe, a pattern, a profile; a plate run paused part
// way, a pattern that has run, a step test), the window goes
// to Chinese and back, and everything a screen holds that is not wording (what
// was typed, chosen, checked, listed, plotted, enabled and shown) is as before,
// and the English is the English it was.
#include "app/gui/instrument_session.h"
#include "app/gui/motion_screens.h"
#include "device/files/accuracy/accuracy_test_file.h"
#include "device/files/text_file.h"
#include "device/jobs/pattern_runner.h"
#include "device/jobs/recipe_runner.h"
#include "device/link/simulated_link.h"
#include "gui_window.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/calibration/test_form.h"
#include "widgets/common/button_key.h"
#include "widgets/common/number_field.h"
#include "widgets/patterns/contour_plot.h"
#include "widgets/patterns/pattern_screen.h"
#include "widgets/plates/plate_map.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/run_panel.h"
#include "widgets/scan/scan_screen.h"
#include "widgets/tuning/gains_panel.h"
#include "widgets/tuning/response_plot.h"
#include "widgets/tuning/step_test_panel.h"
#include "widgets/tuning/tuning_screen.h"
#include "widgets/tuning/zn_panel.h"
#include "widgets/wording/translators.h"

#include <qcustomplot.h>

#include <QAbstractButton>
#include <QAbstractItemView>
#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QMap>
#include <QMouseEvent>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTextEdit>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using guitest::pump;
using guitest::waitFor;

namespace {

QString example(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

/// Where `w` sits under `root`: class and index among siblings of its class, from the root
/// down (object names where there are any), so the same widget has the same key each time.
QString keyOf(const QWidget* w, const QWidget* root)
{
    QStringList parts;
    for (const QObject* o = w; o && o != root; o = o->parent()) {
        QString part = o->objectName();
        if (part.isEmpty()) {
            int index = 0;
            if (const QObject* p = o->parent())
                for (const QObject* sibling : p->children()) {
                    if (sibling == o)
                        break;
                    if (sibling->metaObject() == o->metaObject())
                        ++index;
                }
            part = QStringLiteral("%1[%2]").arg(QString::fromLatin1(o->metaObject()->className())).arg(index);
        }
        parts.prepend(part);
    }
    return parts.join(QLatin1Char('/'));
}

/// Everything `root` holds, one entry a fact: key → value.
QMap<QString, QString> stateOf(QWidget* root)
{
    QMap<QString, QString> out;
    for (QWidget* w : root->findChildren<QWidget*>()) {
        // Not what a screen holds: the status bar's live link counters, the menu bar's own
        // pop-ups, and the tab bar's scroll arrows (they follow the tabs' widths in each language).
        const QString key = keyOf(w, root);
        if (key.startsWith(QLatin1String("QStatusBar")) || key.startsWith(QLatin1String("QMenuBar"))
            || key.contains(QLatin1String("qt_tabwidget_tabbar/")))
            continue;
        auto put = [&](const char* what, const QString& value) { out.insert(key + QLatin1Char(' ') + QLatin1String(what), value); };
        put("shown", w->isVisibleTo(root) ? QStringLiteral("yes") : QStringLiteral("no"));
        put("enabled", w->isEnabled() ? QStringLiteral("yes") : QStringLiteral("no"));
        if (auto* l = qobject_cast<QLabel*>(w))
            put("text", l->text());
        if (auto* e = qobject_cast<QLineEdit*>(w))
            put(qobject_cast<QComboBox*>(w->parentWidget()) ? "chosen" : "typed", e->text());  // an editable combo's text is its item's
        if (auto* bar = qobject_cast<QProgressBar*>(w))
            put("progress", QStringLiteral("%1 of %2").arg(bar->value()).arg(bar->maximum()));
        if (auto* d = qobject_cast<QDoubleSpinBox*>(w))
            put("value", QString::number(d->value(), 'g', 12));
        else if (auto* s = qobject_cast<QAbstractSpinBox*>(w))
            put("value", s->property("value").toString());
        if (auto* b = qobject_cast<QAbstractButton*>(w)) {
            put("button", b->text());
            // A button's key (F5, Ctrl+R): QAbstractButton::setText() puts the text's
            // mnemonic in its place, so rewording a button can take its key away.
            put("key", ui::buttonKey(b).toString());
            if (b->isCheckable())
                put("checked", b->isChecked() ? QStringLiteral("yes") : QStringLiteral("no"));
        }
        if (auto* c = qobject_cast<QComboBox*>(w)) {
            put("choice", QString::number(c->currentIndex()));
            put("choices", QString::number(c->count()));
            put("chosen", c->currentText());
        }
        if (auto* t = qobject_cast<QTabWidget*>(w))
            put("tab", QString::number(t->currentIndex()));
        if (auto* stack = qobject_cast<QStackedWidget*>(w))
            put("page", QString::number(stack->currentIndex()));
        if (auto* v = qobject_cast<QAbstractItemView*>(w); v && v->model()) {
            const QAbstractItemModel* m = v->model();
            put("rows", QString::number(m->rowCount()));
            put("columns", QString::number(m->columnCount()));
            if (qobject_cast<QTableWidget*>(w))
                for (int r = 0; r < m->rowCount() && r < 50; ++r)
                    for (int c = 0; c < m->columnCount(); ++c)
                        out.insert(QStringLiteral("%1 cell %2,%3").arg(key).arg(r).arg(c), m->index(r, c).data().toString());
        }
        if (auto* e = qobject_cast<QPlainTextEdit*>(w))
            put("typed", e->toPlainText());
        if (auto* e = qobject_cast<QTextEdit*>(w))
            put("typed", e->toPlainText());
        if (auto* p = qobject_cast<QCustomPlot*>(w)) {
            put("plottables", QString::number(p->plottableCount()));
            QStringList points;
            for (int i = 0; i < p->graphCount(); ++i)
                points << QString::number(p->graph(i)->dataCount());
            put("points", points.join(QLatin1Char(',')));
        }
    }
    return out;
}

/// What differs between two states, leaving out what changes by itself (`volatile_`).
QStringList differences(const QMap<QString, QString>& before, const QMap<QString, QString>& after, const QSet<QString>& volatile_)
{
    QStringList out;
    for (auto it = before.begin(); it != before.end(); ++it) {
        if (volatile_.contains(it.key()))
            continue;
        const auto there = after.find(it.key());
        if (there == after.end())
            out << QStringLiteral("%1: “%2” is gone").arg(it.key(), it.value());
        else if (*there != it.value())
            out << QStringLiteral("%1: “%2” → “%3”").arg(it.key(), it.value(), *there);
    }
    for (auto it = after.begin(); it != after.end(); ++it)
        if (!before.contains(it.key()) && !volatile_.contains(it.key()))
            out << QStringLiteral("%1: “%2” is new").arg(it.key(), it.value());
    return out;
}

void chooseLanguage(app::MainWindow& w, const QString& code)
{
    for (QAction* a : w.findChildren<QAction*>())
        if (a->data().toString() == code) {
            a->trigger();
            break;
        }
    QApplication::processEvents();
}

void sendMouse(QWidget* w, QEvent::Type type, const QPointF& at, Qt::MouseButtons held)
{
    const Qt::MouseButton b = type == QEvent::MouseMove ? Qt::NoButton : Qt::LeftButton;
    QMouseEvent e(type, at, w->mapToGlobal(at), b, held, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

/// Presses beside the first well, drags past the last and lets go, as a hand would.
void dragWells(ui::PlateMap* map, const motion::plates::WellId& from, const motion::plates::WellId& to)
{
    const QPointF a = map->wellCenter(from) - QPointF(4, 4), b = map->wellCenter(to) + QPointF(4, 4);
    sendMouse(map, QEvent::MouseButtonPress, a, Qt::LeftButton);
    for (int k = 1; k <= 10; ++k)
        sendMouse(map, QEvent::MouseMove, a + (b - a) * k / 10.0, Qt::LeftButton);
    sendMouse(map, QEvent::MouseButtonRelease, b, Qt::NoButton);
}

class LanguageSwitchState : public ::testing::Test {
protected:
    void SetUp() override
    {
        ASSERT_TRUE(translators.setLanguage(QStringLiteral("en")));
        app::MainWindowOptions options = guitest::testWindowOptions();
        options.translators = &translators;
        w = guitest::openReadyWindow({1366, 768}, options);
        ASSERT_TRUE(w) << "the simulated instruments did not become ready";
    }
    void TearDown() override
    {
        w.reset();
        translators.setLanguage(QStringLiteral("en"));
    }

    /// The Tuning screen as the operator left it: Stage X, Z–N results with their rules
    /// table, and gain sets applied from it (a history of three).
    void tuningHolds()
    {
        ASSERT_TRUE(w->showScreen(QStringLiteral("tuning")));
        ui::TuningScreen* t = w->tuningScreen();
        t->setConfirm([](const QString&) { return true; });
        ASSERT_TRUE(waitFor([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 3000));
        ASSERT_TRUE(t->selectTarget(QStringLiteral("Stage X")));
        ASSERT_TRUE(waitFor([&] { return !t->gains()->history().isEmpty(); }, 3000)) << t->statusText().toStdString();
        ASSERT_TRUE(t->loadResults(example("stage-x-relay.tuning.json"))) << t->statusText().toStdString();
        for (const char* rule : {"use_zn-pi", "use_tl-pid"}) {
            const int before = t->gains()->history().size();
            auto* use = t->assistant()->findChild<QPushButton*>(QLatin1String(rule));
            ASSERT_NE(use, nullptr) << rule;
            QTest::mouseClick(use, Qt::LeftButton);
            ASSERT_TRUE(waitFor([&] { return t->gains()->history().size() == before + 1; }, 3000)) << rule << ": " << t->statusText().toStdString();
        }
        ASSERT_EQ(t->gains()->history().size(), 3);
        // Something typed and not applied yet.
        auto* kd = t->gains()->findChild<QLineEdit*>(QStringLiteral("kdEdit"));
        kd->selectAll();
        QTest::keyClicks(kd, QStringLiteral("0.0001"));
    }
    /// A scan plan being edited: a region and a field typed in.
    void scanHolds()
    {
        ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
        ui::ScanScreen* s = w->scanScreen();
        auto setSpin = [&](const char* name, double v) {
            auto* box = s->findChild<ui::NumberField*>(QLatin1String(name));
            ASSERT_NE(box, nullptr) << name;
            box->setValue(v);
        };
        s->findChild<QComboBox*>(QStringLiteral("scanFovFrom"))->setCurrentIndex(1);
        setSpin("scanFieldW", 1.5);
        setSpin("scanX0", 20);
        setSpin("scanX1", 31);
        pump(200);  // the plan is redrawn on a timer
    }
    /// Calibration results: the example interferometer capture imported against its test.
    void calibrationHolds()
    {
        ASSERT_TRUE(w->showScreen(QStringLiteral("calibration")));
        ui::CalibrationScreen* c = w->calibrationScreen();
        c->setInstrument(1);
        const QString sequence = dir.filePath(QStringLiteral("stage-x.targets.csv"));
        const QString capture = dir.filePath(QStringLiteral("xl80-export.csv"));
        ASSERT_TRUE(QFile::copy(example("stage-x-xl80.targets.csv"), sequence));
        ASSERT_TRUE(QFile::copy(example("stage-x-xl80.interferometer.csv"), capture));
        std::string text;
        motion::msg::Message error;
        ASSERT_TRUE(dev::files::readText(example("stage-x-xl80.accuracy-test.json"), &text, &error));
        const auto read = dev::files::accuracy::accuracyTestFromJson(text, "stage-x-xl80.accuracy-test.json");
        ASSERT_TRUE(read.test);
        c->form()->setTest(std::get<motion::metrology::AxisTest>(*read.test));
        pump(20);
        ASSERT_TRUE(c->importCapture(sequence, capture));
        ASSERT_TRUE(c->latest());
    }
    void platesHold()
    {
        ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
        ASSERT_TRUE(w->platesScreen()->openRecipe(example("reagent-transfer.recipe.json")));
    }
    void patternsHold()
    {
        ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
        ui::PatternScreen* p = w->motionScreens()->patterns();
        p->setInstrument(1);
        QString error;
        ASSERT_TRUE(p->loadPattern(example("stage-circle-10mm.pattern.json"), &error)) << error.toStdString();
    }

    /// What a switch to Chinese and back changed under `root` beyond its words: `held` what
    /// was not as before while in Chinese (words aside), `lost` what was not as before once back
    /// in English. What changes by itself is read twice first and left out.
    struct SwitchOutcome {
        QStringList held, lost;
    };
    SwitchOutcome switchToChineseAndBack(QWidget* root)
    {
        const auto first = stateOf(root);
        pump(400);
        const auto before = stateOf(root);
        QSet<QString> live;
        for (auto it = before.begin(); it != before.end(); ++it)
            if (first.value(it.key()) != it.value())
                live.insert(it.key());
        chooseLanguage(*w, QStringLiteral("zh_CN"));
        pump(200);
        const auto inChinese = stateOf(root);
        chooseLanguage(*w, QStringLiteral("en"));
        pump(200);
        SwitchOutcome out;
        for (auto it = before.begin(); it != before.end(); ++it) {
            const QString& k = it.key();
            const bool wording = k.endsWith(QLatin1String(" text")) || k.endsWith(QLatin1String(" button"))
                || k.contains(QLatin1String(" cell ")) || k.endsWith(QLatin1String(" chosen"));
            if (!live.contains(k) && !wording && inChinese.value(k) != it.value())
                out.held << QStringLiteral("%1: “%2” → “%3”").arg(k, it.value(), inChinese.value(k));
        }
        out.lost = differences(before, stateOf(root), live);
        return out;
    }
    dev::Instrument* stageInstrument() { return w->stage()->instrument(); }
    /// The stage homed with its clock sped up (10x, as the patterns tests do), then put at
    /// `x` mm on X and its clock put back to real time.
    bool homeStageAt(double x)
    {
        auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
        if (!link)
            return false;
        link->host().setTimeScale(10);
        stageInstrument()->home(0);
        auto still = [&] {
            const auto& a = stageInstrument()->status().axes;
            return a.size() == 2 && a[0].homed && a[1].homed && !a[0].moving && !a[1].moving;
        };
        bool ok = waitFor(still, 30000);
        if (ok && x != 0) {
            stageInstrument()->move({{0, x}}, false);
            pump(200);
            ok = waitFor([&] { return still() && std::abs(stageInstrument()->status().axes[0].commanded - x) < 1e-6; }, 10000);
        }
        link->host().setTimeScale(1);
        return ok;
    }

    ui::words::Translators translators;
    std::unique_ptr<app::MainWindow> w;
    QTemporaryDir dir;
};

} // namespace

// Found by hand: Tuning → Z–N results and a few gain sets applied, then 简体中文 and back,
// and the Ku/Tu line and the rules table were gone, "Save results…" greyed out and the
// history down to one row: the target list was rebuilt under its new names and the
// target "chosen again".
TEST_F(LanguageSwitchState, TheTuningScreenKeepsItsResultsAndHistory)
{
    tuningHolds();
    ui::TuningScreen* t = w->tuningScreen();
    const QString result = t->assistant()->resultText();
    ASSERT_TRUE(result.contains(QStringLiteral("Ku ="))) << result.toStdString();
    chooseLanguage(*w, QStringLiteral("zh_CN"));
    pump(100);
    EXPECT_TRUE(t->hasResult()) << "the results were thrown away";
    EXPECT_EQ(t->assistant()->rulesTable()->rowCount(), 8);
    EXPECT_EQ(t->gains()->history().size(), 3);
    EXPECT_NE(t->currentTarget(), QStringLiteral("Stage X")) << "the target's name was not reworded";
    chooseLanguage(*w, QStringLiteral("en"));
    pump(100);
    EXPECT_EQ(t->currentTarget(), QStringLiteral("Stage X"));
    EXPECT_EQ(t->assistant()->resultText(), result);
    EXPECT_EQ(t->gains()->history().size(), 3);
    EXPECT_EQ(t->gains()->findChild<QTableWidget*>(QStringLiteral("gainsHistory"))->rowCount(), 3);
    EXPECT_EQ(t->assistant()->rulesTable()->rowCount(), 8);
    EXPECT_TRUE(t->findChild<QPushButton*>(QStringLiteral("saveResults"))->isEnabled());
    EXPECT_EQ(t->gains()->findChild<QLineEdit*>(QStringLiteral("kdEdit"))->text(), QStringLiteral("0.0001")) << "the typed Kd was lost";
}

// The same for every screen, each holding something: nothing a screen holds changes on a
// switch to Chinese and back but the words, and those come back as they were.
TEST_F(LanguageSwitchState, EveryScreenHoldsWhatItHeldAcrossASwitchAndBack)
{
    for (const QString& screen : w->screenNames()) {  // every screen built and shown first
        ASSERT_TRUE(w->showScreen(screen));
        pump(20);
    }
    tuningHolds();
    scanHolds();
    calibrationHolds();
    platesHold();
    patternsHold();
    ASSERT_TRUE(w->showScreen(QStringLiteral("tuning")));
    pump(300);

    // What changes by itself (live readouts, clocks) is left out: it is read twice first.
    const auto first = stateOf(w.get());
    pump(400);
    const auto before = stateOf(w.get());
    QSet<QString> live;
    for (auto it = before.begin(); it != before.end(); ++it)
        if (first.value(it.key()) != it.value())
            live.insert(it.key());

    chooseLanguage(*w, QStringLiteral("zh_CN"));
    pump(200);
    const auto inChinese = stateOf(w.get());
    chooseLanguage(*w, QStringLiteral("en"));
    pump(200);
    const auto after = stateOf(w.get());

    // In Chinese only the words may differ: what is typed, chosen, counted and shown may not.
    QStringList held;
    for (auto it = before.begin(); it != before.end(); ++it) {
        const QString& k = it.key();
        if (live.contains(k))
            continue;
        const bool wording = k.endsWith(QLatin1String(" text")) || k.endsWith(QLatin1String(" button")) || k.contains(QLatin1String(" cell "))
            || k.endsWith(QLatin1String(" chosen")) || k.endsWith(QLatin1String(" key"));  // a mnemonic is the language's
        if (!wording && inChinese.value(k) != it.value())
            held << QStringLiteral("%1: “%2” → “%3”").arg(k, it.value(), inChinese.value(k));
    }
    EXPECT_TRUE(held.isEmpty()) << "changed by the switch to Chinese:\n" << held.join(QLatin1Char('\n')).toStdString();
    const QStringList lost = differences(before, after, live);
    EXPECT_TRUE(lost.isEmpty()) << "not as before after Chinese and back:\n" << lost.join(QLatin1Char('\n')).toStdString();
}

// A plate run paused part way: the switch must leave the run where it was (its table, its
// progress, what is next, its times and the map's done wells), and the run must go on from
// there when resumed.
TEST_F(LanguageSwitchState, APausedPlateRunKeepsItsProgressTableAndMap)
{
    ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
    ui::PlatesScreen* screen = w->platesScreen();
    screen->setRunLogDirectory(dir.path());
    ui::ConnectionChoice c;
    c.baud = 0;  // an unpaced simulator with a fast clock: the run takes seconds
    w->analyzer()->connectTo(c);
    dev::Instrument* analyzer = w->analyzer()->instrument();
    ASSERT_TRUE(waitFor([&] { return analyzer->isReady(); }, 5000));
    auto* link = qobject_cast<dev::SimulatedLink*>(w->analyzer()->link());
    ASSERT_NE(link, nullptr);
    link->host().setTimeScale(20);
    analyzer->home(0);
    ASSERT_TRUE(waitFor(
        [&] {
            const auto& a = analyzer->status().axes;
            return a.size() == 4 && std::all_of(a.begin(), a.end(), [](const auto& x) { return x.homed && !x.moving; });
        },
        30000));
    ui::PlateMap* map = screen->plateMap();
    dragWells(map, {0, 0}, {0, 5});  // A1 … A6
    QTest::mouseClick(guitest::button(screen, QStringLiteral("Aspirate from these")), Qt::LeftButton);
    ASSERT_TRUE(screen->plan().ok());
    QTest::mouseClick(guitest::button(screen->runPanel(), QStringLiteral("Run")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->progress().opsDone >= 2; }, 30000));
    QTest::mouseClick(guitest::button(screen->runPanel(), QStringLiteral("Pause")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Paused; }, 30000))
        << dev::jobs::runStateTerm(screen->runner()->state());
    ASSERT_TRUE(waitFor([&] { return !analyzer->status().anyMoving(); }, 5000));
    pump(300);
    const int done = screen->runner()->progress().opsDone;
    ASSERT_LT(done, screen->runner()->progress().opsTotal) << "the run ended before it could be paused";
    const QImage mapBefore = map->grab().toImage();

    const SwitchOutcome o = switchToChineseAndBack(screen);
    EXPECT_TRUE(o.held.isEmpty()) << "changed by the switch to Chinese:\n" << o.held.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(o.lost.isEmpty()) << "not as before after Chinese and back:\n" << o.lost.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(screen->runner()->state(), dev::jobs::RunState::Paused);
    EXPECT_EQ(screen->runner()->progress().opsDone, done);
    EXPECT_EQ(map->grab().toImage(), mapBefore) << "the map's wells are not drawn as they were";

    QTest::mouseClick(guitest::button(screen->runPanel(), QStringLiteral("Resume")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::RunState::Finished; }, 30000))
        << dev::jobs::runStateTerm(screen->runner()->state());
    EXPECT_EQ(screen->runner()->progress().opsDone, screen->runner()->progress().opsTotal);
}

// A pattern that has run: its measured path, its figures and its summary are what the
// operator came for, and a switch must leave them drawn and said as they were.
TEST_F(LanguageSwitchState, APatternThatRanKeepsItsMeasuredPathAndFigures)
{
    ASSERT_TRUE(homeStageAt(0));
    ASSERT_TRUE(w->showScreen(QStringLiteral("patterns")));
    ui::PatternScreen* p = w->motionScreens()->patterns();
    p->setInstrument(1);
    motion::plans::Pattern pat;
    pat.shape = motion::plans::PatternShape::Line;
    pat.feedMmS = 2.0;
    pat.line = {{0.5, 0.5}, {2.5, 1.5}};  // 2.2 mm at 2 mm/s: about a second
    p->setPattern(pat);
    pump(100);
    ASSERT_TRUE(p->run()) << p->statusText().toStdString();
    ASSERT_TRUE(waitFor([&] { return p->runner()->state() == dev::jobs::PatternRunner::State::Done; }, 15000)) << p->statusText().toStdString();
    pump(300);
    const std::size_t samples = p->runner()->samples().size();
    ASSERT_GT(samples, 0U);
    const QString summary = p->summaryText();
    ASSERT_FALSE(summary.isEmpty());
    const QImage contourBefore = p->contour()->grab().toImage();

    const SwitchOutcome o = switchToChineseAndBack(p);
    EXPECT_TRUE(o.held.isEmpty()) << "changed by the switch to Chinese:\n" << o.held.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(o.lost.isEmpty()) << "not as before after Chinese and back:\n" << o.lost.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(p->runner()->state(), dev::jobs::PatternRunner::State::Done);
    EXPECT_EQ(p->runner()->samples().size(), samples);
    EXPECT_EQ(p->summaryText(), summary);
    EXPECT_EQ(p->contour()->grab().toImage(), contourBefore) << "the measured path is not drawn as it was";
}

// A step test's response and metrics on the Tuning screen stay through a switch, as the
// Z–N results and the gain history do.
TEST_F(LanguageSwitchState, AStepTestKeepsItsResponseAndMetrics)
{
    ASSERT_TRUE(homeStageAt(50));
    ASSERT_TRUE(w->showScreen(QStringLiteral("tuning")));
    ui::TuningScreen* t = w->tuningScreen();
    ASSERT_TRUE(waitFor([&] { return t->targetNames().contains(QStringLiteral("Stage X")); }, 3000));
    ASSERT_TRUE(t->selectTarget(QStringLiteral("Stage X")));
    ASSERT_TRUE(waitFor([&] { return !t->gains()->history().isEmpty(); }, 3000));
    QTest::mouseClick(t->stepTests()->findChild<QPushButton*>(QStringLiteral("runStepTest")), Qt::LeftButton);
    ASSERT_TRUE(waitFor([&] { return t->stepTests()->runs() == 1; }, 10000)) << t->statusText().toStdString();
    ASSERT_TRUE(waitFor([&] { return !stageInstrument()->status().anyMoving(); }, 5000));
    pump(300);
    QStringList metrics;
    for (int r = 0; r < t->stepTests()->metricsTable()->rowCount(); ++r)
        metrics << t->stepTests()->metricsTable()->item(r, 0)->text();

    const SwitchOutcome o = switchToChineseAndBack(t);
    EXPECT_TRUE(o.held.isEmpty()) << "changed by the switch to Chinese:\n" << o.held.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(o.lost.isEmpty()) << "not as before after Chinese and back:\n" << o.lost.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(t->stepTests()->runs(), 1);
    EXPECT_EQ(t->stepTests()->plot()->runCount(), 1) << "the response is gone from the plot";
    ASSERT_EQ(t->stepTests()->metricsTable()->columnCount(), 1);
    QStringList after;
    for (int r = 0; r < t->stepTests()->metricsTable()->rowCount(); ++r)
        after << t->stepTests()->metricsTable()->item(r, 0)->text();
    EXPECT_EQ(after, metrics);
}
