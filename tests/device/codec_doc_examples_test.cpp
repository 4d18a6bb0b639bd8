// The worked examples in docs/protocol.md, built with the real encoders. Each
// example's frame body and wire bytes appear in the document after a marker
// `<!-- body:NAME -->` / `<!-- wire:NAME -->` as a fenced block of hex; this test
// fails when the document and the codec disagree, so the spec cannot drift.
//
// To regenerate the blocks after a deliberate protocol change:
//   BP_DUMP_DOC_EXAMPLES=1 ./test_device --gtest_filter='CodecDocExamples.*'
#include "device/protocol/crc16.h"
#include "device/protocol/frame_codec.h"
#include "device/protocol/messages.h"
#include "compensation_doc_examples.h"
#include "tuning_doc_examples.h"
#include "device/protocol/messages_compensation_2d.h"
#include "device/protocol/messages_path.h"
#include "device/protocol/messages_arch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace dev::proto;

struct Example {
    std::string name;
    std::uint8_t type;
    std::uint16_t seq;
    Bytes payload;
};

std::uint8_t t(MsgType m) { return static_cast<std::uint8_t>(m); }

/// mm → nm, µL → nL
constexpr std::int32_t nm(double mm) { return static_cast<std::int32_t>(mm * 1e6 + (mm < 0 ? -0.5 : 0.5)); }

