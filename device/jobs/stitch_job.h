#pragma once
// Stitching a scan's folder from the GUI: the tiles the run log says were taken, placed
// by the plan's camera (pixel size, rotation, image y), registered, placed and fused off
// the caller's thread, into the files `benchpilot-cli stitch` writes (docs/stitching.md):
// the pyramidal OME-TIFF, Fiji's TileConfiguration.registered.txt and the .stitch.json
// report. The caller's thread is never held: start() only reads the run log.
//
// Live (follow()): while a scan with a camera runs, each tile written is registered
// against its taken neighbours off the GUI thread (imaging/live_stitch.h); when the last
// is written, the placement and the same files follow, and finished() is emitted as for
// start(). A stop drops the live stitch (nothing is written); a resumed scan begins it
// again, reading the tiles taken before from the folder.
#include "imaging/stitch.h"
#include "motion/plans/scan/scan_plan.h"
#include "motion/problem.h"

#include <QElapsedTimer>
#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QSize>
#include <QString>
#include <QStringList>

#include <functional>
#include <memory>
#include <optional>

namespace imaging {
class LiveStitcher;
}

namespace dev::jobs {

class ScanRunner;

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
    /// The folder of the last stitch, live or not.
    const QString& folder() const { return m_folder; }

    /// Stitches `runner`'s camera scans live as they run; `request` gives the stage's
    /// repeatability and the mosaic's name (the folder and the plan are the runner's).
    void follow(ScanRunner* runner, std::function<StitchRequest()> request);
    /// A live stitch is registering tiles as the scan takes them.
    bool isLive() const { return m_live != nullptr; }
    /// The last finished stitch was the live one; how long after the last tile it was
    /// placed, and its files written.
    bool lastWasLive() const { return m_lastWasLive; }
    double livePlacedAfterS() const { return m_livePlacedAfterS; }
    /// The live stitch's tiles as the plan puts them (image px), for drawing those to come.
    const std::vector<QPointF>& livePlannedPx() const { return m_livePlannedPx; }
    int liveTilesRead() const { return m_liveTilesRead; }

signals:
    void finished();
    void failed(const motion::msg::Problems& problems);
    /// A live stitch began (livePlannedPx() holds its tiles), or was dropped by a stop.
    void liveStarted();
    void liveDropped();
    /// A pair registered, and a tile read and registered against its neighbours present (its
    /// measured top-left and size in image px, and a small copy), as they happen; then finished() or failed() once the scan is done.
    void liveTile(int tile, QPointF stagePx, QSize size, std::shared_ptr<const imaging::ImageU16> thumbnail);
    void livePair(const imaging::TilePair& pair);

private:
    struct Shared {
        QPointer<StitchJob> owner;
    };
    struct Live;
    /// The files besides the mosaic, and the hand-back on the caller's thread (worker side).
    static void complete(const std::shared_ptr<Shared>& shared, motion::msg::Checked<imaging::StitchResult> result, const QString& folder,
                         const QString& mosaic, const QElapsedTimer& clock, double placedS);
    static imaging::StitchOptions optionsFor(const motion::scan::ScanPlan& plan, const QString& folder, const StitchRequest& request, double pixelUm);
    void onScanState();
    void onScanTile(int tile);
    void onScanFinished();
    void dropLive();
    QPointF measuredPx(int tile) const;

    std::shared_ptr<Shared> m_shared;    ///< the worker's hand-back; outlives this object if need be
    ScanRunner* m_runner = nullptr;
    std::function<StitchRequest()> m_liveRequest;
    std::shared_ptr<Live> m_live;        ///< the live stitch under way
    int m_liveSession = 0;               ///< events of a dropped live stitch are let be
    bool m_lastWasLive = false;
    double m_livePlacedAfterS = 0;
    std::vector<QPointF> m_livePlannedPx;
    int m_liveTilesRead = 0;
    QString m_folder;
    bool m_running = false;
    int m_tileCount = 0;
    double m_pixelUm = 0;
    double m_seconds = 0;
    std::optional<imaging::StitchResult> m_result;
    QStringList m_written;
};

} // namespace dev::jobs
