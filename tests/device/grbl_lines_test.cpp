// GRBL line protocol, device → host: splitting, classifying, banner, $I, settings and
// probe lines, from transcripts of what GRBL 1.1 and grblHAL send.
#include "device/backends/grbl/grbl_build_info.h"
#include "device/backends/grbl/grbl_codes.h"
#include "device/backends/grbl/grbl_lines.h"

#include <gtest/gtest.h>

namespace {

using namespace dev::grbl;

TEST(GrblLines, SplitsCrLfLinesAcrossChunksAndKeepsTheHalfLine)
{
    LineReader r;
    std::vector<LineReader::Line> out;
    r.feed("ok\r\nerr", out);
    r.feed("or:22\r\n<Idle|MPos:0.000,0.0", out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[0].text, "ok");
    EXPECT_EQ(out[1].text, "error:22");
    EXPECT_EQ(r.partial(), "<Idle|MPos:0.000,0.0");
}

TEST(GrblLines, AFloodWithoutLineEndsIsCutNotStored)
{
    LineReader r;
    std::vector<LineReader::Line> out;
    const std::string garbage(100000, 'x');
    r.feed(garbage, out);
    EXPECT_TRUE(out.empty());
    EXPECT_LE(r.partial().size(), LineReader::kMaxLineBytes);
    r.feed("\nok\n", out);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_TRUE(out[0].truncated);
    EXPECT_EQ(out[1].text, "ok");
    EXPECT_FALSE(out[1].truncated);
    EXPECT_EQ(r.droppedBytes(), garbage.size() - LineReader::kMaxLineBytes);
}

TEST(GrblLines, ClassifiesEveryDocumentedLineKind)
{
    struct Case {
        const char* line;
        LineKind kind;
        int code;
    } cases[] = {
        {"ok", LineKind::Ok, 0},
        {"error:9", LineKind::Error, 9},
        {"error:79", LineKind::Error, 79},
        {"ALARM:3", LineKind::Alarm, 3},
        {"<Idle|MPos:0.000,0.000,0.000|FS:0,0>", LineKind::Status, 0},
        {"Grbl 1.1h ['$' for help]", LineKind::Banner, 0},
        {"GrblHAL 1.1f ['$' or '$HELP' for help]", LineKind::Banner, 0},
        {"[MSG:'$H'|'$X' to unlock]", LineKind::Message, 0},
        {"[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]", LineKind::ParserState, 0},
        {"[HLP:$$ $# $G $I $N $x=val $Nx=line $J=line $SLP $C $X $H ~ ! ? ctrl-x]", LineKind::Help, 0},
        {"[VER:1.1h.20190830:]", LineKind::Version, 0},
        {"[OPT:V,15,128]", LineKind::Options, 0},
        {"[PRB:0.000,0.000,-1.250:1]", LineKind::Probe, 0},
        {"[echo:G1X0.540Y10.4F100]", LineKind::Echo, 0},
        {"[G54:4.000,0.000,0.000]", LineKind::Bracketed, 0},
        {"[FIRMWARE:grblHAL]", LineKind::Bracketed, 0},
        {"$110=500.000", LineKind::Setting, 0},
        {"$N0=G20G54G17", LineKind::StartupBlock, 0},
        {">G54G20:ok", LineKind::StartupBlock, 0},
        {"", LineKind::Empty, 0},
        {"okay", LineKind::Unknown, 0},
        {"error:", LineKind::Unknown, 0},
        {"error:abc", LineKind::Unknown, 0},
        {"ALARM:12345", LineKind::Unknown, 0},
        {"<Idle|MPos:0,0,0", LineKind::Unknown, 0},  // half a report, cut by a reset
        {"[MSG:no end", LineKind::Unknown, 0},
        {"\x01\xff\x80garbage", LineKind::Unknown, 0},
    };
    for (const auto& c : cases) {
        const Line l = classifyLine(c.line);
        EXPECT_EQ(l.kind, c.kind) << c.line;
        EXPECT_EQ(l.code, c.code) << c.line;
    }
    EXPECT_EQ(classifyLine("[MSG:Reset to continue]").payload, "Reset to continue");
    EXPECT_EQ(classifyLine("[NVS STORAGE:*FLASH]").tag, "NVS STORAGE");
}

TEST(GrblLines, BannerNamesTheFirmwareEvenAfterTheTailOfACutLine)
{
    const auto g = parseBanner("Grbl 1.1h ['$' for help]");
    ASSERT_TRUE(g);
    EXPECT_EQ(g->firmware, Firmware::Grbl);
    EXPECT_EQ(g->version, "1.1h");
    const auto h = parseBanner("GrblHAL 1.1f ['$' or '$HELP' for help]");
    ASSERT_TRUE(h);
    EXPECT_EQ(h->firmware, Firmware::GrblHal);
    EXPECT_EQ(h->version, "1.1f");
    // A reset mid-report: the report's first half and the banner share a line.
    const auto cut = parseBanner("<Run|MPos:1.0Grbl 1.1h ['$' for help]");
    ASSERT_TRUE(cut);
    EXPECT_EQ(cut->version, "1.1h");
    EXPECT_FALSE(parseBanner("Grbl is great"));
    EXPECT_FALSE(parseBanner("[MSG:Grbl]"));
}

TEST(GrblLines, BuildInfoOfStockGrblGivesPlannerAndBuffer)
{
    BuildInfo info;
    for (const char* l : {"[VER:1.1h.20190830:bench 2]", "[OPT:V,15,128]"})
        EXPECT_TRUE(addBuildInfoLine(info, classifyLine(l))) << l;
    EXPECT_EQ(info.version, "1.1h.20190830");
    EXPECT_EQ(info.userText, "bench 2");
    EXPECT_EQ(info.plannerBlocks, 15);
    EXPECT_EQ(info.rxBufferBytes, 128);
    EXPECT_TRUE(info.hasOption('V'));
    EXPECT_EQ(info.firmware, Firmware::Unknown);  // the banner says which; $I of stock GRBL does not
    EXPECT_FALSE(addBuildInfoLine(info, classifyLine("ok")));
}

TEST(GrblLines, BuildInfoOfGrblHalKeepsItsExtraLines)
{
    BuildInfo info;
    const char* transcript[] = {"[VER:1.1f.20231210:]",  "[OPT:VNMZHSL,35,1024,3,0]", "[AXS:3:XYZ]",
                                "[NEWOPT:ENUMS,RT+,HOME,SED]", "[FIRMWARE:grblHAL]", "[DRIVER:STM32F401CC]",
                                "[BOARD:BlackPill]", "[AUX IO:2,4,0,0]"};
    for (const char* l : transcript)
        EXPECT_TRUE(addBuildInfoLine(info, classifyLine(l))) << l;
    EXPECT_EQ(info.plannerBlocks, 35);
    EXPECT_EQ(info.rxBufferBytes, 1024);
    EXPECT_EQ(info.axisCount, 3);
    EXPECT_EQ(info.axisLetters, "XYZ");
    EXPECT_EQ(info.firmware, Firmware::GrblHal);
    EXPECT_TRUE(info.hasOption('Z'));  // homing forces the origin to 0
    ASSERT_EQ(info.extra.size(), 6u);
    EXPECT_EQ(info.extra[3].first, "DRIVER");
    EXPECT_EQ(info.extra[3].second, "STM32F401CC");
    // $# lines are not build info.
    EXPECT_FALSE(addBuildInfoLine(info, classifyLine("[G54:0.000,0.000,0.000]")));
}

TEST(GrblLines, MissingOrAbsurdBufferSizesFallBackToTheDocumentedDefaults)
{
    BuildInfo none;
    EXPECT_EQ(none.rxBufferOrDefault(Firmware::Grbl), 128u);
    EXPECT_EQ(none.rxBufferOrDefault(Firmware::GrblHal), 1024u);
    EXPECT_EQ(none.plannerBlocksOrDefault(), 15);
    BuildInfo zero;
    addBuildInfoLine(zero, classifyLine("[OPT:V,0,0]"));
    EXPECT_EQ(zero.rxBufferOrDefault(Firmware::Grbl), 128u);
    EXPECT_EQ(zero.plannerBlocksOrDefault(), 15);
    BuildInfo garbage;
    addBuildInfoLine(garbage, classifyLine("[OPT:V,x,]"));
    EXPECT_EQ(garbage.rxBufferOrDefault(Firmware::Grbl), 128u);
}

TEST(GrblLines, SettingLinesKeepNumberAndText)
{
    const auto s = parseSettingLine("$110=500.000");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->id, 110);
    ASSERT_TRUE(s->value);
    EXPECT_DOUBLE_EQ(*s->value, 500.0);
    const auto t = parseSettingLine("$341=Zz");  // grblHAL text setting
    ASSERT_TRUE(t);
    EXPECT_FALSE(t->value);
    EXPECT_EQ(t->text, "Zz");
    EXPECT_FALSE(parseSettingLine("$$"));
    EXPECT_FALSE(parseSettingLine("$X=1"));
    EXPECT_FALSE(parseSettingLine("$1234567=1"));
}

