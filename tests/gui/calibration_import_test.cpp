// An interferometer's capture imported on the Calibration screen, as a person does it
// after the run: Import capture… asks for the run's target sequence and the export,
// and the figures, the readings beside the sequence and the result appear; an export
// that does not match the run's stops is refused naming the line, with nothing written;
// readings already beside the sequence are replaced only when the operator says so.
#include "app/gui/main_window.h"
#include "device/files/accuracy/accuracy_test_file.h"
#include "device/files/accuracy/interferometer_csv.h"
#include "device/files/text_file.h"
#include "gui_window.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/calibration/test_form.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QPushButton>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using guitest::pump;

namespace {

QString example(const char* name) { return QStringLiteral(BP_SOURCE_DIR "/resources/examples/") + QLatin1String(name); }

class CalibrationImport : public ::testing::Test {
protected:
    void SetUp() override
    {
        w = guitest::openReadyWindow(QSize(1366, 768));
        ASSERT_NE(w, nullptr);
        ASSERT_TRUE(w->showScreen(QStringLiteral("calibration")));
        screen = w->calibrationScreen();
        ASSERT_NE(screen, nullptr);
        screen->setInstrument(1);
        QObject::connect(screen, &ui::CalibrationScreen::problem, [this](const QString& m) { problems << m; });
        sequence = dir.filePath(QStringLiteral("stage-x.targets.csv"));
        capture = dir.filePath(QStringLiteral("xl80-export.csv"));
        ASSERT_TRUE(QFile::copy(example("stage-x-xl80.targets.csv"), sequence));
        ASSERT_TRUE(QFile::copy(example("stage-x-xl80.interferometer.csv"), capture));
        screen->form()->setTest(xl80Test());
        pump(20);
    }
    /// The test the example capture is the run of, with a tolerance it fails: the result
    /// is judged against the test on screen.
    static motion::metrology::AxisTest xl80Test()
    {
        std::string text;
        motion::msg::Message error;
        EXPECT_TRUE(dev::files::readText(example("stage-x-xl80.accuracy-test.json"), &text, &error));
        const auto read = dev::files::accuracy::accuracyTestFromJson(text, "stage-x-xl80.accuracy-test.json");
        EXPECT_TRUE(read.test);
        auto t = read.test ? std::get<motion::metrology::AxisTest>(*read.test) : motion::metrology::AxisTest{};
        t.tolerances.aMm = 0.001;
        return t;
    }
    QPushButton* importButton() { return screen->findChild<QPushButton*>(QStringLiteral("calibrationImport")); }

    QTemporaryDir dir;
    std::unique_ptr<app::MainWindow> w;
    ui::CalibrationScreen* screen = nullptr;
    QString sequence, capture;
    QStringList problems;
};

TEST_F(CalibrationImport, TheButtonAsksForTheSequenceAndTheExportAndShowsTheFigures)
{
    QList<ui::CalibrationScreen::FileAction> asked;
    screen->setFileChooser([&](ui::CalibrationScreen::FileAction a, const QString&, const QString&) {
        asked << a;
        return a == ui::CalibrationScreen::FileAction::OpenSequence ? sequence : capture;
    });
    ASSERT_NE(importButton(), nullptr);
    ASSERT_TRUE(importButton()->isEnabled()) << importButton()->toolTip().toStdString();
    EXPECT_GE(importButton()->width(), importButton()->sizeHint().width()) << "its words are not cut at 1366 × 768";
    importButton()->click();
    ASSERT_EQ(asked.size(), 2);
    EXPECT_EQ(asked[0], ui::CalibrationScreen::FileAction::OpenSequence);
    EXPECT_EQ(asked[1], ui::CalibrationScreen::FileAction::OpenCapture);
    ASSERT_TRUE(screen->latest()) << problems.join(QLatin1Char('\n')).toStdString();
    EXPECT_TRUE(problems.isEmpty()) << problems.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(screen->latest()->reference, "interferometer");
    EXPECT_EQ(screen->latest()->axis, "X");
    EXPECT_EQ(screen->latest()->tolerances.aMm, 0.001);
    // The figures are the capture's: evaluated here from the same files, they agree.
    const auto stops = dev::files::accuracy::loadTargetSequence(sequence);
    const auto readings = dev::files::accuracy::loadInterferometerExport(capture, stops.stops);
    ASSERT_TRUE(readings.ok());
    const auto expected = motion::metrology::evaluate(readings.readings);
    EXPECT_NEAR(*screen->latest()->evaluation.figures.aMm, *expected.figures.aMm, 1e-9);
    EXPECT_GT(*expected.figures.aMm, 0.001) << "the example is one the tight tolerance fails";
    EXPECT_TRUE(screen->figuresText().contains(QStringLiteral("A\t"))) << screen->figuresText().toStdString();
    // Beside the sequence, as `accuracy import` writes them.
    EXPECT_TRUE(QFileInfo::exists(dir.filePath(QStringLiteral("stage-x.readings.csv"))));
    EXPECT_TRUE(QFileInfo::exists(dir.filePath(QStringLiteral("stage-x.accuracy-result.json"))));
}

TEST_F(CalibrationImport, AnExportThatDoesNotMatchTheStopsIsRefusedAndNothingIsWritten)
{
    std::string text;
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::readText(capture, &text, &error));
    text = text.substr(0, text.rfind('\n', text.size() - 2) + 1);  // the last reading is missing
    QFile f(capture);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
    f.write(text.data(), static_cast<qint64>(text.size()));
    f.close();
    EXPECT_FALSE(screen->importCapture(sequence, capture));
    ASSERT_FALSE(problems.isEmpty());
    EXPECT_TRUE(problems.last().contains(QStringLiteral("xl80-export.csv"))) << problems.last().toStdString();
    EXPECT_TRUE(problems.last().contains(QStringLiteral("nothing was imported"))) << problems.last().toStdString();
    EXPECT_FALSE(screen->latest());
    EXPECT_FALSE(QFileInfo::exists(dir.filePath(QStringLiteral("stage-x.readings.csv"))));
}

