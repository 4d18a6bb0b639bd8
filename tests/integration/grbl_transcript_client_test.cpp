// The GRBL client against recorded transcripts of tricky lines, from a scripted controller:
// a report with every field and some unknown ones, an error in the middle of a job, a banner in
// the middle of a stream after a reset, garbage and half lines, inch reports, settings that do
// not give the limits, and boards that never answer or answer only noise. Whatever comes, the
// client says what happened within seconds and never hangs.
#include "device/backends/grbl/client/grbl_client.h"
#include "device/client/path_client.h"
#include "grbl_script.h"
#include "motion/message_print.h"
#include "wait.h"

#include <gtest/gtest.h>

#include <QElapsedTimer>

using itest::ScriptedGrbl;
using itest::waitFor;

namespace {

struct Rig {
    ScriptedGrbl port;
    dev::GrblClient client;
    std::vector<dev::DeviceEvent> events;
    std::vector<dev::RequestError> failures;
    std::vector<motion::msg::Message> notes;
    std::vector<motion::msg::Message> linkErrors;

    explicit Rig(dev::files::MachineProfile profile = dev::files::defaultProfile(dev::proto::DeviceKind::Stage)) : client(profile, true)
    {
        QObject::connect(&client, &dev::Instrument::eventReceived, &client, [this](const dev::DeviceEvent& e) { events.push_back(e); });
        QObject::connect(&client, &dev::Instrument::requestFailed, &client, [this](const dev::RequestError& e) { failures.push_back(e); });
        QObject::connect(&client, &dev::Instrument::noted, &client, [this](const motion::msg::Message& m) { notes.push_back(m); });
        QObject::connect(&client, &dev::Instrument::linkError, &client, [this](const motion::msg::Message& m) { linkErrors.push_back(m); });
        client.setTransport(&port);
    }
    ~Rig() { client.setTransport(nullptr); }