std::vector<Example> examples()
{
    std::vector<Example> ex;
    ex.push_back({"hello-request", t(MsgType::Hello), 1, {}});

    HelloReply h;
    h.kind = DeviceKind::Stage;
    h.capabilities = CapHoming | CapGrating | CapClosedLoopPid | CapTelemetry | CapJogVelocity;
    h.controlPeriodUs = 1000;
    h.maxTelemetryRateHz = 10000;
    h.jogWatchdogMs = 250;
    h.linkBaud = 115200;
    h.model = "Stage";
    h.firmware = "sim 1.0";
    h.axes = {{'X', AxisUnit::Millimetre, 0, nm(100), static_cast<std::uint32_t>(nm(20)), 500},
              {'Y', AxisUnit::Millimetre, 0, nm(100), static_cast<std::uint32_t>(nm(20)), 500}};
    ex.push_back({"hello-reply", replyTypeOf(MsgType::Hello), 1, encode(h)});
    // The same stage to a host that reads the extension blocks: its planner's limits,
    // 200 mm/s² and 4000 mm/s³ per axis, 10 mm/s when a MOVE names no speed.
    ex.push_back({"hello-request-extended", t(MsgType::Hello), 1, encode(HelloRequest{HelloReadsExtensions})});
    h.motionLimits = MotionLimits{MotionProfile::JerkLimited, {{200000, 4000000, static_cast<std::uint32_t>(nm(10)), 0},
                                                               {200000, 4000000, static_cast<std::uint32_t>(nm(10)), 0}}};
    ex.push_back({"hello-reply-extended", replyTypeOf(MsgType::Hello), 1, encode(h)});

    ex.push_back({"status-request", t(MsgType::Status), 2, {}});
    StatusReply s;
    s.deviceFlags = 0;
    s.deviceTimeUs = 1500000;
    s.axes = {{nm(12.5), nm(12.4995), AxisHomed}, {nm(40), nm(40.0005), AxisHomed | AxisMoving | AxisHomeSwitch}};
    ex.push_back({"status-reply", replyTypeOf(MsgType::Status), 2, encode(s)});

    MoveRequest m;
    m.relative = false;
    m.speed = static_cast<std::uint32_t>(nm(10));
    m.axisMask = 0b11;
    m.targets = {nm(12.5), nm(40)};
    ex.push_back({"move-request", t(MsgType::Move), 3, encode(m)});
    ex.push_back({"move-reply", replyTypeOf(MsgType::Move), 3, {}});

    MoveRequest far;
    far.axisMask = 0b01;
    far.targets = {nm(120)};
    ex.push_back({"move-beyond-limit", t(MsgType::Move), 4, encode(far)});
    ErrorReply e;
    e.code = ErrorCode::SoftLimit;
    e.axis = 0;
    e.value = nm(100);
    e.message = "axis X beyond upper soft limit";
    ex.push_back({"error-soft-limit", t(MsgType::Error), 4, encode(e)});

    ex.push_back({"jog-velocity", t(MsgType::JogVelocity), 5, encode(JogVelocityRequest{0b01, {nm(-2.5)}})});
    ex.push_back({"jog-velocity-reply", replyTypeOf(MsgType::JogVelocity), 5, {}});
    ex.push_back({"stop-all", t(MsgType::Stop), 6, encode(AxisMaskRequest{0})});

    EventMsg done;
    done.kind = EventKind::MotionDone;
    done.axis = 1;
    done.deviceTimeUs = 2000000;
    done.position = nm(40.0005);
    ex.push_back({"event-motion-done", t(MsgType::Event), 0, encode(done)});
    EventMsg expired;
    expired.kind = EventKind::JogExpired;
    expired.axis = 0;
    expired.deviceTimeUs = 2450000;
    expired.position = nm(11.2);
    expired.text = "jog not refreshed";
    ex.push_back({"event-jog-expired", t(MsgType::Event), 1, encode(expired)});

    ex.push_back({"home-z", t(MsgType::Home), 7, encode(HomeRequest{0b0100})});
    ex.push_back({"estop", t(MsgType::EStop), 8, {}});

    SubscribeRequest sub;
    sub.rateHz = 100;
    sub.channels = {{0, ChannelKind::Measured}, {1, ChannelKind::Measured}, {0, ChannelKind::Switches}};
    ex.push_back({"subscribe-request", t(MsgType::Subscribe), 9, encode(sub)});
    ex.push_back({"subscribe-reply", replyTypeOf(MsgType::Subscribe), 9, encode(SubscribeReply{100, 2})});
    TelemetryBatch tb;
    tb.firstSampleIndex = 0;
    tb.firstSampleTimeUs = 3000000;
    tb.periodUs = 10000;
    tb.channels = sub.channels;
    tb.sampleCount = 2;
    tb.values = {nm(12.5), nm(40.0005), 1, nm(12.5005), nm(40), 0};
    ex.push_back({"telemetry-batch", t(MsgType::TelemetryBatch), 2, encode(tb)});
    for (auto& [name, type, seq, payload] : tuningdoc::examples())
        ex.push_back({name, type, seq, payload});
    for (auto& [name, type, seq, payload] : compensationdoc::examples())
        ex.push_back({name, type, seq, payload});

    // Path queue (docs/protocol.md, "Path queue"): a quarter circle and a line on the stage.
    ex.push_back({"path-begin-request", t(MsgType::PathBegin), 20, encode(PathBeginRequest{0, 0, 0})});
    PathStatusReply filling{PathState::Filling, 32, 32, 0, 0, 0, 0, PathReason::None, static_cast<std::uint32_t>(nm(100)), 10000};
    ex.push_back({"path-begin-reply", replyTypeOf(MsgType::PathBegin), 20, encode(filling)});
    PathAppendRequest app;
    app.firstIndex = 0;
    app.flags = PathAppendStart | PathAppendLast;
    PathSegmentWire quarter;
    quarter.kind = PathSegmentKind::ArcCcw;
    quarter.feed = static_cast<std::uint32_t>(nm(2));
    quarter.x = nm(50);
    quarter.y = nm(55);
    quarter.cx = nm(50);
    quarter.cy = nm(50);
    PathSegmentWire back;
    back.kind = PathSegmentKind::Line;
    back.feed = static_cast<std::uint32_t>(nm(2));
    back.x = nm(40);
    back.y = nm(55);
    app.segments = {quarter, back};
    ex.push_back({"path-append-request", t(MsgType::PathAppend), 21, encode(app)});
    PathStatusReply running{PathState::Running, 32, 31, 2, 0, 0, 0, PathReason::None, static_cast<std::uint32_t>(nm(100)), 10000};
    ex.push_back({"path-append-reply", replyTypeOf(MsgType::PathAppend), 21, encode(running)});
    ErrorReply outside;
    outside.code = ErrorCode::SoftLimit;
    outside.axis = 0;
    outside.value = nm(100);
    outside.message = "segment 7 (LINE) reaches X = 101.000 mm";
    ex.push_back({"path-append-soft-limit", t(MsgType::Error), 22, encode(outside)});
    ex.push_back({"path-hold", t(MsgType::PathHold), 23, {}});
    EventMsg done0;
    done0.kind = EventKind::PathSegmentDone;
    done0.axis = kNoAxis;
    done0.deviceTimeUs = 4000000;
    done0.position = 0;
    ex.push_back({"event-path-segment-done", t(MsgType::Event), 5, encode(done0)});

    // 2D compensation (docs/protocol.md, "2D compensation"): a 2 × 2 table over the
    // stage's 100 × 100 mm, uploaded in one part, enabled and kept, then only asked.
    Comp2dUploadRequest table;
    table.columns = 2;
    table.rows = 2;
    table.pitchX = nm(100);
    table.pitchY = nm(100);
    table.nodes = {{-1563, -1021}, {-96293, -1021}, {-1563, -65011}, {-96293, -65011}};
    ex.push_back({"comp2d-upload", static_cast<std::uint8_t>(kComp2dUpload), 40, encode(table)});
    ex.push_back({"comp2d-upload-reply", replyTypeOf(kComp2dUpload), 40, encode(Comp2dUploadReply{4, 1})});
    ex.push_back({"comp2d-enable-save", static_cast<std::uint8_t>(kComp2dEnable), 41,
                  encode(Comp2dEnableRequest{Comp2dEnableOn | Comp2dEnableSave})});
    ex.push_back({"comp2d-enable-reply", replyTypeOf(kComp2dEnable), 41,
                  encode(Comp2dEnableReply{Comp2dInstalled | Comp2dEnabled | Comp2dApplied | Comp2dSaved, 2, 2})});
    ex.push_back({"comp2d-query", static_cast<std::uint8_t>(kComp2dEnable), 42, encode(Comp2dEnableRequest{Comp2dEnableQuery})});
    // An arched move from one well of a 96-well plate to the next: X 29 mm, Y 30 mm, up to
    // Z 55.78 mm, down to 70 mm, each opening 2.93 mm; default speeds.
    ArchMoveRequest a;
    a.x = nm(29);
    a.y = nm(30);
    a.clearZ = nm(55.78);
    a.z = nm(70);
    a.departRadius = static_cast<std::uint32_t>(nm(2.93));
    a.approachRadius = static_cast<std::uint32_t>(nm(2.93));
    ex.push_back({"arch-move", t(MsgType::ArchMove), 43, encode(a)});
    ex.push_back({"arch-move-reply", replyTypeOf(MsgType::ArchMove), 43, {}});
    // The same, dispensing 50 µL below the plate's top (Z 60.78 mm), then up to the clearance.
    ArchPump pump;
    pump.delta = -50000;
    pump.liquidZ = nm(60.78);
    pump.leaveZ = nm(55.78);
    a.pump = pump;
    ex.push_back({"arch-move-pump", t(MsgType::ArchMove), 44, encode(a)});
    return ex;
}