TEST_F(CalibrationImport, ACaptureOfAnotherTestIsRefusedNamingWhereItDiffers)
{
    // This file's first version imported the 3-target capture against a 5-target test on
    // screen: the figures were filed under a test that never ran.
    motion::metrology::AxisTest other = xl80Test();
    other.targetsMm = {10, 20.59, 30, 40.41, 50};
    screen->form()->setTest(other);
    pump(20);
    EXPECT_FALSE(screen->importCapture(sequence, capture));
    ASSERT_FALSE(problems.isEmpty());
    EXPECT_TRUE(problems.last().contains(QStringLiteral("stage-x.targets.csv is not the run of the axis test on screen")))
        << problems.last().toStdString();
    EXPECT_TRUE(problems.last().contains(QStringLiteral("the sequence has 30 stops"))) << problems.last().toStdString();
    // As many stops, one target 10 µm off: the first stop that differs is named.
    other.targetsMm = {10, 20.6, 30};
    screen->form()->setTest(other);
    pump(20);
    EXPECT_FALSE(screen->importCapture(sequence, capture));
    // The sequence's second stop is the one named: where it is and how it was approached.
    EXPECT_TRUE(problems.last().contains(QStringLiteral("the sequence's stop %1 is at 20.590 mm, approached up in cycle 1").arg(2)))
        << problems.last().toStdString();
    EXPECT_FALSE(screen->latest());
    EXPECT_FALSE(QFileInfo::exists(dir.filePath(QStringLiteral("stage-x.readings.csv"))));
}

TEST_F(CalibrationImport, ReadingsAlreadyBesideTheSequenceAreReplacedOnlyWhenTheOperatorSaysSo)
{
    const QString readings = dir.filePath(QStringLiteral("stage-x.readings.csv"));
    QFile f(readings);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("kept\n");
    f.close();
    QStringList questions;
    bool answer = false;
    screen->setConfirm([&](const QString& q) {
        questions << q;
        return answer;
    });
    EXPECT_FALSE(screen->importCapture(sequence, capture));
    ASSERT_EQ(questions.size(), 1);
    EXPECT_TRUE(questions[0].contains(readings)) << questions[0].toStdString();
    std::string text;
    motion::msg::Message error;
    ASSERT_TRUE(dev::files::readText(readings, &text, &error));
    EXPECT_EQ(text, "kept\n");
    answer = true;
    EXPECT_TRUE(screen->importCapture(sequence, capture)) << problems.join(QLatin1Char('\n')).toStdString();
    ASSERT_TRUE(dev::files::readText(readings, &text, &error));
    EXPECT_NE(text, "kept\n");
}

TEST_F(CalibrationImport, OnlyAnAxisTestTakesACapture)
{
    motion::metrology::CircularTest circle;
    circle.centreMm = {50, 50};
    circle.radiusMm = 10;
    circle.feedMmS = 10;
    screen->form()->setTest(circle);
    pump(20);
    EXPECT_FALSE(importButton()->isEnabled());
    EXPECT_TRUE(importButton()->toolTip().contains(QStringLiteral("axis test"))) << importButton()->toolTip().toStdString();
    EXPECT_FALSE(screen->importCapture(sequence, capture));
}

} // namespace
