#pragma once
// What the scan runner needs of a camera: take the tile now that the stage has settled,
// say when the exposure is over (the stage may move on), then hand back the written
// image's file name and checksum, or why not. The runner lives in `device`; the cameras
// and the TIFF writer live in `device_camera` above it (dev::camera::ScanCamera implements
// this), so `device` needs neither libtiff nor a multimedia library.
//
// Order: for each take(), exactly one of exposed() … then written() or failed(), or
// failed() alone; written() comes in the order the tiles were taken.
#include "motion/message.h"

#include <QObject>

#include <optional>
#include <string>
#include <vector>

namespace motion::scan {
struct ScanPlan;
}

namespace dev::jobs {

struct TileShot {
    int tile = -1;
    std::string file;                  ///< the image's name in the output folder (the plan's pattern)
    std::vector<double> measuredMm;    ///< the grating's reading at the trigger
    std::uint64_t deviceTimeUs = 0;    ///< the device's clock at that reading
};

struct TileImage {
    std::string file;
    std::string sha256;
    std::optional<std::uint64_t> frameDeviceTimeUs;  ///< the frame's own device time, where the source knows it
};

class ScanTileCamera : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    ~ScanTileCamera() override = default;

    /// Readies the camera for the plan and the folder the images go to; false with the
    /// reason (the camera is not there, its sensor is not the plan's, …).
    virtual bool begin(const motion::scan::ScanPlan& plan, const std::string& folder, motion::msg::Message* error) = 0;
    virtual void take(const TileShot& shot) = 0;
    /// Images taken and not yet written.
    virtual int pendingWrites() const = 0;
    /// Time a tile costs beyond the plan's exposure (transfer, the source's own delay), for
    /// the estimate.
    virtual double overheadPerTileS() const = 0;
    /// The camera, as the operator named it ("sim", "command:…").
    virtual std::string sourceName() const = 0;

signals:
    void exposed(int tile);
    void written(int tile, const dev::jobs::TileImage& image);
    void failed(int tile, const motion::msg::Message& reason);
};

} // namespace dev::jobs
