// Fuzz target "sim_camera_wire": what travels on the simulated camera's socket
// (device/camera/sim_wire.h), read as the server reads requests and as the camera sim:PATH
// reads answers. Not a file people keep, but a stream from another process whose mutations
// this engine makes well: header lines deleted, repeated, truncated, spliced, numbers made
// hostile.
// Invariants: nothing crashes or hangs; the reader gives the same messages and the same
// verdict however the bytes are chunked; it never holds more than a header's bound when no
// frame is arriving; an accepted frame has exactly width × height × bytes-a-pixel pixels with
// each side in bounds; every accepted message encodes and reads back to the same bytes.
#include "fuzz_files.h"

#include "device/camera/sim_wire.h"
#include "motion/message.h"

namespace {

namespace cam = dev::camera;

std::vector<std::string> seeds()
{
    std::vector<std::string> out = fuzzfiles::exampleFiles(".requests.jsonl");
    for (std::string& s : fuzzfiles::exampleFiles("sim-camera.answers.txt"))
        out.push_back(std::move(s));
    cam::SimWireFrame f;
    f.id = 3;
    f.frame.width = 3;
    f.frame.height = 2;
    f.frame.format = cam::PixelFormat::Grey16;
    f.frame.pixels = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    f.frame.deviceTimeUs = 77;
    f.trueXMm = 1.5;
    f.trueYMm = -2;
    cam::SimWireFrame rgb = f;
    rgb.id = 4;
    rgb.frame.format = cam::PixelFormat::Rgb8;
    rgb.frame.bitDepth = 8;
    rgb.frame.pixels.assign(18, 200);
    cam::SimWireError e;
    e.id = 0;
    e.code = "bad_request";
    e.detail = "camera.wire.field{field=id}";
    out.push_back(cam::encodeSimWire(f) + cam::encodeSimWire(rgb) + cam::encodeSimWire(e));
    return out;
}

std::string encoded(const cam::SimWireMessage& m)
{
    return std::visit([](const auto& v) { return cam::encodeSimWire(v); }, m);
}

struct Reading {
    std::vector<std::string> messages;  ///< each re-encoded
    std::string brokenId;
};

Reading readAll(cam::SimWireReader::Side side, std::string_view input, std::size_t chunk)
{
    Reading r;
    cam::SimWireReader reader(side);
    for (std::size_t at = 0; at < input.size() && r.brokenId.empty(); at += chunk) {
        const std::size_t n = std::min(chunk, input.size() - at);
        reader.feed(input.data() + at, n);
        for (;;) {
            cam::SimWireMessage m;
            motion::msg::Message why;
            const auto res = reader.next(&m, &why);
            if (res == cam::SimWireReader::Result::Broken) {
                if (why.id.rfind("camera.wire.", 0) != 0)
                    fuzzfiles::fail("a refusal without its reason: " + why.id);
                r.brokenId = why.id;
                break;
            }
            if (res == cam::SimWireReader::Result::NeedMore) {
                if (reader.unreadBytes() >= cam::kSimWireMaxHeaderBytes)
                    fuzzfiles::fail("the reader holds more than a header's bound unread");
                break;
            }
            if (const auto* f = std::get_if<cam::SimWireFrame>(&m)) {
                const auto& fr = f->frame;
                if (fr.width < 1 || fr.height < 1 || fr.width > cam::kSimWireMaxSidePx || fr.height > cam::kSimWireMaxSidePx
                    || fr.pixels.size() != static_cast<std::size_t>(fr.width) * static_cast<std::size_t>(fr.height)
                                               * static_cast<std::size_t>(cam::bytesPerPixel(fr.format)))
                    fuzzfiles::fail("a frame whose pixels are not its size was accepted");
            }
            r.messages.push_back(encoded(m));
        }
        if (reader.buffered() > at + n)
            fuzzfiles::fail("the reader holds more than it was given");
    }
    return r;
}

void check(std::string_view input)
{
    for (const auto side : {cam::SimWireReader::Side::Server, cam::SimWireReader::Side::Client}) {
        const Reading whole = readAll(side, input, input.size() + 1);
        const Reading chunked = readAll(side, input, 1 + input.size() % 7);
        if (whole.messages != chunked.messages || whole.brokenId != chunked.brokenId)
            fuzzfiles::fail("chunking changed what was read");
        // What was accepted writes back and reads again the same.
        std::string again;
        for (const std::string& m : whole.messages)
            again += m;
        const Reading back = readAll(side, again, again.size() + 1);
        if (!back.brokenId.empty() || back.messages != whole.messages)
            fuzzfiles::fail("an accepted message does not read back the same: " + back.brokenId);
    }
}

} // namespace

BP_FUZZ_FILE_TARGET({"sim_camera_wire", seeds, check});
