// The Scan screen driven as a person would: typing and drawing the region, the
// tile count and time that follow, problems shown and Run held back, plans saved
// and opened, a run on the simulated stage with progress and exports, Esc.
#include "app/gui/instrument_session.h"
#include "app/gui/main_window.h"
#include "device/files/scan_exports.h"
#include "device/jobs/scan_runner.h"
#include "device/link/simulated_link.h"
#include "gui_wait.h"
#include "../device/pseudo_translation.h"
#include "widgets/scan/scan_plan_form.h"
#include "widgets/scan/scan_screen.h"
#include "widgets/scan/scan_stage_map.h"

#include <QComboBox>
#include <QDir>
#include "widgets/common/number_field.h"
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <gtest/gtest.h>

using guitest::pump;
using guitest::waitFor;
using namespace motion::scan;

namespace {

class ScanScreenTest : public ::testing::Test {
protected:
    void SetUp() override
    {
        app::MainWindowOptions o;
        o.persistSettings = false;
        o.confirmDialogs = false;
        w = std::make_unique<app::MainWindow>(o);
        w->resize(1500, 950);
        w->show();
        ASSERT_TRUE(w->showScreen(QStringLiteral("scan")));
        ASSERT_TRUE(waitFor([&] { return w->stage()->instrument()->isReady(); }, 5000));
        screen = w->scanScreen();
        ASSERT_NE(screen, nullptr);
    }
    template <class T>
    T* child(const char* name) { return screen->findChild<T*>(QLatin1String(name)); }
    void setSpin(const char* name, double v)
    {
        auto* s = child<ui::NumberField>(name);
        ASSERT_NE(s, nullptr) << name;
        s->setValue(v);
    }
    void settle() { pump(80); }  // the screen replans on a short timer
    QString summary() { return child<QLabel>("scanSummary")->text(); }

    std::unique_ptr<app::MainWindow> w;
    ui::ScanScreen* screen = nullptr;
};

} // namespace

TEST_F(ScanScreenTest, TypedRegionAndFieldGiveTheTileCountAndTime)
{
    child<QComboBox>("scanFovFrom")->setCurrentIndex(1);  // field size
    setSpin("scanFieldW", 1.0);
    setSpin("scanFieldH", 1.0);
    setSpin("scanOverlapX", 10);
    setSpin("scanOverlapY", 10);
    setSpin("scanX0", 20);
    setSpin("scanY0", 20);
    setSpin("scanX1", 30);  // (10 − 1)/0.9 = 10 steps: 11 columns
    setSpin("scanY1", 24.6);  // (4.6 − 1)/0.9 = 4: 5 rows
    settle();
    EXPECT_TRUE(summary().startsWith(QStringLiteral("55 tiles (11 × 5)"))) << summary().toStdString();
    EXPECT_TRUE(summary().contains(QStringLiteral("step 0.900 × 0.900 mm"))) << summary().toStdString();
    EXPECT_EQ(screen->layout().tiles.size(), 55u);
    EXPECT_GT(screen->estimate().totalS, 55 * (0.02 + 0.05));
    EXPECT_TRUE(child<QPushButton>("scanRun")->isEnabled());
}

TEST_F(ScanScreenTest, ProblemsAreShownAndRunIsHeldBack)
{
    setSpin("scanX1", child<ui::NumberField>("scanX0")->valueOr(0));  // zero width
    settle();
    EXPECT_TRUE(screen->problemsText().contains(QStringLiteral("zero size"))) << screen->problemsText().toStdString();
    EXPECT_FALSE(child<QPushButton>("scanRun")->isEnabled());
    EXPECT_TRUE(screen->layout().tiles.empty());
    setSpin("scanX0", 90);
    setSpin("scanX1", 120);  // beyond the travel
    settle();
    EXPECT_TRUE(screen->problemsText().contains(QStringLiteral("beyond the stage's travel"))) << screen->problemsText().toStdString();
    QStringList problems;
    QObject::connect(screen, &ui::ScanScreen::problem, [&](const QString& m) { problems << m; });
    EXPECT_FALSE(screen->run());
    ASSERT_FALSE(problems.isEmpty());
}