Bytes bodyOf(const Example& x)
{
    Bytes b(3 + x.payload.size() + 2);
    b[0] = x.type;
    b[1] = static_cast<std::uint8_t>(x.seq & 0xFF);
    b[2] = static_cast<std::uint8_t>(x.seq >> 8);
    std::copy(x.payload.begin(), x.payload.end(), b.begin() + 3);
    b.resize(3 + x.payload.size());
    const std::uint16_t crc = crc16Ccitt(b.data(), b.size());
    b.push_back(static_cast<std::uint8_t>(crc & 0xFF));
    b.push_back(static_cast<std::uint8_t>(crc >> 8));
    return b;
}

Bytes wireOf(const Example& x)
{
    Bytes w;
    EXPECT_TRUE(encodeFrame(x.type, x.seq, x.payload.data(), x.payload.size(), w)) << x.name;
    return w;
}

std::string hex(const Bytes& b)
{
    std::string s;
    char buf[4];
    for (std::size_t i = 0; i < b.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%02X", b[i]);
        s += buf;
        s += (i + 1 == b.size()) ? "\n" : (i % 16 == 15) ? "\n" : " ";
    }
    return s;
}

std::string docPath()
{
    // From the build's idea of the source tree, not __FILE__: a compiler cache may
    // rewrite __FILE__ to a path relative to some other directory.
    return std::string(BP_SOURCE_DIR) + "/docs/protocol.md";
}

