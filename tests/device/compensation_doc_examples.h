#pragma once
// The compensation examples of docs/protocol.md ("Compensation", worked example 13),
// for codec_doc_examples_test.cpp.
#include "device/protocol/messages_compensation.h"

#include <string>
#include <tuple>
#include <vector>

namespace compensationdoc {

/// (name, type, seq, payload) of every compensation example in the document.
inline std::vector<std::tuple<std::string, std::uint8_t, std::uint16_t, dev::proto::Bytes>> examples()
{
    using namespace dev::proto;
    auto t = [](MsgType m) { return static_cast<std::uint8_t>(m); };
    auto reply = [](MsgType m) { return replyTypeOf(m); };
    std::vector<std::tuple<std::string, std::uint8_t, std::uint16_t, Bytes>> ex;
    // Seed 002's Y curve, 1.021 + 0.6397·y + 0.0168·y² µm, fitted over 0–100 mm, no backlash.
    CompUploadRequest poly;
    poly.axis = 1;
    poly.kind = CompKind::Polynomial;
    poly.backlash = 0;
    poly.total = 3;
    poly.first = 0;
    poly.validFrom = 0;
    poly.validTo = 100000000;
    poly.coefficients = {1.021, 0.6397, 0.0168};
    ex.emplace_back("comp-upload-polynomial", t(kCompUpload), 30, encode(poly));
    ex.emplace_back("comp-upload-polynomial-reply", reply(kCompUpload), 30, encode(CompUploadReply{1, 3, 1}));
    // The first part of a 5-point table on X with 4 µm of backlash: points 0–2 (a real
    // upload sends up to 80 a part; three keep the example short).
    CompUploadRequest part;
    part.axis = 0;
    part.kind = CompKind::Table;
    part.backlash = 4000;
    part.total = 5;
    part.first = 0;
    part.points = {{0, -1563, -1563}, {25000000, -25120, -25120}, {50000000, -47380, -47380}};
    ex.emplace_back("comp-upload-table-part", t(kCompUpload), 31, encode(part));
    ex.emplace_back("comp-upload-table-part-reply", reply(kCompUpload), 31, encode(CompUploadReply{0, 3, 0}));
    // A second part that starts at the wrong entry.
    ErrorReply seq;
    seq.code = kErrCompSequence;
    seq.axis = 0;
    seq.value = 3;
    seq.message = "part from entry 2 of axis X's compensation: the device expects entry 3 of the upload in progress";
    ex.emplace_back("comp-error-sequence", t(MsgType::Error), 32, encode(seq));
    ex.emplace_back("comp-enable-save", t(kCompEnable), 33, encode(CompEnableRequest{0b10, CompEnableOn | CompEnableSave}));
    ex.emplace_back("comp-enable-reply", reply(kCompEnable), 33, Bytes{});
    EventMsg changed;
    changed.kind = kEvCompChanged;
    changed.axis = 1;
    changed.deviceTimeUs = 5000000;
    changed.position = 0;
    changed.text = "enabled, kept for power-up";
    ex.emplace_back("event-comp-changed", t(MsgType::Event), 6, encode(changed));
    ex.emplace_back("comp-get", t(kCompGet), 34, encode(CompGetRequest{1, 0, kMaxCompPointsPerFrame}));
    CompGetReply got;
    got.axis = 1;
    got.kind = CompKind::Polynomial;
    got.flags = CompEnabled | CompApplied | CompSaved;
    got.total = 3;
    got.validTo = 100000000;
    got.coefficients = poly.coefficients;
    ex.emplace_back("comp-get-reply", reply(kCompGet), 34, encode(got));
    return ex;
}

} // namespace compensationdoc