TEST_F(ScanScreenTest, DraggingOnTheMapDrawsTheRegion)
{
    ui::ScanStageMap* map = screen->map();
    map->fitStage();
    const QPoint a = map->toWidget({30, 60}).toPoint(), b = map->toWidget({50, 40}).toPoint();
    QTest::mousePress(map, Qt::LeftButton, Qt::NoModifier, a);
    QTest::mouseMove(map, (a + b) / 2);
    QTest::mouseMove(map, b);
    QTest::mouseRelease(map, Qt::LeftButton, Qt::NoModifier, b);
    settle();
    const ScanPlan p = screen->plan();
    ASSERT_EQ(p.region.kind, RegionKind::Corners);
    const Rect r = regionBounds(p.region);
    const double pxMm = 1.0 / (map->toWidget({1, 0}).x() - map->toWidget({0, 0}).x());
    EXPECT_NEAR(r.x0Mm, 30, 2 * pxMm);
    EXPECT_NEAR(r.x1Mm, 50, 2 * pxMm);
    EXPECT_NEAR(r.y0Mm, 40, 2 * pxMm);
    EXPECT_NEAR(r.y1Mm, 60, 2 * pxMm);
    EXPECT_FALSE(screen->layout().tiles.empty());
}

TEST_F(ScanScreenTest, ClickingCornersDrawsAPolygon)
{
    child<QComboBox>("scanRegionKind")->setCurrentIndex(2);
    ui::ScanStageMap* map = screen->map();
    ASSERT_EQ(map->drawMode(), ui::ScanStageMap::DrawMode::Polygon);
    map->fitStage();
    for (Point2 c : {Point2{20, 20}, Point2{60, 25}, Point2{45, 70}})
        QTest::mouseClick(map, Qt::LeftButton, Qt::NoModifier, map->toWidget(c).toPoint());
    QTest::mouseDClick(map, Qt::LeftButton, Qt::NoModifier, map->toWidget({45, 70}).toPoint());
    settle();
    const ScanPlan p = screen->plan();
    ASSERT_EQ(p.region.kind, RegionKind::Polygon);
    ASSERT_EQ(p.region.vertices.size(), 3u) << "the double-click closes without adding a corner twice";
    EXPECT_NEAR(p.region.vertices[1].xMm, 60, 0.5);
    EXPECT_TRUE(child<QLineEdit>("scanVertices")->text().contains(QLatin1String(";")));
    EXPECT_TRUE(summary().contains(QStringLiteral("in the outline"))) << summary().toStdString();
}

TEST_F(ScanScreenTest, PlansAreSavedAndOpened)
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("mine.scan.json"));
    screen->setFileChooser([&](ui::ScanScreen::FileAction, const QString&, const QString&) { return path; });
    setSpin("scanOverlapX", 33);
    child<QComboBox>("scanOrder")->setCurrentIndex(3);  // column by column
    settle();
    ASSERT_TRUE(screen->savePlan(path));
    screen->setPlan(ScanPlan{});
    EXPECT_NE(screen->plan().order, ScanOrder::Columns);
    ASSERT_TRUE(screen->openPlan(path));
    EXPECT_EQ(screen->plan().order, ScanOrder::Columns);
    EXPECT_NEAR(screen->plan().overlapX, 0.33, 1e-9);
    QFile bad(dir.filePath(QStringLiteral("bad.scan.json")));
    ASSERT_TRUE(bad.open(QIODevice::WriteOnly));
    bad.write("{\"schema\": \"benchpilot.scan-plan\", \"version\": 1, \"overlap\": 2}");
    bad.close();
    QStringList problems;
    QObject::connect(screen, &ui::ScanScreen::problem, [&](const QString& m) { problems << m; });
    EXPECT_FALSE(screen->openPlan(bad.fileName()));
    ASSERT_FALSE(problems.isEmpty());
    EXPECT_TRUE(problems.last().contains(QStringLiteral("bad.scan.json:1:"))) << problems.last().toStdString();
    EXPECT_EQ(screen->plan().order, ScanOrder::Columns) << "a bad file leaves the plan as it was";
}

