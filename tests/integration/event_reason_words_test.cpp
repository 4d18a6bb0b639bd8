// An event's reason (docs/protocol.md, "Event reasons") becomes a sentence in the
// operator's language: every reason the reference firmware sends is worded, in
// Chinese without an English word, and a reason this host does not know leaves the
// device's text to be shown instead.
#include "device/backends/benchpilot/event_reason.h"
#include "device/protocol/event_reasons.h"
#include "device/protocol/messages_compensation.h"
#include "device/protocol/messages_path.h"
#include "device/protocol/messages_tuning.h"
#include "widgets/wording/translators.h"
#include "widgets/wording/wording.h"

#include "../device/pseudo_translation.h"

#include <gtest/gtest.h>

#include <vector>

namespace {

using dev::proto::EventKind;
using dev::proto::EventReason;
namespace why = dev::proto::reason;

struct Case {
    EventKind kind;
    EventReason reason;
    std::string letter = "X";
};

/// One of each reason the simulator raises (device/sim), with values as it sends them.
std::vector<Case> everyReason()
{
    const double relay = why::kRelayTest, step = why::kStepTest;
    std::vector<Case> c = {
        {EventKind::MotionDone, {why::kAlreadyThere, {}}},
        {EventKind::HomeDone, {why::kOutsideWindow, {}}},
        {EventKind::LimitHit, {why::kHomeSwitch, {}}},
        {EventKind::LimitHit, {why::kLimitSwitch, {}}},
        {EventKind::Fault, {why::kHomeSwitchNotFound, {}}},
        {EventKind::EStop, {why::kAllHalted, {}}, ""},
        {EventKind::JogExpired, {why::kNotRefreshed, {0.2}}},
        {EventKind::LostSteps, {why::kOffCommand, {0.125}}},
        {EventKind::Reset, {why::kCleared, {}}, ""},
        {dev::proto::kEvTestEnded, {why::kSettled, {step, 0.42}}},
        {dev::proto::kEvTestEnded, {why::kCompleted, {relay, 0.061}}},
        {dev::proto::kEvTestTripped, {why::kExcursion, {step, 0.03, 0.031, 0.2, 50.01}}},
        {dev::proto::kEvTestTripped, {why::kFollowingError, {relay, 0.05, 0.06, 0.3, 49.99}}},
        {dev::proto::kEvTestTripped, {why::kDuration, {relay, 5, 50.0}}},
        {dev::proto::kEvTestAborted, {why::kOnRequest, {step}}},
        {dev::proto::kEvTestAborted, {why::kByEStop, {relay}}},
        {dev::proto::kEvTestAborted, {why::kHostSilent, {relay, 0.5}}},
        {dev::proto::kEvTestAborted, {why::kByFault, {step}}},
        {dev::proto::kEvGainsChanged, {why::kGainsSet, {0.25, 0.5, 0.03, 0}}},
        {dev::proto::kEvGainsChanged, {why::kGainsSet, {0.25, 0.5, 0.03, 1}}},
        {dev::proto::kEvGainsChanged, {why::kGainsFellBack, {0.25, 0.5, 0.03}}},
        {dev::proto::kEvCompChanged, {why::kInstalled, {1, 11, 0}}},
        {dev::proto::kEvCompChanged, {why::kInstalled, {1, 11, 1}}},
        {dev::proto::kEvCompChanged, {why::kInstalled, {2, 3, 0, 100}}},
        {dev::proto::kEvCompChanged, {why::kEnabled, {0}}},
        {dev::proto::kEvCompChanged, {why::kEnabled, {1}}},
        {dev::proto::kEvCompChanged, {why::kDisabled, {0}}},
        {dev::proto::kEvCompChanged, {why::kDisabled, {1}}},
        {EventKind::PathUnderrun, {why::kPathRan, {}}, ""},
    };
    for (std::uint8_t s = why::kStopRequest; s <= why::kWaitedMoveHitSwitch; ++s)
        c.push_back({EventKind::Stopped, {s, {}}});
    for (std::uint8_t r = 1; r <= static_cast<std::uint8_t>(dev::proto::PathReason::Cleared); ++r) {
        c.push_back({EventKind::PathHeld, {r, {}}, ""});
        c.push_back({EventKind::PathAborted, {r, {}}, ""});
    }
    return c;
}

motion::msg::Message worded(const Case& c)
{
    const auto m = dev::eventReasonMessage(c.kind, c.reason, c.letter, dev::proto::AxisUnit::Millimetre);
    return m ? *m : motion::msg::Message{};
}

} // namespace

