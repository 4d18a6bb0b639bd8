// The operator and a script on one simulated stage (docs/api.md, "Control"): while the
// script holds control the window says who and since when with Take back, the
// operator's motion controls do not interleave with it, and Take back stops the
// script within one call. The window still fits 1366 × 768 with the strip showing.
#include "api_script.h"
#include "gui_window.h"

#include "app/api/api_server.h"
#include "app/api/json_rpc.h"
#include "app/gui/api_panel.h"
#include "widgets/event_log.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QLayout>
#include <QLocalSocket>
#include <QPushButton>
#include <QToolButton>
#include <QTableWidget>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace {

using guitest::Script;
using guitest::errorCode;


TEST(ApiTakeBack, TheWindowSaysWhoHasControlAndTakeBackStopsTheScriptWithinOneCall)
{
    QTemporaryDir dir;
    const app::MainWindowOptions options = guitest::apiWindowOptions(dir.filePath(QStringLiteral("api.sock")));
    const auto window = guitest::openReadyWindow(QSize(1366, 740), options);
    ASSERT_TRUE(window);
    app::MainWindow& w = *window;
    ASSERT_NE(w.api()->server(), nullptr) << w.api()->startError().toStdString();
    app::ApiControlStrip* strip = w.api()->strip();
    ASSERT_NE(strip, nullptr);
    EXPECT_FALSE(strip->isVisible()) << "nothing to say while the operator has control";

    Script script(options.api.socketPath);
    const QJsonObject acquired = script.call(QStringLiteral("control.acquire"), QJsonObject{{QStringLiteral("client"), QStringLiteral("plate-then-image")}});
    const QString lease = acquired.value(QStringLiteral("result")).toObject().value(QStringLiteral("lease")).toString();
    ASSERT_FALSE(lease.isEmpty());
    QTimer beat;
    QObject::connect(&beat, &QTimer::timeout, [&] { script.heartbeat(lease); });
    beat.start(100);
    EXPECT_TRUE(strip->isVisible());
    EXPECT_TRUE(strip->text().contains(QStringLiteral("plate-then-image"))) << strip->text().toStdString();
    EXPECT_TRUE(strip->text().contains(QStringLiteral("since"))) << strip->text().toStdString();
    // It fits with the strip showing: the strip shares the banner's row and adds neither
    // height nor width to the window (tests/gui/main_window_size_test.cpp checks the rest).
    w.layout()->activate();
    const QSize withStrip = w.minimumSizeHint();
    strip->hide();
    w.layout()->activate();
    const QSize without = w.minimumSizeHint();
    strip->show();
    w.layout()->activate();
    EXPECT_LE(withStrip.height(), without.height()) << "the strip adds no height";
    EXPECT_LE(withStrip.width(), without.width()) << "the strip adds no width";
    if (qEnvironmentVariableIsSet("BP_API_SHOT")) {
        w.api()->statusButton()->click();
        guitest::pump(300);
        w.grab().save(qEnvironmentVariable("BP_API_SHOT"));
        w.api()->panel()->window()->grab().save(qEnvironmentVariable("BP_API_SHOT") + QStringLiteral(".panel.png"));
    }
    std::fprintf(stderr, "minimum with the strip %dx%d, without %dx%d\n", withStrip.width(), withStrip.height(), without.width(), without.height());
    // The panel lists the client as in control.
    bool listed = false;
    QTableWidget* clients = w.api()->panel()->clientsTable();
    for (int r = 0; r < clients->rowCount(); ++r)
        listed = listed || clients->item(r, 0)->text().contains(QStringLiteral("in control"));
    EXPECT_TRUE(listed);

    // The script jogs X; the operator's own jog does not interleave with it.
    const QJsonObject jog = script.call(QStringLiteral("device.jog"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")},
                                                                                   {QStringLiteral("axis"), QStringLiteral("X")},
                                                                                   {QStringLiteral("velocity"), 2},
                                                                                   {QStringLiteral("lease"), lease}});
    ASSERT_TRUE(jog.contains(QStringLiteral("result"))) << QJsonDocument(jog).toJson().toStdString();
    dev::Instrument* screens = w.api()->screenInstrument(1);
    std::optional<dev::RequestError> refused;
    bool answered = false;
    screens->jogStep(1, 1.0, 0, [&](const std::optional<dev::RequestError>& e) {
        refused = e;
        answered = true;
    });
    ASSERT_TRUE(answered);
    ASSERT_TRUE(refused.has_value()) << "the operator's controls ask first while a script has control";
    EXPECT_EQ(refused->message.id, "request.bench_held");
    EXPECT_EQ(refused->message.text("holder").find("plate-then-image") != std::string::npos, true) << motion::msg::debugString(refused->message);
    ASSERT_TRUE(guitest::waitFor([&] { return w.stage()->instrument()->status().axes.value(0).moving; }, 5000));

    // Take back: the jog stops at once, the script's next call is refused.
    strip->takeBackButton()->click();
    EXPECT_FALSE(w.stage()->instrument()->isJogging(0));
    EXPECT_FALSE(strip->isVisible());
    const QJsonObject next = script.call(QStringLiteral("device.jog"), QJsonObject{{QStringLiteral("instrument"), QStringLiteral("stage")},
                                                                                    {QStringLiteral("axis"), QStringLiteral("X")},
                                                                                    {QStringLiteral("velocity"), 2},
                                                                                    {QStringLiteral("lease"), lease}});
    EXPECT_EQ(errorCode(next), app::api::code::kNotInControl);
    EXPECT_TRUE(guitest::waitFor([&] { return !w.stage()->instrument()->status().axes.value(0).moving; }, 5000));
    // And the operator's controls act again.
    answered = false;
    refused.reset();
    screens->jogStep(0, 0.1, 0, [&](const std::optional<dev::RequestError>& e) {
        refused = e;
        answered = true;
    });
    EXPECT_TRUE(guitest::waitFor([&] { return answered; }, 5000));
    EXPECT_FALSE(refused.has_value()) << (refused ? motion::msg::debugString(refused->message) : std::string());
    // The event log has the script's calls with its name.
    bool logged = false;
    for (int r = 0; r < w.eventLog()->rowCount(); ++r)
        logged = logged || (w.eventLog()->rowText(r).contains(QStringLiteral("plate-then-image")) && w.eventLog()->rowText(r).contains(QStringLiteral("device.jog")));
    EXPECT_TRUE(logged);
}

TEST(ApiTakeBack, NoApiWasAskedForNoneRuns)
{
    app::MainWindow w(guitest::testWindowOptions());
    EXPECT_EQ(w.api()->server(), nullptr);
    EXPECT_EQ(w.api()->strip(), nullptr);
    // The screens' instruments pass everything through.
    EXPECT_NE(w.api()->screenInstrument(0), nullptr);
}

} // namespace