/// Blocks of the document: "body:NAME" / "wire:NAME" → the bytes of the fenced block after the marker.
std::map<std::string, Bytes> docBlocks(const std::string& text, std::vector<std::string>& problems)
{
    std::map<std::string, Bytes> blocks;
    std::size_t at = 0;
    const std::string open = "<!-- ";
    while ((at = text.find(open, at)) != std::string::npos) {
        const std::size_t end = text.find(" -->", at);
        if (end == std::string::npos)
            break;
        const std::string key = text.substr(at + open.size(), end - at - open.size());
        at = end;
        if (key.rfind("body:", 0) != 0 && key.rfind("wire:", 0) != 0)
            continue;
        const std::size_t fence = text.find("```", end);
        const std::size_t bodyStart = fence == std::string::npos ? fence : text.find('\n', fence);
        const std::size_t fenceEnd = bodyStart == std::string::npos ? bodyStart : text.find("```", bodyStart);
        if (fenceEnd == std::string::npos) {
            problems.push_back(key + ": no fenced block after the marker");
            continue;
        }
        std::istringstream in(text.substr(bodyStart, fenceEnd - bodyStart));
        Bytes bytes;
        std::string tok;
        while (in >> tok) {
            if (tok.size() != 2 || !std::isxdigit(static_cast<unsigned char>(tok[0]))
                || !std::isxdigit(static_cast<unsigned char>(tok[1]))) {
                problems.push_back(key + ": '" + tok + "' is not a hex byte");
                continue;
            }
            bytes.push_back(static_cast<std::uint8_t>(std::stoul(tok, nullptr, 16)));
        }
        if (blocks.count(key))
            problems.push_back(key + ": marker appears twice");
        blocks[key] = bytes;
    }
    return blocks;
}

TEST(CodecDocExamples, DocumentShowsTheEncodersBytes)
{
    const auto ex = examples();
    if (std::getenv("BP_DUMP_DOC_EXAMPLES")) {
        for (const auto& x : ex)
            std::printf("<!-- body:%s -->\n```\n%s```\n<!-- wire:%s -->\n```\n%s```\n\n", x.name.c_str(),
                        hex(bodyOf(x)).c_str(), x.name.c_str(), hex(wireOf(x)).c_str());
    }
    std::ifstream in(docPath());
    ASSERT_TRUE(in) << "cannot open " << docPath();
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<std::string> problems;
    const auto blocks = docBlocks(text, problems);
    for (const auto& p : problems)
        ADD_FAILURE() << docPath() << ": " << p;

    std::map<std::string, bool> known;
    for (const auto& x : ex) {
        for (const char* kind : {"body", "wire"}) {
            const std::string key = std::string(kind) + ":" + x.name;
            known[key] = true;
            const Bytes want = kind[0] == 'b' ? bodyOf(x) : wireOf(x);
            const auto it = blocks.find(key);
            if (it == blocks.end()) {
                ADD_FAILURE() << "docs/protocol.md has no block <!-- " << key << " -->; it should read:\n" << hex(want);
                continue;
            }
            EXPECT_EQ(hex(it->second), hex(want)) << "docs/protocol.md block " << key << " differs from the encoder";
        }
    }
    for (const auto& [key, bytes] : blocks)
        EXPECT_TRUE(known.count(key)) << "docs/protocol.md has a block <!-- " << key << " --> no test checks";
    EXPECT_GE(blocks.size(), 12u);
}

TEST(CodecDocExamples, WireBytesDecodeBackToTheExamples)
{
    for (const auto& x : examples()) {
        const Bytes w = wireOf(x);
        FrameDecoder d;
        std::vector<Frame> frames;
        d.feed(w.data(), w.size(), frames);
        ASSERT_EQ(frames.size(), 1u) << x.name;
        EXPECT_EQ(frames[0].type, x.type) << x.name;
        EXPECT_EQ(frames[0].seq, x.seq) << x.name;
        EXPECT_EQ(frames[0].payload, x.payload) << x.name;
    }
}

} // namespace
