// Every text a screen shows went through translation: with a pseudo-translation of
// every context installed before the window is built, no label, button, tab, column
// header, combo item, placeholder or tooltip may still read as plain English — except
// data shown as it is: what a device says of itself (its model and firmware), port
// paths, and names from files (the deck's slots, a recipe's plates, field paths).
// The walk prints what it found on every screen.
#include "gui_window.h"
#include "shown_texts.h"

#include "../device/pseudo_translation.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QTabWidget>
#include <QTest>
#include <QTableWidget>

#include "widgets/axis_row.h"
#include "widgets/jog_screen.h"
#include "widgets/common/elided_label.h"
#include "widgets/event_log.h"
#include "widgets/message_banner.h"
#include "widgets/plates/plates_screen.h"
#include "widgets/plates/run_panel.h"
#include "widgets/retranslator.h"
#include "widgets/wording/translators.h"
#include "widgets/wording/wording.h"

#include <gtest/gtest.h>

namespace {

using InstrumentSessionPtr = app::InstrumentSession*;

/// Text shown verbatim in every language: the simulator's firmware name, the protocol's
/// name, serial-port paths, the deck's station ids, a recipe problem's field path and a
/// model plant's spec. The shipped deck's slot names ("back"), the new recipe's plate
/// name and the simulator's model are worded (ui::words::shippedName, ui::words::modelName), so
/// they are not listed.
QString withoutData(QString text)
{
    static const QStringList data = [] {
        // "samples": the plate of a recipe made while the window spoke English keeps its name
        // in the recipe (steps refer to it), so the plate map shows it as it is.
        QStringList d{QStringLiteral("benchpilot-sim 1.0"), QStringLiteral("BenchPilot protocol 1"), QStringLiteral("samples"),
                      QStringLiteral("wash"), QStringLiteral("waste"), QStringLiteral("steps:"),
                      QStringLiteral("steps：")};
        return d;
    }();
    for (const QString& d : data)
        text.remove(d);
    // What stays as typed in every language: file names, keys, the well syntax and
    // placeholders a person types, the minute's symbol, the simulator's gauge port.
    static const QRegularExpression literal(QStringLiteral(
        "[A-Za-z0-9_./-]*\\.(json|txt|pos|csv|jsonl|md)\\b|\\{[a-z0-9:]+\\}|\\bPg(Up|Dn)\\b|\\b(row B|column 3|all|min|sim)\\b"));
    text.remove(literal);
    static const QRegularExpression path(QStringLiteral("/dev/[A-Za-z0-9_./-]+"));
    static const QRegularExpression plant(QStringLiteral("(fopdt|lag):[A-Za-z0-9_.,=]+"));  // a model plant's spec, as typed
    static const QRegularExpression labware(QStringLiteral("\\bsbs-\\d+\\b"));  // a built-in labware's id, as files name it
    text.remove(labware);
    text.remove(path);
    text.remove(plant);
    return text;
}

using guitest::forEachShownText;

/// Visible texts of `root` and its visible children that still read as English.
QStringList englishOn(QWidget* root)
{
    QStringList out;
    forEachShownText(root, [&out](const QString& where, const QString& text) {
        for (const QString& w : i18ntest::untranslated(withoutData(text)))
            out << QStringLiteral("%1: \"%2\" in \"%3\"").arg(where, w, text.left(80));
    });
    return out;
}

TEST(I18nWalk, TheWindowsOwnTextsAndEveryScreenGoThroughTranslation)
{
    const i18ntest::PseudoTranslation pseudo({});
    app::MainWindow w(guitest::testWindowOptions());
    w.resize(1366, 768);
    w.show();
    QApplication::processEvents();
    QStringList failures;
    for (const QString& screen : w.screenNames()) {
        ASSERT_TRUE(w.showScreen(screen));
        QApplication::processEvents();
        const QStringList found = englishOn(&w);
        for (const QString& f : found)
            std::printf("[i18n walk] %s: %s\n", qPrintable(screen), qPrintable(f));
        for (const QString& f : found)
            failures << screen + QStringLiteral(": ") + f;
    }
    EXPECT_TRUE(failures.isEmpty()) << failures.join(QLatin1Char('\n')).toStdString();
}

TEST(I18nWalk, InChineseNoScreenShowsAnEnglishWord)
{
    // The pseudo-translation answers every context; the real catalogue answers only the
    // context lupdate filed a string under, so a tr() whose runtime context differs
    // (a class without Q_OBJECT) shows English here and nowhere else.
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
    app::MainWindow w(guitest::testWindowOptions());
    w.resize(1366, 768);
    w.show();
    QApplication::processEvents();
    QStringList failures;
    for (const QString& screen : w.screenNames()) {
        ASSERT_TRUE(w.showScreen(screen));
        QApplication::processEvents();
        for (const QString& f : englishOn(&w))
            failures << screen + QStringLiteral(": ") + f;
    }
    translators.setLanguage(QStringLiteral("en"));
    EXPECT_TRUE(failures.isEmpty()) << failures.join(QLatin1Char('\n')).toStdString();
}

/// Visible texts of `root` that contain a Chinese character (a language is named in
/// its own words in the Language menu, so "简体中文" is not one).
QStringList chineseOn(QWidget* root)
{
    static const QRegularExpression han(QStringLiteral("\\p{Han}"));
    QStringList out;
    forEachShownText(root, [&out](const QString& where, const QString& text) {
        if (text.contains(han) && text != QStringLiteral("简体中文"))
            out << QStringLiteral("%1: \"%2\"").arg(where, text.left(80));
    });
    return out;
}

/// Triggers the Language menu's entry for `code`, as the operator would.
void chooseLanguage(app::MainWindow& w, const QString& code)
{
    for (QAction* a : w.findChildren<QAction*>())
        if (a->data().toString() == code) {
            a->trigger();
            break;
        }
    QApplication::processEvents();
}

TEST(I18nWalk, SwitchingLanguageRewordsEveryOpenScreenWithoutARestart)
{
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("en")));
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.translators = &translators;
    app::MainWindow w(options);
    w.resize(1366, 768);
    w.show();
    for (const QString& screen : w.screenNames()) {  // every screen built and shown in English first
        ASSERT_TRUE(w.showScreen(screen));
        QApplication::processEvents();
    }
    chooseLanguage(w, QStringLiteral("zh_CN"));
    QStringList english;
    for (const QString& screen : w.screenNames()) {
        ASSERT_TRUE(w.showScreen(screen));
        QApplication::processEvents();
        for (const QString& f : englishOn(&w))
            english << screen + QStringLiteral(": ") + f;
    }
    EXPECT_TRUE(english.isEmpty()) << "left in English after switching to Chinese:\n" << english.join(QLatin1Char('\n')).toStdString();
    chooseLanguage(w, QStringLiteral("en"));
    QStringList chinese;
    for (const QString& screen : w.screenNames()) {
        ASSERT_TRUE(w.showScreen(screen));
        QApplication::processEvents();
        for (const QString& f : chineseOn(&w))
            chinese << screen + QStringLiteral(": ") + f;
    }
    EXPECT_TRUE(chinese.isEmpty()) << "left in Chinese after switching back:\n" << chinese.join(QLatin1Char('\n')).toStdString();
}

