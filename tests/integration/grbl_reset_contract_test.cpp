// What every way the GRBL client's state is reset promises, whichever path it takes (closing the
// link, losing it, a controller that resets by itself, an E-stop, an alarm): every command in
// flight is answered exactly once, no jog goes on, no MotionDone is owed afterwards, and the
// client takes the next command (or the next connection) as if fresh. A scripted controller
// holds a move unanswered and runs a jog when the path is taken.
#include "device/backends/grbl/client/grbl_client.h"
#include "grbl_script.h"
#include "motion/message_print.h"
#include "wait.h"

#include <gtest/gtest.h>

#include <algorithm>

using itest::ScriptedGrbl;
using itest::waitFor;

namespace {

enum class ResetPath { Disconnect, LinkLost, ControllerReset, EStop, Alarm };

const char* nameOf(ResetPath p)
{
    switch (p) {
    case ResetPath::Disconnect: return "disconnect";
    case ResetPath::LinkLost: return "link lost";
    case ResetPath::ControllerReset: return "controller reset";
    case ResetPath::EStop: return "estop";
    case ResetPath::Alarm: return "alarm";
    }
    return "?";
}

bool endsTheLink(ResetPath p) { return p == ResetPath::Disconnect || p == ResetPath::LinkLost; }

struct ContractRig {
    ScriptedGrbl port;
    dev::GrblClient client{dev::files::defaultProfile(dev::proto::DeviceKind::Stage), true};
    std::vector<dev::DeviceEvent> events;

    ContractRig()
    {
        QObject::connect(&client, &dev::Instrument::eventReceived, &client, [this](const dev::DeviceEvent& e) { events.push_back(e); });
        client.setTransport(&port);
    }
    ~ContractRig() { client.setTransport(nullptr); }

    bool connect()
    {
        client.connectLink();
        return waitFor([this] { return client.isReady() || client.state() == dev::LinkState::Disconnected; }, 8000) && client.isReady();
    }
    bool anyJogging() const
    {
        for (int i = 0; i < client.identity().axes.size(); ++i)
            if (client.isJogging(i))
                return true;
        return false;
    }
    int motionDoneFrom(std::size_t from) const
    {
        int n = 0;
        for (std::size_t i = from; i < events.size(); ++i)
            n += events[i].kind == dev::proto::EventKind::MotionDone;
        return n;
    }
};

} // namespace

