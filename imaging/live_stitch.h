#pragma once
// Stitching while a scan runs (docs/stitching.md, "Live during a scan"): tiles come one
// at a time, each with the stage's measured position; a worker thread registers every
// new tile against its neighbours already taken as soon as both exist, with the same
// registration (registration.h) and the same rule for who is a neighbour as the batch
// stitch (stitch.h), so that finish() — the global placement over the pairs kept —
// gives what stitching the folder afterwards would give, within rounding.
//
// Threads: add() is called by the scan's side and never waits for registration (it
// queues); registration and the reading of tiles run on one worker thread of this
// object; the events are called on that worker. finish() and cancel() may be called
// from any one thread.
//
// Memory is bounded: a tile's image is held only while a neighbour of it (by the plan's
// positions) is still to come; past `memoryMegabytes` (queue and held tiles together)
// the oldest images are let go and read again from their files when a late neighbour
// needs them, so a tile handed in without a file is always held.
#include "imaging/stitch.h"

#include <Eigen/Core>

#include <condition_variable>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace imaging {

struct LiveStitchOptions {
    RegistrationOptions registration;  ///< as the batch stitch's: the pairs come out the same
    PlacementOptions placement;
    double memoryMegabytes = 512;      ///< tile images held (queued and awaiting a neighbour)
    int thumbnailPx = 96;              ///< the thumbnails' longer side; 0 = none
    /// Each tile divided by it before registration, as the batch stitch does (null: none).
    std::shared_ptr<const FlatField> flatField;
    /// The camera the stage pixels came from: finish() checks it against the registered
    /// shifts, as the batch stitch does (geometry_check.h). Unset: no check.
    std::optional<PlanCameraGeometry> planCamera;
};

/// What the live stitch says as it goes; each is called on the worker thread.
struct LiveStitchEvents {
    /// A tile read and registered against the neighbours present (its size in pixels), with
    /// a small copy (box-averaged) for drawing the growing mosaic.
    std::function<void(int tile, int width, int height, std::shared_ptr<const ImageU16> thumbnail)> tileRead;
    /// A pair registered (tile indices as given to the stitcher, a < b).
    std::function<void(const TilePair& pair)> pairRegistered;
};

/// `src` box-averaged down so that its longer side is at most `maxSidePx`.
ImageU16 thumbnail(const ImageU16& src, int maxSidePx);

class LiveStitcher {
public:
    /// Every tile the scan will take: its file (read when the image is not handed in, or
    /// was let go) and where the plan puts it (stagePx), which says who will be whose
    /// neighbour before the tiles exist.
    LiveStitcher(std::vector<StitchTile> planned, LiveStitchOptions options, LiveStitchEvents events = {});
    ~LiveStitcher();  ///< cancels and waits for the worker
    LiveStitcher(const LiveStitcher&) = delete;
    LiveStitcher& operator=(const LiveStitcher&) = delete;

    /// Tile `tile` taken at `stagePx` (its measured top-left in image pixels). `image` may
    /// be null: the worker reads the tile's file. False (and nothing queued) for an index
    /// out of range, a tile already given, or after finish() or cancel().
    bool add(int tile, const Eigen::Vector2d& stagePx, std::shared_ptr<const TileImage> image = nullptr);

    /// Waits for the queue, registers any pair the measured positions make neighbours that
    /// the plan's did not, checks the plan's camera when given, and places every tile. Refused when a tile could not be read or
    /// does not match the first, when tiles are missing (imaging.live.incomplete) or after
    /// cancel() (imaging.live.cancelled). Called once.
    motion::msg::Checked<StitchResult> finish();
    /// Drops the queue and stops the worker after the pair in hand; finish() is then refused.
    void cancel();

    int tileCount() const { return static_cast<int>(m_tiles.size()); }
    int tilesAdded() const;
    int tilesRegistered() const;          ///< read and registered against the neighbours present
    int pairsRegistered() const;
    double peakHeldMegabytes() const;     ///< the most image memory held at once
    int tilesReadAgain() const;           ///< images let go and read again from their files

private:
    struct Queued {
        int tile = 0;
        std::shared_ptr<const TileImage> image;
    };
    void work();
    /// The tile's image: held, or read from its file. Sets m_problems on failure.
    std::shared_ptr<const TileImage> imageOf(int tile, std::unique_lock<std::mutex>& lock);
    /// Checks a new tile's size and kind against the first; on the first, works out the neighbours.
    bool acceptImage(int tile, const TileImage& image);
    void hold(int tile, std::shared_ptr<const TileImage> image);
    void releaseFinished(int tile);
    void trimHeld();
    double heldMegabytes() const;
    TilePair registerNow(int a, int b, const TileImage& ia, const TileImage& ib);

    std::vector<StitchTile> m_tiles;   ///< stagePx: planned until the tile comes, then measured
    LiveStitchOptions m_options;
    LiveStitchEvents m_events;

    mutable std::mutex m_mutex;
    std::condition_variable m_wake;
    std::deque<Queued> m_queue;
    std::vector<char> m_added, m_done;          ///< per tile: given to add(); read and registered
    std::vector<std::vector<int>> m_candidates; ///< per tile: neighbours by the plan (once the size is known)
    std::map<int, std::shared_ptr<const TileImage>> m_held;
    std::deque<int> m_heldOrder;                ///< oldest first, for letting go
    std::map<std::pair<int, int>, PairRegistration> m_pairs;
    motion::msg::Problems m_problems;
    int m_tileW = 0, m_tileH = 0, m_firstTile = -1;
    SampleKind m_kind = SampleKind::Grey16;
    bool m_finishing = false, m_cancelled = false, m_finished = false;
    int m_addedCount = 0, m_doneCount = 0, m_readAgain = 0;
    double m_peakHeldMb = 0, m_registrationS = 0;
    std::thread m_worker;
};

} // namespace imaging
