#pragma once
// The tuning examples of docs/protocol.md ("Tuning"), for codec_doc_examples_test.cpp.
#include "device/protocol/messages_tuning.h"

#include <string>
#include <tuple>
#include <vector>

namespace tuningdoc {

/// (name, type, seq, payload) of every tuning example in the document.
inline std::vector<std::tuple<std::string, std::uint8_t, std::uint16_t, dev::proto::Bytes>> examples()
{
    using namespace dev::proto;
    auto t = [](MsgType m) { return static_cast<std::uint8_t>(m); };
    auto reply = [](MsgType m) { return replyTypeOf(m); };
    std::vector<std::tuple<std::string, std::uint8_t, std::uint16_t, Bytes>> ex;
    ex.emplace_back("get-gains", t(kGetGains), 20, encode(AxisRequest{0}));
    GainsReply g;
    g.axis = 0;
    g.controlPeriodUs = 1000;
    g.gains = {0.25f, 0.5f, 0.03f};
    g.saved = g.gains;
    g.limits = {100, 100, 100};
    ex.emplace_back("gains-reply", reply(kGetGains), 20, encode(g));
    ex.emplace_back("set-gains", t(kSetGains), 21, encode(SetGainsRequest{0, 0, {3.0f, 1.75f, 1.25f}}));
    ErrorReply bad;
    bad.code = kErrBadGains;
    bad.axis = 0;
    bad.value = 1;
    bad.message = "ki = -1 must not be negative";
    ex.emplace_back("set-gains-nan", t(kSetGains), 22,
                    encode(SetGainsRequest{0, 0, {0.25f, -1.0f, 0.03f}}));
    ex.emplace_back("error-bad-gains", t(MsgType::Error), 22, encode(bad));
    StepTestRequest s;
    s.axis = 0;
    s.step = 10000;          // 10 µm
    s.settleBand = 1000;     // 1 µm
    s.settleHoldMs = 20;
    s.runMs = 300;
    s.envelope = {18000, 18000, 1000};
    s.trialGains = WireGains{4.0f, 0, 0};
    ex.emplace_back("step-test-trial", t(kStepTest), 23, encode(s));
    EventMsg tripped;
    tripped.kind = kEvTestTripped;
    tripped.axis = 0;
    tripped.deviceTimeUs = 5012000;
    tripped.position = 50018500;
    tripped.text = "max excursion 0.0180 mm crossed (0.0185 mm)";
    ex.emplace_back("event-test-tripped", t(MsgType::Event), 9, encode(tripped));
    ex.emplace_back("relay-test", t(kRelayTest), 24, encode(RelayTestRequest{0, 10000, 1000, 0, 20, {50000, 50000, 2000}}));
    ex.emplace_back("get-capture", t(kGetCapture), 25, encode(CaptureRequest{0, 0, 2}));
    CaptureReply c;
    c.axis = 0;
    c.kind = 2;
    c.reason = 2;
    c.testId = 4;
    c.periodUs = 1000;
    c.total = 84;
    c.startPosition = 50000000;
    c.first = 0;
    c.samples = {{50000000, 50000000, 10000}, {50000000, 50001500, 10000}};
    ex.emplace_back("capture-reply", reply(kGetCapture), 25, encode(c));
    ex.emplace_back("test-abort", t(kTestAbort), 26, encode(AbortRequest{0}));
    return ex;
}

} // namespace tuningdoc