/// A window ready on both simulators at 1366 × 768, in Chinese; its Language menu switches
/// `translators`.
std::unique_ptr<app::MainWindow> openInChinese(ui::words::Translators& translators)
{
    if (!translators.setLanguage(QStringLiteral("zh_CN")))
        return nullptr;
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.translators = &translators;
    return guitest::openReadyWindow(QSize(1366, 768), options);
}

TEST(I18nWalk, TheEventLogSaysWhatTheDeviceDidInTheLanguageOnScreen)
{
    ui::words::Translators translators;
    auto w = openInChinese(translators);
    ASSERT_TRUE(w);
    dev::Instrument* stage = w->stage()->instrument();
    const int before = w->eventLog()->rowCount();
    stage->estop();
    ASSERT_TRUE(guitest::waitFor([&] { return stage->status().estop; }, 3000));
    stage->reset();
    ASSERT_TRUE(guitest::waitFor([&] { return !stage->status().estop && w->eventLog()->rowCount() >= before + 2; }, 3000));
    QStringList english;
    for (int r = before; r < w->eventLog()->rowCount(); ++r)
        for (const QString& word : i18ntest::untranslated(withoutData(w->eventLog()->rowText(r))))
            english << QStringLiteral("\"%1\" in %2").arg(word, w->eventLog()->rowText(r));
    EXPECT_TRUE(english.isEmpty()) << english.join(QLatin1Char('\n')).toStdString();
    // Worded when shown: switching back rewords the rows already in the log.
    chooseLanguage(*w, QStringLiteral("en"));
    bool halted = false;
    for (int r = before; r < w->eventLog()->rowCount(); ++r)
        halted = halted || w->eventLog()->rowText(r).contains(QStringLiteral("all motion halted"));
    EXPECT_TRUE(halted);
}

