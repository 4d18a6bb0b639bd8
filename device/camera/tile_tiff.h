#pragma once
// A tile's image file: a baseline TIFF (16-bit grey, 8-bit grey or 8-bit RGB, as the source
// gave it; uncompressed, so any reader opens it) with the pixel size in its resolution tags
// and, in ImageDescription, one line of JSON saying what it is: the tile, where the stage
// stood (measured), the device time, the exposure and the pixel size (docs/camera.md).
// Written to NAME.part beside it, flushed to disk and renamed: a crash or a full disk
// leaves either the whole file or none. Thread-safe; the scan calls it off the GUI thread.
#include "device/camera/frame.h"
#include "motion/message.h"

#include <optional>
#include <string>
#include <vector>

namespace dev::camera {

struct TileMetadata {
    int tile = -1;                ///< −1: a snap
    std::string label;            ///< the file's name in the scan's folder
    std::vector<double> measuredMm;  ///< [x, y] the grating read when the tile was taken; empty: unknown
    std::optional<std::uint64_t> deviceTimeUs;
    std::string source;           ///< the camera, as the operator named it
};

/// The description JSON (also what tests read back).
std::string tileDescription(const Frame& frame, const TileMetadata& meta);

/// Writes `frame` to `path` (temporary name, then rename). On success `sha256Hex` holds the
/// file's SHA-256 (lower-case hex) when given.
bool writeTileTiff(const std::string& path, const Frame& frame, const TileMetadata& meta, std::string* sha256Hex,
                   motion::msg::Message* error);

/// The SHA-256 of a file, lower-case hex; nullopt when it cannot be read.
std::optional<std::string> fileSha256(const std::string& path);

/// Reads a TIFF this writer (or a camera) wrote, into a Frame (grey 8/16, RGB 8); the
/// description, when asked. For tests, the resume check and the folder source.
bool readTiff(const std::string& path, Frame* frame, std::string* description, motion::msg::Message* error);

} // namespace dev::camera
