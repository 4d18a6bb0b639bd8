#pragma once
// The simulated camera's socket (benchpilot-sim --camera-socket PATH, the camera sim:PATH):
// requests and answers as they travel, and the reader that takes them off a byte stream.
// docs/camera.md ("The simulated camera on a socket") gives the format with an example;
// resources/examples/sim-camera.socket.txt is one conversation.
//
// Each message is one line of JSON, its header, at most kSimWireMaxHeaderBytes with the '\n';
// a frame's header is followed by exactly `bytes` bytes of pixels (16-bit little-endian).
// Every header says "schema": "benchpilot.sim-camera" and "version": 1.
//
// Nothing from the wire is trusted: the header's length is bounded before it is parsed,
// every number is checked against its range before it is used, a frame's `bytes` must be
// its width × height × bytes a pixel (each side at most kSimWireMaxSidePx), and pixels are
// stored as they arrive, never allocated from a size the peer sent.
#include "device/camera/camera_geometry.h"
#include "device/camera/frame.h"
#include "motion/message.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

namespace dev::camera {

constexpr const char* kSimWireSchema = "benchpilot.sim-camera";
constexpr int kSimWireVersion = 1;
constexpr std::size_t kSimWireMaxHeaderBytes = 4096;
constexpr int kSimWireMaxSidePx = 8192;
constexpr double kSimWireMaxExposureMs = 60000;
constexpr double kSimWireMaxPixelUm = 1000;
/// Ids and counters travel as JSON numbers: whole numbers up to 2^53 are exact there.
constexpr double kSimWireMaxInteger = 9007199254740991.0;

/// What the server says first, on every connection.
struct SimWireHello {
    std::string specimen;
    std::uint64_t seed = 0;
    CameraGeometry geometry;   ///< what a capture without a geometry gets
};

/// One image, please: exposure starting when the server reads this.
struct SimWireCapture {
    std::uint64_t id = 0;      ///< from 1; the answer carries it
    double exposureMs = 10;
    std::optional<CameraGeometry> geometry;
};

/// The image for capture `id`.
struct SimWireFrame {
    std::uint64_t id = 0;
    Frame frame;               ///< its pixels, exposure, pixel size, device time, sequence
    std::optional<double> trueXMm, trueYMm;  ///< where the work point truly was (for tests and logs)
};

/// No image for `id` (0: not about a request), and why: `code` a stable word, `detail` for a log.
struct SimWireError {
    std::uint64_t id = 0;
    std::string code;
    std::string detail;
};

using SimWireMessage = std::variant<SimWireHello, SimWireCapture, SimWireFrame, SimWireError>;

std::string encodeSimWire(const SimWireHello& m);
std::string encodeSimWire(const SimWireCapture& m);
/// The header line and the pixels after it.
std::string encodeSimWire(const SimWireFrame& m);
std::string encodeSimWire(const SimWireError& m);

/// Reads messages off a stream in any chunking. Once a message is wrong the stream cannot be
/// trusted to find the next one: the reader stays broken and says why (camera.wire.*).
class SimWireReader {
public:
    enum class Side {
        Server,  ///< reads what a client sends: captures
        Client,  ///< reads what a server sends: hello, frames, errors
    };
    enum class Result { NeedMore, Message, Broken };

    explicit SimWireReader(Side side) : m_side(side) {}

    void feed(const char* data, std::size_t size);
    /// The next whole message into `out`; Broken with the reason in `error` (every call after).
    Result next(SimWireMessage* out, motion::msg::Message* error);

    bool broken() const { return !m_error.empty(); }
    /// Bytes held that are not yet a message: a frame's pixels as they arrive, and what follows.
    std::size_t buffered() const { return unreadBytes() + (m_pending ? m_pending->frame.pixels.size() : 0); }
    /// Bytes not yet taken into a message; after NeedMore, fewer than kSimWireMaxHeaderBytes.
    std::size_t unreadBytes() const { return m_buf.size() - m_pos; }

private:
    Result breakWith(motion::msg::Message why, motion::msg::Message* error);
    bool parseHeader(const std::string& line, SimWireMessage* out, motion::msg::Message* error);

    Side m_side;
    std::string m_buf;
    std::size_t m_pos = 0;
    std::optional<SimWireFrame> m_pending;  ///< a frame whose pixels are still arriving
    std::size_t m_pendingBytes = 0;
    motion::msg::Message m_error;
};

} // namespace dev::camera