// Seen under Xvfb: switching to English mid-run left "回环 @ 115200 波特" in both connection
// bars, the run's message lines and the banner in Chinese; each was worded once, when it came.
TEST(I18nWalk, LinesAlreadyShownAreRewordedOnASwitch)
{
    ui::words::Translators translators;
    auto w = openInChinese(translators);
    ASSERT_TRUE(w);
    ASSERT_TRUE(w->showScreen(QStringLiteral("plates")));
    emit w->platesScreen()->runner()->message(motion::msg::make("recipe.run.aborted"), false);
    QApplication::processEvents();
    auto* lines = w->platesScreen()->runPanel()->findChild<QListWidget*>(QStringLiteral("runMessages"));
    ASSERT_NE(lines, nullptr);
    ASSERT_GT(lines->count(), 0);
    const QString chineseLine = lines->item(lines->count() - 1)->text();
    auto connectionTexts = [&] {
        QStringList out;
        for (auto* l : w->findChildren<ui::ElidedLabel*>())
            out << l->fullText();
        return out.join(QLatin1Char('\n'));
    };
    ASSERT_TRUE(connectionTexts().contains(QStringLiteral("回环"))) << connectionTexts().toStdString();
    QTest::keyClick(w.get(), Qt::Key_Escape);  // the E-stop's banner, an error that waits to be read
    ASSERT_TRUE(w->banner()->text().contains(QStringLiteral("急停"))) << w->banner()->text().toStdString();

    chooseLanguage(*w, QStringLiteral("en"));
    EXPECT_TRUE(w->banner()->text().startsWith(QStringLiteral("E-STOP"))) << w->banner()->text().toStdString();
    const QString englishLine = lines->item(lines->count() - 1)->text();
    EXPECT_NE(englishLine, chineseLine);
    EXPECT_TRUE(englishLine.endsWith(QStringLiteral("  Aborted by the operator"))) << englishLine.toStdString();
    EXPECT_FALSE(connectionTexts().contains(QStringLiteral("回环"))) << connectionTexts().toStdString();
    EXPECT_TRUE(connectionTexts().contains(QStringLiteral("loopback"))) << connectionTexts().toStdString();
}

TEST(I18nWalk, SwitchingLeavesANameInAComboAsItIs)
{
    // A deck station called "wash" is a name from a file, not the step "wash" (清洗):
    // rewording it would break the recipe that refers to it by name.
    QWidget root;
    auto* stations = new QComboBox(&root);
    stations->addItem(QStringLiteral("wash"));
    stations->addItem(QStringLiteral("waste"), QStringLiteral("waste"));
    auto* label = new QLabel(QStringLiteral("wash"), &root);
    ui::Retranslator::retranslate({&root}, QStringLiteral("en"), QStringLiteral("zh_CN"));
    EXPECT_EQ(stations->itemText(0), QStringLiteral("wash"));
    EXPECT_EQ(label->text(), QStringLiteral("清洗")) << "a label's text is worded";
}

