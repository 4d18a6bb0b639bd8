// A script cannot take the bench while the operator runs a test on the Calibration
// screen (it could before: the screen's runs were not among the operator's jobs, so
// control.acquire succeeded mid-run and a script's move would have spoilt the readings).
// The run is on the job board with its readings while it runs, paused included.
#include "api_script.h"
#include "gui_window.h"

#include "app/api/api_server.h"
#include "app/api/json_rpc.h"
#include "device/link/simulated_link.h"
#include "widgets/calibration/calibration_screen.h"
#include "widgets/calibration/test_form.h"

#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

const app::api::Job* calibrationJob(app::MainWindow& w)
{
    for (const auto& j : w.api()->server()->jobs().all())
        if (j.kind == QLatin1String("calibration screen"))
            return &j;
    return nullptr;
}

TEST(ApiCalibrationBusy, AScriptIsRefusedWhileTheOperatorsAccuracyRunRunsOrWaitsPaused)
{
    QTemporaryDir dir;
    const app::MainWindowOptions options = guitest::apiWindowOptions(dir.filePath(QStringLiteral("api.sock")));
    const auto window = guitest::openReadyWindow(QSize(1366, 740), options);
    ASSERT_TRUE(window);
    app::MainWindow& w = *window;
    ASSERT_NE(w.api()->server(), nullptr) << w.api()->startError().toStdString();
    ASSERT_TRUE(w.showScreen(QStringLiteral("calibration")));
    ui::CalibrationScreen* screen = w.calibrationScreen();
    screen->setInstrument(1);
    screen->setOutputFolder(dir.filePath(QStringLiteral("runs")));
    dev::Instrument* stage = w.stage()->instrument();
    auto* link = qobject_cast<dev::SimulatedLink*>(w.stage()->link());
    ASSERT_NE(link, nullptr);
    link->host().setTimeScale(20);  // homing crosses the travel at search speed
    stage->home(0);
    ASSERT_TRUE(guitest::waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed
                                             && stage->status().axes[1].homed && !stage->status().anyMoving(); },
                                 60000));
    link->host().setTimeScale(1);
    motion::metrology::AxisTest t;
    t.name = "busy-x";
    t.axis = "X";
    t.targetsMm = {20, 21, 22};
    t.cycles = 2;
    t.feedMmS = 10;
    t.overrunMm = 0.5;
    t.dwellS = 0.05;
    t.settle = {1, 0.05, 2};
    screen->form()->setTest(t);
    guitest::pump(20);
    ASSERT_TRUE(screen->run());
    ASSERT_TRUE(guitest::waitFor([&] { return screen->runner() && screen->runner()->readingsTaken() >= 1; }, 20000));
    EXPECT_TRUE(screen->busy());

    guitest::Script script(options.api.socketPath);
    const auto client = QJsonObject{{QStringLiteral("client"), QStringLiteral("notebook")}};
    QJsonObject answer = script.call(QStringLiteral("control.acquire"), client);
    EXPECT_EQ(guitest::errorCode(answer), app::api::code::kBusy) << QJsonDocument(answer).toJson().toStdString();
    EXPECT_TRUE(answer.value(QStringLiteral("error")).toObject().value(QStringLiteral("message")).toString().contains(
        QStringLiteral("Calibration screen")));
    const app::api::Job* job = calibrationJob(w);
    ASSERT_NE(job, nullptr) << "the operator's run is on the job board";
    EXPECT_EQ(job->instrument, QStringLiteral("stage"));
    EXPECT_EQ(job->state, QStringLiteral("running"));
    ASSERT_TRUE(guitest::waitFor([&] { return calibrationJob(w)->progress.value(QStringLiteral("readings_taken")).toInt() >= 1; }, 5000));
    EXPECT_EQ(calibrationJob(w)->progress.value(QStringLiteral("readings")).toInt(), 12);

    // Paused part-way the bench is still the operator's.
    screen->pause();
    ASSERT_TRUE(guitest::waitFor([&] { return screen->runner()->state() == dev::jobs::AccuracyRunner::State::Paused; }, 10000));
    answer = script.call(QStringLiteral("control.acquire"), client);
    EXPECT_EQ(guitest::errorCode(answer), app::api::code::kBusy);

    // Aborted, the board says so and a script may take the bench.
    screen->abort();
    ASSERT_TRUE(guitest::waitFor([&] { return !screen->busy(); }, 10000));
    EXPECT_EQ(calibrationJob(w)->state, QStringLiteral("stopped"));
    answer = script.call(QStringLiteral("control.acquire"), client);
    EXPECT_FALSE(answer.value(QStringLiteral("result")).toObject().value(QStringLiteral("lease")).toString().isEmpty())
        << QJsonDocument(answer).toJson().toStdString();
}

} // namespace
