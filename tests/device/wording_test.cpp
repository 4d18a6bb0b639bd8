// The wording layer turns structured messages into sentences: numbers in the
// locale with their unit's precision, terms and nested messages worded, and an
// unknown id kept readable rather than lost.
#include "widgets/wording/wording.h"

#include "device/client/capabilities.h"

#include <QJsonObject>
#include <QLocale>

#include <gtest/gtest.h>

namespace {

struct LocaleGuard {
    QLocale saved;
    explicit LocaleGuard(const QLocale& l) { QLocale::setDefault(l); }
    ~LocaleGuard() { QLocale::setDefault(saved); }
};

TEST(Wording, NumbersCarryTheirUnitsPrecision)
{
    LocaleGuard c(QLocale::c());
    EXPECT_EQ(ui::words::number(12.34567, motion::msg::Unit::Mm), QStringLiteral("12.346 mm"));
    // Not a tie (1.25 is exact in binary and Qt rounds a tie away from zero).
    EXPECT_EQ(ui::words::number(1.234, motion::msg::Unit::Um), QStringLiteral("1.2 µm"));
    EXPECT_EQ(ui::words::number(1.27, motion::msg::Unit::Um), QStringLiteral("1.3 µm"));
    EXPECT_EQ(ui::words::number(90, motion::msg::Unit::Deg), QStringLiteral("90.0°"));
    // Below the unit's last digit a value keeps its significant digits.
    EXPECT_EQ(ui::words::number(0.0004, motion::msg::Unit::Mm), QStringLiteral("0.0004 mm"));
}

// One rule for every screen (the five each had their own) and for sentences with seconds:
// the 96-well run's banner said "about 173.00 s".
TEST(Wording, DurationsReadLikeAPersonWouldSayThem)
{
    LocaleGuard c(QLocale::c());
    EXPECT_EQ(ui::words::duration(4.24), QStringLiteral("4.2 s"));
    EXPECT_EQ(ui::words::duration(42.4), QStringLiteral("42 s"));
    EXPECT_EQ(ui::words::duration(75), QStringLiteral("1 min 15 s"));
    EXPECT_EQ(ui::words::duration(173), QStringLiteral("2 min 53 s"));
    EXPECT_EQ(ui::words::duration(3 * 3600 + 125), QStringLiteral("3 h 02 min"));
    EXPECT_EQ(ui::words::duration(-1), QStringLiteral("—"));
    EXPECT_EQ(ui::words::number(173, motion::msg::Unit::S), QStringLiteral("2 min 53 s"));
    EXPECT_EQ(ui::words::number(12.5, motion::msg::Unit::S), QStringLiteral("12.50 s"));
}

// Sentences are worded to be embedded; shown on their own (banner, run log, a question's
// paragraph) they start with a capital. Seen lower-case in the Xvfb session.
TEST(Wording, ASentenceShownOnItsOwnStartsWithACapital)
{
    EXPECT_EQ(ui::words::sentence(QStringLiteral("the link to the analyzer was lost")), QStringLiteral("The link to the analyzer was lost"));
    EXPECT_EQ(ui::words::sentence(QStringLiteral("Analyzer: ready")), QStringLiteral("Analyzer: ready"));
    EXPECT_EQ(ui::words::sentence(QStringLiteral("分析仪连接中断")), QStringLiteral("分析仪连接中断"));
    EXPECT_EQ(ui::words::sentence(QStringLiteral("µL left")), QStringLiteral("µL left")) << "a unit's prefix is not a letter to capitalise";
    EXPECT_EQ(ui::words::sentence(QString()), QString());
}

// "Sampling-96.recipe.json cannot be opened" named a file that does not exist: a sentence
// that starts with a file's name or a path keeps it as it is.
TEST(Wording, ASentenceThatStartsWithAFileNameKeepsItsCase)
{
    EXPECT_EQ(ui::words::sentence(QStringLiteral("sampling-96.recipe.json was not opened")), QStringLiteral("sampling-96.recipe.json was not opened"));
    EXPECT_EQ(ui::words::sentence(QStringLiteral("runs/plate-1/run.log: line 4 is damaged")), QStringLiteral("runs/plate-1/run.log: line 4 is damaged"));
    EXPECT_EQ(ui::words::sentence(QStringLiteral("calibration.json: 2 problems")), QStringLiteral("calibration.json: 2 problems"));
    EXPECT_EQ(ui::words::sentence(QStringLiteral("done.")), QStringLiteral("Done.")) << "a full stop at the end is no extension";
}

// One wording of a problem for the CLI, the API's text and the screens: the place as far
// as it is known, then the sentence.
TEST(Wording, AProblemSaysItsPlaceThenItsSentence)
{
    LocaleGuard c(QLocale::c());
    motion::msg::Problem p = motion::msg::error("steps[3].volume_ul", motion::msg::make("file.json.missing"));
    const QString sentence = ui::words::text(p.message);
    EXPECT_EQ(ui::words::problem(p), QStringLiteral("steps[3].volume_ul: ") + sentence);
    p.file = "a.recipe.json";
    EXPECT_EQ(ui::words::problem(p), QStringLiteral("a.recipe.json: steps[3].volume_ul: ") + sentence);
    p.line = 12;
    p.column = 7;
    EXPECT_EQ(ui::words::problem(p), QStringLiteral("a.recipe.json:12:7: steps[3].volume_ul: ") + sentence);
    p.severity = motion::msg::Severity::Warning;
    EXPECT_EQ(ui::words::problem(p), QStringLiteral("a.recipe.json:12:7: steps[3].volume_ul: warning: ") + sentence);
    p.path.clear();
    p.line = 0;
    EXPECT_EQ(ui::words::problem(p), QStringLiteral("a.recipe.json: warning: ") + sentence);

    const QJsonObject o = ui::words::toJson(p);
    EXPECT_EQ(o.value(QStringLiteral("file")).toString(), QStringLiteral("a.recipe.json"));
    EXPECT_TRUE(o.value(QStringLiteral("warning")).toBool());
    EXPECT_FALSE(o.contains(QStringLiteral("line"))) << "a file as a whole has no line";
    EXPECT_FALSE(o.contains(QStringLiteral("field")));
}

TEST(Wording, NumbersFollowTheLocale)
{
    LocaleGuard de(QLocale(QLocale::German, QLocale::Germany));
    EXPECT_EQ(ui::words::number(1234.5, motion::msg::Unit::Mm), QStringLiteral("1.234,500 mm"));
}

TEST(Wording, ACapabilityReasonIsASentenceWithItsInstrument)
{
    const motion::msg::Message m = motion::msg::make(dev::missingId(dev::Capability::PidGains),
        {motion::msg::term("instrument", "instrument.analyzer"), motion::msg::verbatim("family", "Grbl 1.1h"),
         motion::msg::term("because", "capability.because.open_loop")});
    EXPECT_EQ(ui::words::text(m), QStringLiteral("The analyzer (Grbl 1.1h) has no PID gains to tune: it runs open loop."));
}

TEST(Wording, AnUnknownIdIsShownWithItsArgumentsNotDropped)
{
    const motion::msg::Message m = motion::msg::make("nowhere.unknown", {motion::msg::real("value", 2, motion::msg::Unit::Mm)});
    EXPECT_EQ(ui::words::text(m), QStringLiteral("nowhere.unknown{value=2 mm}"));
    EXPECT_EQ(ui::words::term("nowhere.term"), QStringLiteral("nowhere.term"));
}

} // namespace

namespace {

TEST(Wording, JsonKeepsTheIdTypedArgumentsUnitsAndEnglish)
{
    const motion::msg::Message m = motion::msg::make(dev::kNotConnectedId, {motion::msg::term("instrument", "instrument.stage"),
                                                            motion::msg::real("value", 2.5, motion::msg::Unit::Mm),
                                                            motion::msg::integer("count", 3)});
    const QJsonObject o = ui::words::toJson(m);
    EXPECT_EQ(o.value("id").toString(), QStringLiteral("capability.not_connected"));
    EXPECT_EQ(o.value("args").toObject().value("instrument").toString(), QStringLiteral("instrument.stage"));
    EXPECT_DOUBLE_EQ(o.value("args").toObject().value("value").toDouble(), 2.5);
    EXPECT_EQ(o.value("args").toObject().value("count").toInteger(), 3);
    EXPECT_EQ(o.value("units").toObject().value("value").toString(), QStringLiteral("mm"));
    EXPECT_FALSE(o.value("units").toObject().contains("count"));
    EXPECT_EQ(o.value("message").toString(), QStringLiteral("The stage is not connected."));
}

} // namespace