    bool connect()
    {
        client.connectLink();
        return waitFor([this] { return client.isReady() || client.state() == dev::LinkState::Disconnected; }, 8000) && client.isReady();
    }
    /// The next status report the client asks for says `report`; waits until it is applied.
    bool report(const std::string& text)
    {
        port.report = text;
        int n = 0;
        const auto c = QObject::connect(&client, &dev::Instrument::statusChanged, &client, [&n] { ++n; });
        const bool ok = waitFor([&n] { return n >= 2; }, 5000);
        QObject::disconnect(c);
        return ok;
    }
    bool hasNote(const std::string& id) const
    {
        for (const auto& n : notes)
            if (n.id == id)
                return true;
        return false;
    }
};

TEST(GrblTranscriptClient, AReportWithEveryFieldAndUnknownOnesIsRead)
{
    Rig r;
    ASSERT_TRUE(r.connect()) << (r.linkErrors.empty() ? motion::msg::Message{} : r.linkErrors.front());
    // grblHAL-style extra fields (H:, FW:, WCS:) among the documented ones, in no particular order.
    ASSERT_TRUE(r.report("<Hold:1|WPos:1.000,2.000,0.000|Bf:15,128|Ln:99|FS:600,0|Pn:XZ|WCO:0.500,-1.000,0.000|Ov:100,100,100|"
                         "A:SF|H:0,0|FW:grblHAL|WCS:G54>"));
    const auto& st = r.client.status();
    EXPECT_NEAR(st.axes[0].commanded, 1.0, 1e-9);  // work coordinates, as reported
    EXPECT_NEAR(st.axes[1].commanded, 2.0, 1e-9);
    EXPECT_TRUE(st.axes[0].limitSwitch);           // Pn:X
    EXPECT_FALSE(st.axes[1].limitSwitch);
    EXPECT_EQ(r.client.machineState(), dev::grbl::MachineState::Hold);
    EXPECT_FALSE(r.hasNote("grbl.status.malformed"));
    // Then MPos with the remembered WCO: work = machine − offset.
    ASSERT_TRUE(r.report("<Idle|MPos:10.500,4.000,0.000|FS:0,0>"));
    EXPECT_NEAR(r.client.status().axes[0].commanded, 10.0, 1e-9);
    EXPECT_NEAR(r.client.status().axes[1].commanded, 5.0, 1e-9);
    // A report that cannot be read is noted and skipped, never fatal.
    r.port.report = "<Sleepy|MPos:1,2,3>";
    ASSERT_TRUE(waitFor([&] { return r.hasNote("grbl.status.malformed"); }, 3000));
    EXPECT_TRUE(r.client.isReady());
}

TEST(GrblTranscriptClient, AnErrorInTheMiddleOfAJobStopsItAndNamesTheLine)
{
    Rig r;
    ASSERT_TRUE(r.connect());
    r.port.report = "<Idle|MPos:0.000,0.000,0.000|FS:0,0>";
    dev::PathClient* paths = r.client.paths();
    ASSERT_NE(paths, nullptr);
    std::vector<motion::path::Segment> segs(3);
    segs[0].end = {5, 0};
    segs[1].start = {5, 0};
    segs[1].end = {5, 5};
    segs[2].start = {5, 5};
    segs[2].end = {0, 5};
    for (auto& s : segs)
        s.feedMmS = 10;
    r.port.answers = {"ok", "error:33", "ok"};
    bool begun = false, appended = false;
    paths->begin(0, [&](const auto& e, const auto&) { begun = !e; });
    ASSERT_TRUE(waitFor([&] { return begun; }, 3000));
    std::optional<quint32> abortedAt;
    QString abortedBecause;
    QObject::connect(paths, &dev::PathClient::aborted, paths, [&](quint32 i, const QString& said) {
        abortedAt = i;
        abortedBecause = said;
    });
    paths->append(0, segs, true, true, [&](const auto& e, const auto&) { appended = !e; });
    ASSERT_TRUE(appended);
    ASSERT_TRUE(waitFor([&] { return abortedAt.has_value(); }, 5000));
    ASSERT_FALSE(r.failures.empty());
    const auto& f = r.failures.back();
    EXPECT_EQ(f.message.id, "grbl.error") << f.message;
    EXPECT_EQ(f.message.integer("code"), 33);
    EXPECT_EQ(f.message.text("line"), "G90 G21 G1 X5 Y5 F600");  // the second segment's line
    EXPECT_EQ(f.message.text("request"), "request.path_segments");
    EXPECT_EQ(f.message.integer("segment", -1), 1);
    EXPECT_EQ(abortedBecause, QStringLiteral("error:33"));  // what the controller said
    // The job is stopped: a feed hold, then (at rest) a reset that flushes the rest.
    r.port.report = "<Hold:0|MPos:5.000,0.000,0.000|FS:0,0>";
    ASSERT_TRUE(waitFor([&] { return r.port.realtime.find('\x18') != std::string::npos; }, 5000));
    EXPECT_NE(r.port.realtime.find('!'), std::string::npos);
}

TEST(GrblTranscriptClient, ABannerInTheMiddleOfAStreamIsAResetThatLosesTheLinesInFlight)
{
    Rig r;
    ASSERT_TRUE(r.connect());
    r.port.report = "<Idle|MPos:0.000,0.000,0.000|FS:0,0>";
    // The default report is Idle with homing on: the position counts as established.
    r.port.hold = [](const std::string& line) { return line.rfind("G91", 0) == 0; };  // the move is never answered
    std::optional<std::optional<dev::RequestError>> result;
    r.client.move({{0, 5}}, true, 5, [&](const auto& e) { result = e; });
    ASSERT_TRUE(waitFor([&] { return !r.port.lines.empty() && r.port.lines.back().rfind("G91", 0) == 0; }, 3000));
    // The board resets: half a report, then its banner (as a power glitch leaves it).
    r.port.pushRaw("<Run|MPos:1.2");
    r.port.push("\r\nGrbl 1.1h ['$' for help]");
    ASSERT_TRUE(waitFor([&] { return result.has_value(); }, 5000));
    ASSERT_TRUE(result->has_value());
    EXPECT_EQ((*result)->message.id, "request.abandoned") << (*result)->message;
    EXPECT_EQ((*result)->message.text("request"), "request.move");
    EXPECT_EQ(motion::msg::nested((*result)->message, "cause").id, "grbl.reset_by_itself") << (*result)->message;
    const auto it = std::find_if(r.events.begin(), r.events.end(), [](const auto& e) { return e.detail.id == "grbl.controller_reset"; });
    ASSERT_NE(it, r.events.end());
    EXPECT_EQ(it->detail.integer("lost"), 1);
    EXPECT_EQ(it->detail.text("first"), "G91 G21 G1 X5 F300");
    EXPECT_FALSE(r.client.status().axes[0].homed);  // an unexplained reset: the position is not trusted
    EXPECT_TRUE(r.client.isReady());
}

TEST(GrblTranscriptClient, GarbageAndHalfLinesAreNotedNeverFatal)
{
    Rig r;
    ASSERT_TRUE(r.connect());
    static const char kNoise[] = "\x01\x02\xfe noise\r\n";
    r.port.pushRaw(std::string(kNoise, sizeof kNoise - 1) + "[MSG:Pgm End]\r\n[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]\r\n"
                   "<Idle|MPos:1.000,0.000");
    r.port.pushRaw(",0.000|FS:0,0>\r\n");  // the rest of the half line, later
    ASSERT_TRUE(waitFor([&] { return r.hasNote("grbl.unknown_line") && r.hasNote("grbl.device_message"); }, 3000));
    EXPECT_TRUE(r.hasNote("grbl.device_line"));
    EXPECT_TRUE(r.client.isReady());
    // 2000 bytes without a line end: cut at the line limit, said once, memory bounded.
    r.port.pushRaw(std::string(2000, 'x') + "\r\n");
    ASSERT_TRUE(waitFor([&] { return r.hasNote("grbl.line_too_long"); }, 3000));
    ASSERT_TRUE(r.report("<Idle|MPos:2.000,0.000,0.000|FS:0,0>"));
    EXPECT_NEAR(r.client.status().axes[0].commanded, 2.0, 1e-9);
}

TEST(GrblTranscriptClient, InchReportsAreConvertedOrRefusedNeverMisread)
{
    {
        Rig r;
        r.port.settings.replace(r.port.settings.find("$13=0"), 5, "$13=1");
        r.port.report = "<Idle|MPos:1.0000,0.5000,0.0000|FS:0,0|WCO:0.0000,0.0000,0.0000>";
        ASSERT_TRUE(r.connect());
        ASSERT_TRUE(waitFor([&] { return std::abs(r.client.status().axes[0].commanded - 25.4) < 1e-9; }, 3000));
        EXPECT_NEAR(r.client.status().axes[1].commanded, 12.7, 1e-9);
        EXPECT_TRUE(r.hasNote("grbl.settings.report_inches"));
        // Limits are millimetres whatever $13 says.
        EXPECT_NEAR(r.client.identity().axes[0].maxSpeed, 20, 1e-9);
    }
    {
        dev::files::MachineProfile p = dev::files::defaultProfile(dev::proto::DeviceKind::Stage);
        p.inchReports = dev::files::MachineProfile::InchReports::Refuse;
        Rig r(p);
        r.port.settings.replace(r.port.settings.find("$13=0"), 5, "$13=1");
        EXPECT_FALSE(r.connect());
        ASSERT_FALSE(r.linkErrors.empty());
        EXPECT_EQ(r.linkErrors.front().id, "grbl.identify.inches_refused") << r.linkErrors.front();
    }
}

TEST(GrblTranscriptClient, SettingsWithoutTheLimitsRefuseTheConnectionSayingWhich)
{
    Rig r;
    r.port.settings.replace(r.port.settings.find("$110=1200.000\r\n"), 15, "");
    EXPECT_FALSE(r.connect());
    ASSERT_FALSE(r.linkErrors.empty());
    const motion::msg::Message& why = r.linkErrors.front();
    EXPECT_EQ(why.id, "grbl.identify.no_limits") << why;
    EXPECT_EQ(why.integer("count"), 1);
    EXPECT_EQ(motion::msg::nested(why, "problem").id, "grbl.settings.missing") << why;
    EXPECT_EQ(motion::msg::nested(why, "problem").integer("setting"), 110);
    EXPECT_EQ(motion::msg::nested(why, "problem").text("axis"), "X");
    EXPECT_TRUE(r.hasNote("grbl.settings.missing"));  // every problem is in the event log
}

TEST(GrblTranscriptClient, ABoardThatNeverAnswersOrAnswersNoiseIsToldWithinSeconds)
{
    for (const bool noise : {false, true}) {
        Rig r;
        r.port.silent = true;
        if (noise)
            r.client.setConnectTimeoutMs(1500);  // the message is the point here; the silent board keeps the real 5 s
        QElapsedTimer t;
        t.start();
        r.client.connectLink();
        if (noise) {
            static const char kNoise[] = "\x11\x93\xa7 garbage at the wrong baud rate \x05\r\n";
            ASSERT_TRUE(waitFor([&] { return r.port.isOpen(); }, 2000));
            r.port.pushRaw(std::string(kNoise, sizeof kNoise - 1));
        }
        ASSERT_TRUE(waitFor([&] { return r.client.state() == dev::LinkState::Disconnected; }, 15000));
        ASSERT_EQ(r.linkErrors.size(), 1u);
        const motion::msg::Message& why = r.linkErrors.front();
        EXPECT_EQ(why.id, noise ? "grbl.connect.no_grbl_line" : "grbl.connect.no_answer") << why;
        EXPECT_EQ(why.text("link"), r.client.linkDescription().toStdString());
        EXPECT_GT(why.number("seconds"), 0);
        if (noise) {
            EXPECT_GT(why.integer("bytes"), 0);
        }
        // The second sync went out (a board may still be booting after its port opened).
        EXPECT_GE(std::count(r.port.lines.begin(), r.port.lines.end(), std::string()), 2);
    }
}

TEST(GrblTranscriptClient, AControllerThatFallsSilentIsALostLink)
{
    Rig r;
    ASSERT_TRUE(r.connect());
    r.port.silent = true;
    ASSERT_TRUE(waitFor([&] { return r.client.state() == dev::LinkState::Lost; }, 10000));
    ASSERT_FALSE(r.linkErrors.empty());
    const motion::msg::Message& why = r.linkErrors.back();
    EXPECT_EQ(why.id, "link.lost") << why;
    EXPECT_EQ(motion::msg::nested(why, "cause").id, "grbl.silent") << why;
    EXPECT_DOUBLE_EQ(motion::msg::nested(why, "cause").number("seconds"), dev::GrblClient::kSilenceMs / 1000.0);
}

} // namespace
