// The simulated camera's socket format (device/camera/sim_wire.h): the examples read as
// docs/camera.md says, every message comes back the same in any chunking, and nothing read
// from the wire is trusted (sizes, ranges, versions), each refusal saying why.
#include "device/camera/sim_wire.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>

namespace cam = dev::camera;

namespace {

std::string wireExample(const char* name)
{
    std::ifstream in(std::string(BP_SOURCE_DIR) + "/resources/examples/" + name, std::ios::binary);
    EXPECT_TRUE(in.good()) << name;
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Every message of `bytes` fed `chunk` bytes at a time; the reason in `error` when it broke.
std::vector<cam::SimWireMessage> readWire(cam::SimWireReader::Side side, const std::string& bytes, std::size_t chunk,
                                          motion::msg::Message* error = nullptr)
{
    cam::SimWireReader reader(side);
    std::vector<cam::SimWireMessage> out;
    for (std::size_t at = 0; at < bytes.size(); at += chunk) {
        reader.feed(bytes.data() + at, std::min(chunk, bytes.size() - at));
        for (;;) {
            cam::SimWireMessage m;
            motion::msg::Message why;
            const auto r = reader.next(&m, &why);
            if (r == cam::SimWireReader::Result::Message) {
                out.push_back(std::move(m));
                continue;
            }
            if (r == cam::SimWireReader::Result::Broken && error)
                *error = why;
            if (r == cam::SimWireReader::Result::Broken)
                return out;
            break;
        }
    }
    return out;
}

std::string header(const std::string& fields)
{
    return R"({"schema":"benchpilot.sim-camera","version":1,)" + fields + "}\n";
}

motion::msg::Message refusal(cam::SimWireReader::Side side, const std::string& bytes)
{
    motion::msg::Message why;
    readWire(side, bytes, bytes.size() + 1, &why);
    return why;
}

} // namespace

TEST(SimWire, TheExamplesReadAsDocumented)
{
    const auto requests = readWire(cam::SimWireReader::Side::Server, wireExample("sim-camera.requests.jsonl"), 4096);
    ASSERT_EQ(requests.size(), 2u);
    const auto& first = std::get<cam::SimWireCapture>(requests[0]);
    EXPECT_EQ(first.id, 1u);
    EXPECT_EQ(first.exposureMs, 10);
    EXPECT_FALSE(first.geometry);
    const auto& second = std::get<cam::SimWireCapture>(requests[1]);
    ASSERT_TRUE(second.geometry);
    EXPECT_EQ(second.geometry->sensorWidthPx, 4);
    EXPECT_EQ(second.geometry->sensorHeightPx, 2);
    EXPECT_EQ(second.geometry->pixelUm, 1);
    EXPECT_TRUE(second.geometry->imageYAlongMinusY);

    const auto answers = readWire(cam::SimWireReader::Side::Client, wireExample("sim-camera.answers.txt"), 4096);
    ASSERT_EQ(answers.size(), 3u);
    const auto& hello = std::get<cam::SimWireHello>(answers[0]);
    EXPECT_EQ(hello.specimen, "slide");
    EXPECT_EQ(hello.geometry.sensorWidthPx, 2048);
    EXPECT_DOUBLE_EQ(hello.geometry.pixelUm, 0.65);
    const auto& frame = std::get<cam::SimWireFrame>(answers[1]);
    EXPECT_EQ(frame.id, 2u);
    EXPECT_EQ(frame.frame.width, 4);
    EXPECT_EQ(frame.frame.height, 2);
    EXPECT_EQ(frame.frame.format, cam::PixelFormat::Grey8);
    EXPECT_EQ(std::string(frame.frame.pixels.begin(), frame.frame.pixels.end()), "ABCDEFGH") << "the pixels are the 8 bytes after the header";
    EXPECT_EQ(frame.frame.deviceTimeUs.value_or(0), 1234500u);
    EXPECT_DOUBLE_EQ(frame.trueXMm.value_or(0), 20.0012);
    const auto& error = std::get<cam::SimWireError>(answers[2]);
    EXPECT_EQ(error.id, 3u);
    EXPECT_EQ(error.code, "busy");
}

TEST(SimWire, EveryMessageComesBackTheSameInAnyChunkingWithGrey16LittleEndian)
{
    cam::SimWireHello hello;
    hello.specimen = "grid-plate";
    hello.seed = 42;
    hello.geometry.sensorWidthPx = 640;
    hello.geometry.rotationDeg = -1.5;
    hello.geometry.imageYAlongMinusY = false;
    cam::SimWireFrame frame;
    frame.id = 9;
    frame.frame.width = 3;
    frame.frame.height = 2;
    frame.frame.format = cam::PixelFormat::Grey16;
    frame.frame.bitDepth = 12;
    frame.frame.exposureMs = 2.5;
    frame.frame.pixelUm = 0.65;
    frame.frame.sequence = 7;
    frame.frame.deviceTimeUs = 99;
    const std::uint16_t values[6] = {0x0102, 0, 0xffff, 4095, 10, 0x8000};
    frame.frame.pixels.resize(sizeof values);
    std::memcpy(frame.frame.pixels.data(), values, sizeof values);
    cam::SimWireError error;
    error.id = 0;
    error.code = "bad_request";
    error.detail = "x\ny \"quoted\"";
    const std::string frameBytes = cam::encodeSimWire(frame);
    // On the wire, 0x0102 is 02 01: little-endian whatever the host.
    const std::size_t pixelsAt = frameBytes.find('\n') + 1;
    EXPECT_EQ(static_cast<unsigned char>(frameBytes[pixelsAt]), 0x02);
    EXPECT_EQ(static_cast<unsigned char>(frameBytes[pixelsAt + 1]), 0x01);
    const std::string stream = cam::encodeSimWire(hello) + frameBytes + cam::encodeSimWire(error) + frameBytes;

    for (std::size_t chunk : {std::size_t(1), std::size_t(3), std::size_t(7), std::size_t(64), stream.size()}) {
        const auto got = readWire(cam::SimWireReader::Side::Client, stream, chunk);
        ASSERT_EQ(got.size(), 4u) << "chunk " << chunk;
        const auto& h = std::get<cam::SimWireHello>(got[0]);
        EXPECT_EQ(h.specimen, "grid-plate");
        EXPECT_EQ(h.seed, 42u);
        EXPECT_EQ(h.geometry.sensorWidthPx, 640);
        EXPECT_DOUBLE_EQ(h.geometry.rotationDeg, -1.5);
        EXPECT_FALSE(h.geometry.imageYAlongMinusY);
        for (int k : {1, 3}) {
            const auto& f = std::get<cam::SimWireFrame>(got[static_cast<std::size_t>(k)]);
            EXPECT_EQ(f.frame.pixels, frame.frame.pixels);
            EXPECT_EQ(f.frame.bitDepth, 12);
            EXPECT_EQ(f.frame.sequence, 7u);
            EXPECT_DOUBLE_EQ(f.frame.exposureMs, 2.5);
        }
        EXPECT_EQ(std::get<cam::SimWireError>(got[2]).detail, error.detail);
    }

    cam::SimWireCapture capture;
    capture.id = 123456789012345ull;
    capture.exposureMs = 0.25;
    capture.geometry = cam::CameraGeometry{};
    capture.geometry->rotationDeg = 3;
    const auto back = readWire(cam::SimWireReader::Side::Server, cam::encodeSimWire(capture), 5);
    ASSERT_EQ(back.size(), 1u);
    const auto& c = std::get<cam::SimWireCapture>(back[0]);
    EXPECT_EQ(c.id, capture.id);
    EXPECT_DOUBLE_EQ(c.exposureMs, 0.25);
    ASSERT_TRUE(c.geometry);
    EXPECT_DOUBLE_EQ(c.geometry->rotationDeg, 3);
}

TEST(SimWire, NothingFromTheWireIsTrustedAndEachRefusalSaysWhy)
{
    using Side = cam::SimWireReader::Side;
    const std::string frameFields = R"("type":"frame","id":1,"format":"grey16","bit_depth":16,"exposure_ms":1,"pixel_um":1,"sequence":0,)";
    // A size that is not width × height × 2: refused before a byte is stored.
    EXPECT_EQ(refusal(Side::Client, header(frameFields + R"("width_px":2,"height_px":2,"bytes":1000000000000)")).id, "camera.wire.size");
    EXPECT_EQ(refusal(Side::Client, header(frameFields + R"("width_px":2,"height_px":2,"bytes":7)")).id, "camera.wire.size");
    // Sides beyond the bound, negative, fractional, or not numbers.
    for (const char* side : {"8193", "0", "-1", "2.5", "\"2\"", "1e300"}) {
        const auto why = refusal(Side::Client, header(frameFields + R"("height_px":2,"bytes":4,"width_px":)" + side));
        EXPECT_EQ(why.id, "camera.wire.field") << side;
        EXPECT_EQ(why.text("field"), "width_px") << side;
    }
    EXPECT_EQ(refusal(Side::Server, header(R"("type":"capture","id":1,"exposure_ms":1e9)")).text("field"), "exposure_ms");
    EXPECT_EQ(refusal(Side::Server, header(R"("type":"capture","id":0,"exposure_ms":1)")).text("field"), "id");
    EXPECT_EQ(refusal(Side::Server, header(R"("type":"capture","id":1,"exposure_ms":1,"camera":{"width_px":8,"height_px":8,"pixel_um":0,"rotation_deg":0,"image_y":"-y"})"))
                  .text("field"),
              "camera.pixel_um");
    // Another version, another schema, not JSON, a header with no end, a message for the other side.
    const auto version = refusal(Side::Server, R"({"schema":"benchpilot.sim-camera","version":2,"type":"capture","id":1,"exposure_ms":1})" "\n");
    EXPECT_EQ(version.id, "camera.wire.version");
    EXPECT_EQ(version.text("version"), "2");
    EXPECT_EQ(refusal(Side::Server, R"({"schema":"benchpilot.tile","version":1})" "\n").id, "camera.wire.schema");
    EXPECT_EQ(refusal(Side::Server, "GET / HTTP/1.1\r\n").id, "camera.wire.not_json");
    EXPECT_EQ(refusal(Side::Client, header(R"("type":"capture","id":1,"exposure_ms":1)")).id, "camera.wire.unexpected");

    cam::SimWireReader endless(Side::Client);
    const std::string noNewline(1000, 'x');
    motion::msg::Message why;
    cam::SimWireMessage m;
    for (int i = 0; i < 100 && !endless.broken(); ++i) {
        endless.feed(noNewline.data(), noNewline.size());
        endless.next(&m, &why);
        EXPECT_LE(endless.buffered(), cam::kSimWireMaxHeaderBytes + noNewline.size()) << "the reader holds a bounded header";
    }
    EXPECT_EQ(why.id, "camera.wire.header_too_long");
    // Broken is for good: what comes after cannot be found in step.
    const std::string good = wireExample("sim-camera.answers.txt");
    endless.feed(good.data(), good.size());
    EXPECT_EQ(endless.next(&m, &why), cam::SimWireReader::Result::Broken);
}