TEST(EventReasonWords, EveryReasonTheFirmwareSendsIsASentenceInEnglishAndInChinese)
{
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
    static const QRegularExpression han(QStringLiteral("\\p{Han}"));
    for (const Case& c : everyReason()) {
        const motion::msg::Message m = worded(c);
        const std::string what = std::string(dev::proto::eventKindName(c.kind)) + " reason " + std::to_string(c.reason.code);
        ASSERT_FALSE(m.empty()) << what;
        const QString zh = ui::words::text(m), en = ui::words::englishText(m);
        EXPECT_TRUE(zh.contains(han)) << what << ": " << zh.toStdString();
        EXPECT_TRUE(i18ntest::untranslated(zh).isEmpty()) << what << ": " << zh.toStdString();
        EXPECT_FALSE(en.contains(han)) << what << ": " << en.toStdString();
        EXPECT_FALSE(en.contains(QLatin1Char('%'))) << what << ": every argument filled: " << en.toStdString();
    }
    translators.setLanguage(QStringLiteral("en"));
}

TEST(EventReasonWords, TheSentencesCarryTheDevicesNumbers)
{
    const ui::words::EnglishScope english;
    auto en = [](EventKind k, EventReason r) { return ui::words::text(worded({k, std::move(r)})).toStdString(); };
    EXPECT_EQ(en(dev::proto::kEvTestEnded, {why::kCompleted, {why::kRelayTest, 0.061}}), "axis X relay test completed in 0.06 s");
    EXPECT_EQ(en(dev::proto::kEvTestTripped, {why::kExcursion, {why::kStepTest, 0.03, 0.031, 0.2, 50.01}}),
              "axis X step test stopped after 0.20 s: its excursion reached 0.031 mm, past the limit of 0.030 mm; the axis stopped at 50.010 mm");
    EXPECT_EQ(en(EventKind::LostSteps, {why::kOffCommand, {0.125}}), "axis X's encoder is 0.125 mm off the command");
    EXPECT_EQ(en(EventKind::PathHeld, {static_cast<std::uint8_t>(dev::proto::PathReason::HostSilent), {}}),
              "held: the instrument heard nothing from BenchPilot for a second");
    EXPECT_EQ(en(dev::proto::kEvCompChanged, {why::kInstalled, {1, 11, 1}}),
              "axis X: a compensation table of 11 points per direction installed, not yet enabled");
}

TEST(EventReasonWords, AReasonThisHostDoesNotKnowLeavesTheDevicesTextToBeShown)
{
    auto known = [](EventKind k, EventReason r, std::string letter = "X") {
        return dev::eventReasonMessage(k, r, letter, dev::proto::AxisUnit::Millimetre).has_value();
    };
    EXPECT_FALSE(known(EventKind::LimitHit, {9, {}})) << "a newer device's code";
    EXPECT_FALSE(known(dev::proto::kEvTestEnded, {why::kCompleted, {}})) << "values missing";
    EXPECT_FALSE(known(EventKind::LimitHit, {why::kHomeSwitch, {}}, "")) << "an axis event without its axis";
    EXPECT_FALSE(known(EventKind::PathAborted, {8, {}}));
    // A path that ran as planned: known, and nothing to add to the event's kind.
    const auto started = dev::eventReasonMessage(EventKind::PathStarted, {why::kPathRan, {}}, "", dev::proto::AxisUnit::Millimetre);
    ASSERT_TRUE(started);
    EXPECT_TRUE(started->empty());
}