TEST(GrblResetContract, EveryResetPathAnswersEveryCommandOnceAndLeavesNothingRunningOrOwed)
{
    for (const ResetPath path : {ResetPath::Disconnect, ResetPath::LinkLost, ResetPath::ControllerReset, ResetPath::EStop, ResetPath::Alarm}) {
        SCOPED_TRACE(nameOf(path));
        ContractRig r;
        ASSERT_TRUE(r.connect());
        r.port.report = "<Idle|MPos:0.000,0.000,0.000|FS:0,0>";

        // A move GRBL never answers, and a held jog behind it (GRBL answers in order: nothing
        // after the move is answered either).
        bool holding = false;
        r.port.hold = [&holding](const std::string& line) { return holding = holding || line.rfind("G91", 0) == 0; };
        int moveAnswers = 0;
        std::optional<dev::RequestError> moveError;
        r.client.move({{0, 5}}, true, 5, [&](const std::optional<dev::RequestError>& e) {
            ++moveAnswers;
            moveError = e;
        });
        r.client.startJog(1, 2.0);
        ASSERT_TRUE(waitFor([&] {
            bool move = false, jog = false;
            for (const auto& l : r.port.lines) {
                move = move || l.rfind("G91", 0) == 0;
                jog = jog || l.rfind("$J=", 0) == 0;
            }
            return move && jog;
        }, 3000));
        ASSERT_TRUE(r.client.isJogging(1));

        // On the paths that end the link, a status read the controller (fallen silent) never answers.
        int statusAnswers = 0;
        std::optional<dev::RequestError> statusError;
        if (endsTheLink(path)) {
            r.port.silent = true;
            r.client.readStatus([&](const std::optional<dev::RequestError>& e, const dev::InstrumentStatus&) {
                ++statusAnswers;
                statusError = e;
            });
        }

        int resetAnswers = 0;
        auto countReset = [&](const std::optional<dev::RequestError>& e) {
            ++resetAnswers;
            EXPECT_FALSE(e.has_value()) << motion::msg::debugString(e->message);
        };
        switch (path) {
        case ResetPath::Disconnect: r.client.disconnectLink(); break;
        case ResetPath::LinkLost: emit r.port.lost(motion::msg::make("link.unplugged")); break;
        case ResetPath::ControllerReset:
            r.port.hold = {};  // what it held is gone with the reset; what comes after, it answers
            r.port.push("Grbl 1.1h ['$' for help]");
            ASSERT_TRUE(waitFor([&] {
                return std::any_of(r.events.begin(), r.events.end(), [](const dev::DeviceEvent& e) { return e.detail.id == "grbl.controller_reset"; });
            }, 3000));
            break;
        case ResetPath::EStop: r.client.estop(countReset); break;
        case ResetPath::Alarm:
            // A hard limit: GRBL hears nothing but a reset, which the operator gives.
            r.port.report = "<Alarm|MPos:0.000,0.000,0.000|FS:0,0>";
            r.port.push("ALARM:1");
            ASSERT_TRUE(waitFor([&] { return r.client.alarmCode() == 1; }, 3000));
            r.client.reset(countReset);
            break;
        }
        const std::size_t after = r.events.size();

        // Whatever the path: the jog is over at once, and the move's line, gone with the link or
        // the controller's buffers, is answered once as lost.
        EXPECT_FALSE(r.anyJogging());
        ASSERT_TRUE(waitFor([&] { return moveAnswers > 0; }, 3000));
        ASSERT_TRUE(moveError.has_value());
        EXPECT_EQ(moveError->message.id, "request.abandoned") << moveError->message;
        r.port.hold = {};
        if (endsTheLink(path)) {
            // Every waiter is answered with the link's end.
            EXPECT_EQ(statusAnswers, 1);
            ASSERT_TRUE(statusError.has_value());
            EXPECT_EQ(statusError->kind, dev::RequestError::Kind::LinkDown);
            EXPECT_FALSE(r.client.isReady());
            // The next connection starts fresh.
            r.port.silent = false;
            ASSERT_TRUE(r.connect());
        } else if (path != ResetPath::ControllerReset) {
            // The soft reset this host sent is answered by the controller's banner.
            r.port.push("Grbl 1.1h ['$' for help]");
            EXPECT_TRUE(waitFor([&] { return resetAnswers == 1; }, 3000));
            if (path == ResetPath::EStop)
                r.client.reset();  // the operator clears the E-stop
            r.port.report = "<Idle|MPos:0.000,0.000,0.000|FS:0,0>";
        }
        // Idle reports: nothing is owed from before the reset, and nothing jogs.
        const int reports = 3;
        int seen = 0;
        const auto c = QObject::connect(&r.client, &dev::Instrument::statusChanged, &r.client, [&seen] { ++seen; });
        ASSERT_TRUE(waitFor([&] { return seen >= reports; }, 5000));
        QObject::disconnect(c);
        EXPECT_EQ(r.motionDoneFrom(after), 0);
        EXPECT_EQ(moveAnswers, 1);
        EXPECT_FALSE(r.anyJogging());

        // And the client takes the next command.
        std::optional<std::optional<dev::RequestError>> next;
        r.client.move({{0, 1}}, true, 5, [&](const std::optional<dev::RequestError>& e) { next = e; });
        ASSERT_TRUE(waitFor([&] { return next.has_value(); }, 3000));
        EXPECT_FALSE(next->has_value()) << (next->has_value() ? motion::msg::debugString((*next)->message) : std::string());
    }
}
