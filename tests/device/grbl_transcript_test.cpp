// A GRBL conversation as the client will see it: a stream with an error in the middle, a
// message, a report cut short by a reset, and the banner that follows it — fed through the
// line reader in awkward chunks, the streamer and the status tracker together.
#include "device/backends/grbl/grbl_codes.h"
#include "device/backends/grbl/grbl_lines.h"
#include "device/backends/grbl/grbl_status.h"
#include "device/backends/grbl/grbl_streamer.h"

#include <gtest/gtest.h>

namespace {

using namespace dev::grbl;

struct Client {
    Streamer streamer;
    StatusTracker tracker;
    std::vector<motion::msg::Message> shown;  ///< what a person would be told
    std::vector<std::string> lost;    ///< lines a reset swallowed
    int unknown = 0, banners = 0;

    void line(const std::string& text)
    {
        const Line l = classifyLine(text);
        switch (l.kind) {
        case LineKind::Ok:
        case LineKind::Error:
            if (const auto ack = streamer.acknowledge(l.kind == LineKind::Ok, l.code); ack && !ack->ok)
                shown.push_back(errorMessage(ack->errorCode, ack->line));
            break;
        case LineKind::Alarm:
            shown.push_back(alarmMessage(l.code));
            break;
        case LineKind::Banner:
            ++banners;
            for (const auto& a : streamer.softReset())
                lost.push_back(a.line);
            tracker.reset();
            break;
        case LineKind::Status:
            if (const auto p = parseStatusReport(l.payload); p.report)
                tracker.update(*p.report);
            break;
        case LineKind::Unknown:
            ++unknown;
            break;
        default:
            break;
        }
    }
};

TEST(GrblTranscript, AnErrorMidStreamAndABannerAfterAReset)
{
    Client c;
    for (const char* l : {"G90 G21 G1 X1 F600", "G1 X2 Y", "G1 X2", "G1 X3", "G1 X4"})
        ASSERT_EQ(c.streamer.enqueue(l), Streamer::Queued::Ok);
    ASSERT_EQ(c.streamer.takeOutput().size(), 19u + 8 + 6 + 6 + 6);
    const std::string transcript =
        "ok\r\n"
        "<Run|MPos:1.000,0.000,0.000|FS:600,0|WCO:0.500,0.000,0.000>\r\n"
        "error:2\r\n"                 // "G1 X2 Y": a word without its number
        "[MSG:Pgm End]\r\n"
        "ok\r\n"
        "<Run|MPos:2.0"               // cut short: the board was reset
        "\r\nGrbl 1.1h ['$' for help]\r\n"
        "[MSG:'$H'|'$X' to unlock]\r\n"
        "<Alarm|MPos:2.000,0.000,0.000|FS:0,0|WCO:0.000,0.000,0.000>\r\n";
    LineReader reader;
    std::vector<LineReader::Line> lines;
    for (std::size_t i = 0; i < transcript.size(); i += 7)  // chunks that split lines and "\r\n"
        reader.feed(std::string_view(transcript).substr(i, 7), lines);
    for (const auto& l : lines)
        c.line(l.text);
    ASSERT_EQ(c.shown.size(), 1u);
    EXPECT_EQ(c.shown[0].id, "grbl.error");
    EXPECT_EQ(c.shown[0].integer("code"), 2);
    EXPECT_EQ(c.shown[0].text("line"), "G1 X2 Y");  // the error names the line that caused it
    EXPECT_EQ(c.banners, 1);
    EXPECT_EQ(c.lost, (std::vector<std::string>{"G1 X3", "G1 X4"}));  // never answered: the reset ate them
    EXPECT_EQ(c.streamer.inFlightBytes(), 0u);
    EXPECT_EQ(c.unknown, 1);  // the half report, logged and otherwise ignored
    EXPECT_EQ(c.tracker.state(), MachineState::Alarm);
    EXPECT_EQ(c.tracker.workOffsetMm()[0], 0.0);  // the offset from before the reset is gone
    EXPECT_EQ(c.tracker.machineMm()[0], 2.0);
}

TEST(GrblTranscript, AnAlarmWithItsMessageAndAStrayOkAfterTheReset)
{
    Client c;
    c.streamer.enqueue("G1 X250 F600");
    c.streamer.takeOutput();
    for (const char* l : {"ALARM:2", "[MSG:Reset to continue]", "", "Grbl 1.1h ['$' for help]", "ok"})
        c.line(l);
    ASSERT_EQ(c.shown.size(), 1u);
    EXPECT_EQ(c.shown[0], alarmMessage(2));
    EXPECT_EQ(c.lost, (std::vector<std::string>{"G1 X250 F600"}));
    EXPECT_EQ(c.streamer.strayAcks(), 1u);  // an ok nobody is waiting for is counted, not matched
}

} // namespace
