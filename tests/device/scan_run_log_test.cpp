// The scan's run log: what a resumed run reads back, a torn last line after a
// crash, and a damaged log named by its line.
#include "device/english_words.h"
#include "device/files/scan_run_log.h"

#include <gtest/gtest.h>

namespace {

motion::PositionRecord record(int tile)
{
    motion::PositionRecord r;
    r.target = tile;
    r.label = "tile_" + std::to_string(tile + 1) + ".tif";
    r.plannedMm = {10.0 + tile, 20.5};
    r.commandedMm = {10.0 + tile - 0.0125, 20.5 - 0.0234};
    r.measuredMm = {10.0 + tile - 0.0125, 20.5 - 0.0235};
    r.deviceTimeUs = 1234567890123ull + static_cast<std::uint64_t>(tile);
    r.settleS = 0.0315;
    return r;
}

} // namespace

TEST(ScanRunLog, RecordsReadBackExactly)
{
    std::string text = dev::files::scan::runLogHeader("Slide \"A\"", 0x0123456789abcdefull, 12);
    for (int t : {0, 1, 2, 5})
        text += dev::files::scan::runLogLine(record(t));
    const auto r = dev::files::scan::parseRunLog(text);
    ASSERT_TRUE(r.log) << i18ntest::englishFormat(r.problems, "run.jsonl");
    EXPECT_EQ(r.log->planName, "Slide \"A\"");
    EXPECT_EQ(r.log->fingerprint, 0x0123456789abcdefull);
    EXPECT_EQ(r.log->tiles, 12);
    ASSERT_EQ(r.log->records.size(), 4u);
    const auto& back = r.log->records[3];
    const auto want = record(5);
    EXPECT_EQ(back.target, 5);
    EXPECT_EQ(back.label, want.label);
    EXPECT_EQ(back.commandedMm, want.commandedMm);
    EXPECT_EQ(back.measuredMm, want.measuredMm);
    EXPECT_EQ(back.deviceTimeUs, want.deviceTimeUs);
    EXPECT_EQ(back.settleS, want.settleS);
    EXPECT_FALSE(r.log->tornTail);
}

TEST(ScanRunLog, ALineTornByACrashIsDropped)
{
    std::string text = dev::files::scan::runLogHeader("p", 1, 4) + dev::files::scan::runLogLine(record(0));
    const std::string next = dev::files::scan::runLogLine(record(1));
    text += next.substr(0, next.size() / 2);  // the process died mid-write
    const auto r = dev::files::scan::parseRunLog(text);
    ASSERT_TRUE(r.log) << i18ntest::englishFormat(r.problems, "run.jsonl");
    EXPECT_EQ(r.log->records.size(), 1u);
    EXPECT_TRUE(r.log->tornTail);
}

TEST(ScanRunLog, DamageInsideTheLogIsAnError)
{
    std::string text = dev::files::scan::runLogHeader("p", 1, 4) + dev::files::scan::runLogLine(record(0));
    text += "{\"tile\": 9, \"label\": \"x\"}\n" + dev::files::scan::runLogLine(record(1));
    const auto r = dev::files::scan::parseRunLog(text);
    EXPECT_FALSE(r.log);
    const std::string e = i18ntest::englishFormat(r.problems, "run.jsonl");
    EXPECT_NE(e.find("run.jsonl:3:10: tile: must be from 0 to 3 (got 9)"), std::string::npos) << e;
    EXPECT_NE(e.find("run.jsonl:3:1: planned_mm: is missing"), std::string::npos) << e;
    EXPECT_FALSE(dev::files::scan::parseRunLog("").log);
    EXPECT_FALSE(dev::files::scan::parseRunLog("{\"schema\": \"benchpilot.scan-plan\", \"version\": 1}\n").log);
}