TEST_F(ScanScreenTest, APlanNamingACameraProfileKeepsTheLinkWhenSavedAgain)
{
    QTemporaryDir dir;
    ASSERT_TRUE(QFile::copy(QStringLiteral(BP_SOURCE_DIR "/resources/examples/sim-stage-camera.camera-profile.json"),
                            dir.filePath(QStringLiteral("scope.camera-profile.json"))));
    ScanPlan named = screen->plan();
    named.camera.profile = "scope.camera-profile.json";
    screen->setPlan(named);
    settle();
    const QString path = dir.filePath(QStringLiteral("linked.scan.json"));
    ASSERT_TRUE(screen->savePlan(path));
    screen->setPlan(ScanPlan{});
    EXPECT_TRUE(screen->plan().camera.profile.empty()) << "a new plan names no profile";
    ASSERT_TRUE(screen->openPlan(path));
    EXPECT_EQ(screen->plan().camera.profile, "scope.camera-profile.json") << "saving from the screen dropped the plan's profile";
    EXPECT_NEAR(screen->plan().camera.rotationDeg, 0.42, 1e-9) << "the profile's rotation";
    EXPECT_TRUE(child<QLabel>("scanCameraInfo")->text().contains(QStringLiteral("scope.camera-profile.json")))
        << child<QLabel>("scanCameraInfo")->text().toStdString();
    // Saved again from the screen: still linked.
    ASSERT_TRUE(screen->savePlan(path));
    QFile saved(path);
    ASSERT_TRUE(saved.open(QIODevice::ReadOnly));
    EXPECT_TRUE(saved.readAll().contains("\"profile\": \"scope.camera-profile.json\""));
}

TEST_F(ScanScreenTest, RunsOnTheStageWithProgressAndExports)
{
    dev::Instrument* stage = w->stage()->instrument();
    auto* link = qobject_cast<dev::SimulatedLink*>(w->stage()->link());
    ASSERT_NE(link, nullptr);
    // Homing crosses the stage at search speed; 10x keeps the simulated plant inside what one
    // core computes in real time on a loaded machine (at 20x HOME went unanswered now and then).
    link->host().setTimeScale(10);
    std::optional<dev::RequestError> homeError;
    stage->home(0, [&](const std::optional<dev::RequestError>& e) { homeError = e; });
    ASSERT_TRUE(waitFor([&] { return stage->status().axes.size() >= 2 && stage->status().axes[0].homed && stage->status().axes[1].homed
                                     && !stage->status().anyMoving(); }, 30000))
        << (homeError ? motion::msg::debugString(homeError->message) : std::string("home not refused")) << "; X homed "
        << stage->status().axes.value(0).homed << " moving " << stage->status().axes.value(0).moving << ", Y homed "
        << stage->status().axes.value(1).homed << " moving " << stage->status().axes.value(1).moving;
    link->host().setTimeScale(1);
    QTemporaryDir dir;
    ScanPlan p;
    p.region.cornerA = {1, 1};
    p.region.cornerB = {4.7, 3.8};  // 4 × 3 fields of 1 mm, near home
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1;
    p.exposureS = 0.01;
    screen->setPlan(p);
    screen->setOutputFolder(dir.path());
    int asked = 0;
    screen->setConfirm([&](const QString&) { return ++asked, true; });
    ASSERT_TRUE(screen->run());
    EXPECT_FALSE(child<QPushButton>("scanRun")->isEnabled()) << "no second run while one is going";
    EXPECT_FALSE(screen->form()->isEnabled()) << "the plan is locked while it runs";
    for (auto* b : screen->findChildren<QPushButton*>()) {
        if (b->text() == QStringLiteral("Open plan…") || b->text() == QStringLiteral("New")) {
            EXPECT_FALSE(b->isEnabled()) << "no other plan opens over a running one";
        }
    }
    ASSERT_TRUE(waitFor([&] { return screen->runner()->state() == dev::jobs::ScanRunner::State::Finished; }, 30000));
    auto* progress = child<QProgressBar>("scanProgress");
    EXPECT_EQ(progress->value(), 12);
    EXPECT_EQ(progress->maximum(), 12);
    EXPECT_EQ(asked, 0) << "a run of a few seconds goes without asking";
    for (const char* f : {dev::files::scan::kTileConfigFile, dev::files::scan::kPositionsFile, dev::files::scan::kCsvFile})
        EXPECT_TRUE(QFile::exists(QDir(dir.path()).filePath(QLatin1String(f)))) << f;
    EXPECT_TRUE(screen->form()->isEnabled());
}

