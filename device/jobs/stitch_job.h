#pragma once
// Stitching a scan's folder from the GUI: the tiles the run log says were taken, placed
// by the plan's camera (pixel size, rotation, image y), registered, placed and fused off
// the caller's thread, into the files `benchpilot-cli stitch` writes (docs/stitching.md):
// the pyramidal OME-TIFF, Fiji's TileConfiguration.registered.txt and the .stitch.json
// report. The caller's thread is never held: start() only reads the run log.
#include "imaging/stitch.h"
#include "motion/plans/scan/scan_plan.h"
#include "motion/problem.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <memory>
#include <optional>

namespace dev::jobs {

struct StitchRequest {
    QString folder;                      ///< the scan's output folder: its run log and images
    motion::scan::ScanPlan plan;         ///< the camera's geometry comes from here
    double repeatabilityUm = 1.0;        ///< the stage's (1σ): the weight of its positions
    QString mosaicName = QStringLiteral("mosaic.ome.tif");
    QString flatPath;                    ///< a blank image to divide every tile by; "" = none
    double darkLevel = 0;                ///< the camera's offset under the blank, grey levels
};

class StitchJob : public QObject {
    Q_OBJECT
public:
    explicit StitchJob(QObject* parent = nullptr);
    ~StitchJob() override;

    /// Reads the run log and starts; false with why (a job running, no run log, no image
    /// taken, a tile's image missing).
    bool start(const StitchRequest& request, motion::msg::Message* error);
    bool isRunning() const { return m_running; }
    int tileCount() const { return m_tileCount; }
    /// The last finished stitch, and the files it wrote (mosaic first).
    const std::optional<imaging::StitchResult>& result() const { return m_result; }
    const QStringList& written() const { return m_written; }
    double seconds() const { return m_seconds; }
    /// The stage's repeatability in image pixels, as the last stitch weighed it.
    double pixelUm() const { return m_pixelUm; }

signals:
    void finished();
    void failed(const motion::msg::Problems& problems);

private:
    struct Shared;
    std::shared_ptr<Shared> m_shared;    ///< the worker's hand-back; outlives this object if need be
    bool m_running = false;
    int m_tileCount = 0;
    double m_pixelUm = 0;
    double m_seconds = 0;
    std::optional<imaging::StitchResult> m_result;
    QStringList m_written;
};

} // namespace dev::jobs