TEST(GrblLines, ProbeLineGivesPositionAndOutcome)
{
    const auto p = parseProbeLine(classifyLine("[PRB:1.000,-2.500,-10.125:1]").payload);
    ASSERT_TRUE(p);
    EXPECT_TRUE(p->succeeded);
    ASSERT_EQ(p->position.size(), 3u);
    EXPECT_DOUBLE_EQ(p->position[2], -10.125);
    EXPECT_FALSE(parseProbeLine("1,2,3:2"));
    EXPECT_FALSE(parseProbeLine("1,2,3"));
}

TEST(GrblLines, NumbersAreGrblsPlainDecimalsOnly)
{
    EXPECT_EQ(parseNumber("-12.5"), -12.5);
    EXPECT_EQ(parseNumber(".5"), 0.5);
    EXPECT_EQ(parseNumber("3."), 3.0);
    for (const char* bad : {"", "-", ".", "1e5", "inf", "nan", "0x10", " 1", "1 ", "1.2.3", "--1"})
        EXPECT_FALSE(parseNumber(bad)) << bad;
    EXPECT_FALSE(parseNumberList("1,,2"));
    EXPECT_FALSE(parseNumberList("1,2,3,4", 3));
}

TEST(GrblCodes, EveryDocumentedCodeHasAMeaning)
{
    // GRBL 1.1's interface document: errors 1–38 (no 18, 19 there), alarms 1–9.
    for (int c = 1; c <= 38; ++c) {
        const CodeMeaning* m = errorMeaning(c);
        ASSERT_NE(m, nullptr) << c;
        EXPECT_GT(std::string(m->text).size(), 10u);
        EXPECT_EQ(m->grblHalOnly, c == 18 || c == 19) << c;
    }
    for (int c = 1; c <= 9; ++c) {
        ASSERT_NE(alarmMeaning(c), nullptr) << c;
        EXPECT_FALSE(alarmMeaning(c)->grblHalOnly);
    }
    // grblHAL additions.
    EXPECT_TRUE(errorMeaning(79)->grblHalOnly);
    EXPECT_TRUE(alarmMeaning(10)->grblHalOnly);
    EXPECT_EQ(errorMeaning(59), nullptr);
    EXPECT_EQ(alarmMeaning(0), nullptr);
    EXPECT_EQ(alarmMeaning(99), nullptr);
    std::size_t n = 0;
    const CodeMeaning* t = errorTable(&n);
    for (std::size_t i = 1; i < n; ++i)
        EXPECT_LT(t[i - 1].code, t[i].code);  // lookup bisects: the table stays sorted
}

TEST(GrblCodes, AnErrorMessageNamesCodeAndLine)
{
    const motion::msg::Message m = errorMessage(22, "G1 X10");
    EXPECT_EQ(m.id, "grbl.error");
    EXPECT_EQ(m.integer("code"), 22);
    EXPECT_EQ(m.text("line"), "G1 X10");
    EXPECT_EQ(alarmMessage(2).integer("code"), 2);
}

} // namespace

namespace {
TEST(GrblLines, ABannerAfterACutReportIsStillABanner)
{
    EXPECT_EQ(dev::grbl::classifyLine("<Run|MPos:1.0Grbl 1.1h ['$' for help]").kind, dev::grbl::LineKind::Banner);
    EXPECT_EQ(dev::grbl::classifyLine("[MSG:ResGrblHAL 1.1f ['$' or '$HELP' for help]").kind, dev::grbl::LineKind::Banner);
}
} // namespace