TEST_F(ScanScreenTest, AnotherPlansRunLogOffersAFreshStartInAnyLanguage)
{
    QTemporaryDir dir;
    ScanPlan p;
    p.region.cornerA = {1, 1};
    p.region.cornerB = {3, 3};
    p.camera.source = FieldSource::Direct;
    p.camera.fieldWidthMm = p.camera.fieldHeightMm = 1;
    screen->setPlan(p);
    screen->setOutputFolder(dir.path());
    QStringList asked, problems;
    bool answer = false;
    screen->setConfirm([&](const QString& q) {
        asked << q;
        return answer;
    });
    QObject::connect(screen, &ui::ScanScreen::problem, [&](const QString& m) { problems << m; });
    EXPECT_FALSE(screen->run()) << "the stage is not homed; the run log of this plan is in the folder now";
    EXPECT_TRUE(asked.isEmpty());
    auto logs = [&] { return QDir(dir.path()).entryList({QStringLiteral("scan-run*.jsonl")}).size(); };
    ASSERT_EQ(logs(), 1);

    // Another plan, same folder, the runner's messages translated.
    const i18ntest::PseudoTranslation translated({QStringLiteral("ui::words::ScanWords")});
    p.overlapX = 0.3;
    screen->setPlan(p);
    settle();
    problems.clear();
    EXPECT_FALSE(screen->run());
    ASSERT_EQ(asked.size(), 1) << "a fresh start is offered: " << problems.join(QLatin1Char(' ')).toStdString();
    EXPECT_TRUE(asked[0].contains(QStringLiteral("Start this scan anew"))) << asked[0].toStdString();
    EXPECT_TRUE(asked[0].contains(QStringLiteral("dífférént scán"))) << "with the translated reason: " << asked[0].toStdString();
    ASSERT_FALSE(problems.isEmpty()) << "declined: the reason is shown";
    EXPECT_EQ(logs(), 1) << "declined: the other plan's log is left alone";

    answer = true;
    problems.clear();
    EXPECT_FALSE(screen->run()) << "accepted, then held back by the unhomed stage";
    EXPECT_EQ(asked.size(), 2);
    EXPECT_EQ(logs(), 2) << "the old log is kept under another name";
    ASSERT_FALSE(problems.isEmpty());
    EXPECT_TRUE(problems.last().contains(QStringLiteral("cannot start"))) << problems.last().toStdString();
}

TEST_F(ScanScreenTest, EscapeOnTheMapIsStillTheEStop)
{
    dev::Instrument* stage = w->stage()->instrument();
    screen->map()->setFocus();
    QTest::keyClick(screen->map(), Qt::Key_Escape);
    ASSERT_TRUE(waitFor([&] { return stage->status().estop; }, 3000));
    w->resetEStop();
    ASSERT_TRUE(waitFor([&] { return !stage->status().estop; }, 3000));
}

