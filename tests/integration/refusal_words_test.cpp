// A device's refusal is worded from its error code, the axis and the code's value in the
// operator's language: in Chinese without the firmware's English, in English with the
// firmware's words quoted where they add what the code cannot say.
#include "device/protocol/messages.h"
#include "device/protocol/messages_compensation.h"
#include "sim_session.h"
#include "widgets/wording/translators.h"
#include "widgets/wording/wording.h"

#include "../device/pseudo_translation.h"

#include <gtest/gtest.h>

namespace {

constexpr const char* kFirmwareWords = "axis X relay test: amplitude 5.000 mm above 1.000 mm";

motion::msg::Message refusal(int code, bool onAxis = true)
{
    std::vector<motion::msg::Arg> args{motion::msg::term("code", dev::proto::errorCodeTerm(static_cast<dev::proto::ErrorCode>(code))),
                               motion::msg::verbatim("detail", kFirmwareWords)};
    if (onAxis)
        args.push_back(motion::msg::verbatim("axis", "X"));
    args.push_back(motion::msg::real("value", 3, motion::msg::Unit::Mm));
    return motion::msg::make("device.refused", std::move(args));
}

const int kCodes[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 23, 24, 25};

} // namespace

TEST(RefusalWords, EveryCodeIsASentenceInChineseWithoutTheFirmwaresEnglish)
{
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
    static const QRegularExpression han(QStringLiteral("\\p{Han}"));
    for (int code : kCodes)
        for (bool onAxis : {true, false}) {
            const QString zh = ui::words::text(refusal(code, onAxis));
            EXPECT_TRUE(zh.contains(han)) << code << ": " << zh.toStdString();
            EXPECT_TRUE(i18ntest::untranslated(zh).isEmpty()) << code << ": " << zh.toStdString();
            EXPECT_EQ(zh.startsWith(QStringLiteral("X 轴")), onAxis) << code << ": " << zh.toStdString();
        }
    translators.setLanguage(QStringLiteral("en"));
}

TEST(RefusalWords, TheEnglishQuotesTheDeviceOnlyWhereItsWordsAddToTheCode)
{
    const ui::words::EnglishScope english;
    EXPECT_EQ(ui::words::text(refusal(9)).toStdString(), std::string("axis X: a speed, limit, rate or count in the request is out of the device's range "
                                                                 "(the device says: ") + kFirmwareWords + ")");
    EXPECT_EQ(ui::words::text(refusal(5)).toStdString(), "axis X: it would cross the soft limit at 3.000 mm");
    EXPECT_EQ(ui::words::text(refusal(7, false)).toStdString(), "the E-stop is latched: reset it first");
    // A code this host does not know: its term and the device's words, as before.
    EXPECT_EQ(ui::words::text(refusal(99)).toStdString(), std::string("unknown error: ") + kFirmwareWords);
}

TEST(RefusalWords, AnAbsoluteMoveOnAnUnhomedAxisIsRefusedInTheOperatorsLanguage)
{
    itest::SimSession s(dev::proto::DeviceKind::Analyzer);
    ASSERT_TRUE(s.connect());
    const auto err = s.call([&](auto cb) { s.client.move({{s.axis('Y'), 50.0}}, false, 0, cb); });
    ASSERT_TRUE(err);
    {
        const ui::words::EnglishScope english;
        EXPECT_EQ(ui::words::text(err->message).toStdString(), "move refused: axis Y: not homed: home it first");
    }
    ui::words::Translators translators;
    ASSERT_TRUE(translators.setLanguage(QStringLiteral("zh_CN")));
    const QString zh = ui::words::text(err->message);
    EXPECT_TRUE(zh.contains(QStringLiteral("Y 轴：未回零"))) << zh.toStdString();
    EXPECT_TRUE(i18ntest::untranslated(zh).isEmpty()) << zh.toStdString();
    translators.setLanguage(QStringLiteral("en"));
}