TEST(I18nWalk, TheShippedDecksAndLabwaresNamesAreWordedAndALabsOwnNamesAreNot)
{
    // "1 (back)" and "96-well plate, 360 µL" stayed English in Chinese: they come from the
    // files BenchPilot ships. Only those exact names are worded, for display.
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
    EXPECT_EQ(ui::words::shippedName("back"), QStringLiteral("后侧"));
    EXPECT_EQ(ui::words::shippedName("wash trough"), QStringLiteral("清洗槽"));
    EXPECT_EQ(ui::words::shippedName("96-well plate, 360 µL"), QStringLiteral("96 孔板，360 µL"));
    EXPECT_EQ(ui::words::shippedName("back bench"), QStringLiteral("back bench")) << "a lab's own name";
    EXPECT_EQ(ui::words::shippedName("wash"), QStringLiteral("wash")) << "a station's id, which recipes refer to";
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("en")));
    EXPECT_EQ(ui::words::shippedName("back"), QStringLiteral("back"));
}

TEST(I18nWalk, TheWalkFindsATextThatDidNotGoThroughTranslation)
{
    const i18ntest::PseudoTranslation pseudo({});
    QWidget root;
    auto* l = new QLabel(QStringLiteral("Plain English here"), &root);
    (void)l;
    root.show();
    EXPECT_FALSE(englishOn(&root).isEmpty());
    l->setText(QCoreApplication::translate("ui::Test", "Plain English here"));
    EXPECT_TRUE(englishOn(&root).isEmpty()) << englishOn(&root).join(QLatin1Char('\n')).toStdString();
}

/// A little motion of each instrument, so every plot has lines, ticks and a legend.
void exerciseBoth(app::MainWindow& w)
{
    for (InstrumentSessionPtr s : {w.analyzer(), w.stage()}) {
        dev::Instrument* c = s->instrument();
        c->startJog(0, 0.2 * c->identity().axes[0].maxSpeed);
        guitest::pump(400);
        c->stopJog(0);
    }
    guitest::waitFor([&] { return !w.analyzer()->instrument()->status().anyMoving() && !w.stage()->instrument()->status().anyMoving(); },
                     3000);
}

/// What of `w`'s screen on show reads as English in Chinese, and tick labels that repeat.
QStringList englishOnScreen(app::MainWindow& w, const QString& where)
{
    QStringList out;
    forEachShownText(
        &w,
        [&](const QString& what, const QString& text) {
            for (const QString& word : guitest::englishWords(withoutData(text)))
                out << QStringLiteral("%1: %2: \"%3\" in \"%4\"").arg(where, what, word, text.left(100));
        },
        true);
    for (auto* plot : w.findChildren<QCustomPlot*>()) {
        if (!plot->isVisibleTo(&w))
            continue;
        for (QCPAxis* axis : plot->axisRects().isEmpty() ? QList<QCPAxis*>() : plot->axisRects().first()->axes())
            if (axis->visible() && axis->tickLabels()) {
                const QVector<QString> labels = axis->tickVectorLabels();
                if (QSet<QString>(labels.begin(), labels.end()).size() != labels.size())
                    out << QStringLiteral("%1: %2 tick labels repeat: %3").arg(where, QString::fromLatin1(plot->metaObject()->className()),
                                                                                QStringList(labels.begin(), labels.end()).join(QStringLiteral(", ")));
            }
    }
    return out;
}

// A walk of every screen in Chinese, for each simulated instrument, reading everything a
// person sees: labels, buttons, items and headers, tooltips, plot axes, ticks and legends,
// and the words custom widgets paint. Only names, units, keys and file names stay Latin.
TEST(I18nWalk, InChineseEveryTextOfEveryScreenIsChineseForBothInstruments)
{
    ui::words::Translators translators;
    auto w = openInChinese(translators);
    ASSERT_TRUE(w);
    exerciseBoth(*w);
    QStringList failures;
    for (int instrument : {0, 1}) {
        w->showInstrument(instrument);
        for (const QString& screen : w->screenNames()) {
            ASSERT_TRUE(w->showScreen(screen));
            guitest::pump(150);  // plots draw on their frame timers
            failures << englishOnScreen(*w, QStringLiteral("%1 (%2)").arg(screen, instrument ? QStringLiteral("stage") : QStringLiteral("analyzer")));
        }
    }
    failures.removeDuplicates();
    for (const QString& f : failures)
        std::printf("[zh walk] %s\n", qPrintable(f));
    translators.setLanguage(QStringLiteral("en"));
    EXPECT_TRUE(failures.isEmpty()) << failures.size() << " English texts; the first:\n"
                                    << failures.mid(0, 40).join(QLatin1Char('\n')).toStdString();
}

/// Every screen of `w` for each instrument in turn, with what reads as English on each.
QStringList walkBothInstruments(app::MainWindow& w)
{
    QStringList failures;
    for (int instrument : {0, 1}) {
        w.showInstrument(instrument);
        for (const QString& screen : w.screenNames()) {
            if (!w.showScreen(screen))
                continue;
            guitest::pump(150);  // plots draw on their frame timers
            failures << englishOnScreen(w, QStringLiteral("%1 (%2)").arg(screen, instrument ? QStringLiteral("stage") : QStringLiteral("analyzer")));
        }
    }
    failures.removeDuplicates();
    return failures;
}

// The session that found the English: Chinese chosen at run time, every screen already built
// and shown in English, plots already drawn.
TEST(I18nWalk, AfterASwitchToChineseEveryTextOfEveryScreenIsChinese)
{
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("en")));
    app::MainWindowOptions options = guitest::testWindowOptions();
    options.translators = &translators;
    auto w = guitest::openReadyWindow(QSize(1366, 768), options);
    ASSERT_TRUE(w);
    exerciseBoth(*w);
    for (int instrument : {0, 1}) {
        w->showInstrument(instrument);
        for (const QString& screen : w->screenNames()) {
            ASSERT_TRUE(w->showScreen(screen));
            guitest::pump(60);
        }
    }
    chooseLanguage(*w, QStringLiteral("zh_CN"));
    const QStringList failures = walkBothInstruments(*w);
    for (const QString& f : failures)
        std::printf("[zh switch walk] %s\n", qPrintable(f));
    chooseLanguage(*w, QStringLiteral("en"));
    EXPECT_TRUE(failures.isEmpty()) << failures.size() << " English texts; the first:\n"
                                    << failures.mid(0, 40).join(QLatin1Char('\n')).toStdString();
}

TEST(I18nWalk, TheJogButtonsReadHomeAndGoAgainAfterChineseAndBack)
{
    ui::words::Translators translators;
    auto w = openInChinese(translators);
    ASSERT_TRUE(w);
    chooseLanguage(*w, QStringLiteral("en"));
    for (int i = 0; i < 2; ++i) {
        QStringList buttons;
        for (auto* b : w->jogScreen(i)->findChildren<QPushButton*>())
            buttons << b->text();
        const int axes = static_cast<int>(w->jogScreen(i)->findChildren<ui::AxisRow*>().size());
        EXPECT_EQ(buttons.count(QStringLiteral("Home")), axes) << buttons.join(QStringLiteral(", ")).toStdString();
        EXPECT_EQ(buttons.count(QStringLiteral("Go")), axes) << buttons.join(QStringLiteral(", ")).toStdString();
        EXPECT_FALSE(buttons.contains(QStringLiteral("home")) || buttons.contains(QStringLiteral("move")))
            << buttons.join(QStringLiteral(", ")).toStdString();
    }
}

} // namespace
