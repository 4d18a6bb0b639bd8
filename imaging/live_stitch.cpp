#include "imaging/live_stitch.h"

#include "imaging/tiff_read.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace imaging {
namespace {

using LiveClock = std::chrono::steady_clock;

double liveSince(LiveClock::time_point t0)
{
    return std::chrono::duration<double>(LiveClock::now() - t0).count();
}

double imageMegabytes(const TileImage& image)
{
    return static_cast<double>(image.grey.px.size()) * sizeof(std::uint16_t) / 1e6;
}

} // namespace

ImageU16 thumbnail(const ImageU16& src, int maxSidePx)
{
    if (src.empty() || maxSidePx <= 0)
        return {};
    const int f = std::max(1, (std::max(src.width, src.height) + maxSidePx - 1) / maxSidePx);
    ImageU16 out(std::max(1, src.width / f), std::max(1, src.height / f));
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            std::uint64_t sum = 0;
            for (int v = 0; v < f; ++v) {
                const std::uint16_t* r = src.row(y * f + v) + x * f;
                for (int u = 0; u < f; ++u)
                    sum += r[u];
            }
            out.at(x, y) = static_cast<std::uint16_t>(sum / (static_cast<std::uint64_t>(f) * static_cast<std::uint64_t>(f)));
        }
    return out;
}

LiveStitcher::LiveStitcher(std::vector<StitchTile> planned, LiveStitchOptions options, LiveStitchEvents events)
    : m_tiles(std::move(planned)), m_options(std::move(options)), m_events(std::move(events))
{
    m_added.assign(m_tiles.size(), 0);
    m_done.assign(m_tiles.size(), 0);
    m_candidates.resize(m_tiles.size());
    m_worker = std::thread([this] { work(); });
}

LiveStitcher::~LiveStitcher()
{
    cancel();
    if (m_worker.joinable())
        m_worker.join();
}

bool LiveStitcher::add(int tile, const Eigen::Vector2d& stagePx, std::shared_ptr<const TileImage> image)
{
    std::lock_guard<std::mutex> lock(m_mutex);
    if (tile < 0 || tile >= tileCount() || m_added[static_cast<std::size_t>(tile)] || m_finishing || m_cancelled)
        return false;
    StitchTile& t = m_tiles[static_cast<std::size_t>(tile)];
    t.stagePx = stagePx;
    m_added[static_cast<std::size_t>(tile)] = 1;
    ++m_addedCount;
    // Over the bound a tile that has a file waits without its pixels: the worker reads it.
    if (image && !t.path.empty() && heldMegabytes() + imageMegabytes(*image) > m_options.memoryMegabytes)
        image.reset();
    m_queue.push_back({tile, std::move(image)});
    m_peakHeldMb = std::max(m_peakHeldMb, heldMegabytes());
    m_wake.notify_one();
    return true;
}

double LiveStitcher::heldMegabytes() const
{
    double mb = 0;
    for (const auto& h : m_held)
        mb += imageMegabytes(*h.second);
    for (const Queued& q : m_queue)
        if (q.image)
            mb += imageMegabytes(*q.image);
    return mb;
}

bool LiveStitcher::acceptImage(int tile, const TileImage& image)
{
    const StitchTile& t = m_tiles[static_cast<std::size_t>(tile)];
    if (m_firstTile < 0) {
        m_firstTile = tile;
        m_tileW = image.grey.width;
        m_tileH = image.grey.height;
        m_kind = image.kind;
        if (m_options.flatField) {
            motion::msg::Problems size = m_options.flatField->checkSize(m_tileW, m_tileH, t.file);
            if (!size.empty()) {
                m_problems.insert(m_problems.end(), size.begin(), size.end());
                return false;
            }
        }
        // Neighbours by the plan, loosely: a tile may come up to the search bound away
        // from where the plan put it, and the measured positions decide in the end.
        const double slack = m_options.registration.maxShiftPx;
        for (std::size_t i = 0; i < m_tiles.size(); ++i)
            for (std::size_t j = i + 1; j < m_tiles.size(); ++j) {
                const Eigen::Vector2d d = (m_tiles[j].stagePx - m_tiles[i].stagePx).cwiseAbs();
                if (d.x() > m_tileW + slack || d.y() > m_tileH + slack)
                    continue;
                if (d.x() > m_tileW / 2.0 + slack && d.y() > m_tileH / 2.0 + slack)
                    continue;
                m_candidates[i].push_back(static_cast<int>(j));
                m_candidates[j].push_back(static_cast<int>(i));
            }
        return true;
    }
    const StitchTile& first = m_tiles[static_cast<std::size_t>(m_firstTile)];
    using namespace motion::msg;
    if (image.grey.width != m_tileW || image.grey.height != m_tileH) {
        m_problems.push_back(Problem(t.file, 0, 0, "",
                                     make("imaging.tiles.mixed_size",
                                          {verbatim("file", t.file), integer("width", image.grey.width, Unit::None), integer("height", image.grey.height, Unit::None),
                                           verbatim("first", first.file), integer("first_width", m_tileW, Unit::None), integer("first_height", m_tileH, Unit::None)})));
        return false;
    }
    if (image.kind != m_kind) {
        m_problems.push_back(Problem(t.file, 0, 0, "",
                                     make("imaging.tiles.mixed_kind", {verbatim("file", t.file), verbatim("kind", sampleKindName(image.kind)),
                                                                       verbatim("first", first.file), verbatim("first_kind", sampleKindName(m_kind))})));
        return false;
    }
    return true;
}

void LiveStitcher::hold(int tile, std::shared_ptr<const TileImage> image)
{
    if (m_held.count(tile))
        return;
    m_held[tile] = std::move(image);
    m_heldOrder.push_back(tile);
    m_peakHeldMb = std::max(m_peakHeldMb, heldMegabytes());
}

void LiveStitcher::releaseFinished(int tile)
{
    auto settled = [&](int t) {
        if (!m_done[static_cast<std::size_t>(t)])
            return false;
        for (int n : m_candidates[static_cast<std::size_t>(t)])
            if (!m_done[static_cast<std::size_t>(n)])
                return false;
        return true;
    };
    std::vector<int> look = m_candidates[static_cast<std::size_t>(tile)];
    look.push_back(tile);
    for (int t : look)
        if (settled(t))
            m_held.erase(t);
}

void LiveStitcher::trimHeld()
{
    while (heldMegabytes() > m_options.memoryMegabytes && !m_heldOrder.empty()) {
        bool dropped = false;
        for (auto it = m_heldOrder.begin(); it != m_heldOrder.end(); ++it) {
            const auto h = m_held.find(*it);
            if (h == m_held.end()) {
                m_heldOrder.erase(it);  // released already
                dropped = true;
                break;
            }
            if (m_tiles[static_cast<std::size_t>(*it)].path.empty())
                continue;  // no file to read it again from: it stays
            m_held.erase(h);
            m_heldOrder.erase(it);
            dropped = true;
            break;
        }
        if (!dropped)
            return;
    }
}

std::shared_ptr<const TileImage> LiveStitcher::imageOf(int tile, std::unique_lock<std::mutex>& lock)
{
    const auto h = m_held.find(tile);
    if (h != m_held.end())
        return h->second;
    const StitchTile t = m_tiles[static_cast<std::size_t>(tile)];
    lock.unlock();
    motion::msg::Checked<TileImage> read = readTile(t, m_options.flatField.get());
    lock.lock();
    if (!read) {
        m_problems.insert(m_problems.end(), read.problems().begin(), read.problems().end());
        return nullptr;
    }
    ++m_readAgain;
    auto shared = std::make_shared<const TileImage>(read.take());
    hold(tile, shared);
    return shared;
}

TilePair LiveStitcher::registerNow(int a, int b, const TileImage& ia, const TileImage& ib)
{
    TilePair p;
    p.a = a;
    p.b = b;
    const Eigen::Vector2d expected = m_tiles[static_cast<std::size_t>(b)].stagePx - m_tiles[static_cast<std::size_t>(a)].stagePx;
    p.reg = registerPair(ia.grey, ib.grey, expected, m_options.registration);
    return p;
}

void LiveStitcher::work()
{
    std::unique_lock<std::mutex> lock(m_mutex);
    for (;;) {
        m_wake.wait(lock, [this] { return m_cancelled || m_finishing || !m_queue.empty(); });
        if (m_cancelled)
            return;
        if (m_queue.empty()) {
            if (m_finishing)
                return;
            continue;
        }
        Queued q = std::move(m_queue.front());
        m_queue.pop_front();
        const int tile = q.tile;
        std::shared_ptr<const TileImage> image = q.image;
        if (!image) {
            const StitchTile t = m_tiles[static_cast<std::size_t>(tile)];
            lock.unlock();
            motion::msg::Checked<TileImage> read = readTile(t, m_options.flatField.get());
            lock.lock();
            if (!read) {
                m_problems.insert(m_problems.end(), read.problems().begin(), read.problems().end());
                continue;
            }
            image = std::make_shared<const TileImage>(read.take());
        }
        if (q.image && m_options.flatField) {  // handed in as taken: flattened here, off the scan's thread
            TileImage flat = *q.image;
            const StitchTile t = m_tiles[static_cast<std::size_t>(tile)];
            lock.unlock();
            motion::msg::Problems problems = m_options.flatField->apply(flat, t.file);
            lock.lock();
            if (!problems.empty()) {
                m_problems.insert(m_problems.end(), problems.begin(), problems.end());
                continue;
            }
            image = std::make_shared<const TileImage>(std::move(flat));
        }
        if (!acceptImage(tile, *image))
            continue;
        hold(tile, image);
        // Against every neighbour registered before it, in index order as the batch does.
        std::vector<int> ready;
        for (int n : m_candidates[static_cast<std::size_t>(tile)])
            if (m_done[static_cast<std::size_t>(n)])
                ready.push_back(n);
        std::sort(ready.begin(), ready.end());
        for (int n : ready) {
            if (m_cancelled)
                return;
            const int a = std::min(n, tile), b = std::max(n, tile);
            const Eigen::Vector2d d = m_tiles[static_cast<std::size_t>(b)].stagePx - m_tiles[static_cast<std::size_t>(a)].stagePx;
            if (!areNeighbours(d, m_tileW, m_tileH, m_options.registration.minOverlapPx))
                continue;
            const std::shared_ptr<const TileImage> other = imageOf(n, lock);
            if (!other)
                continue;
            lock.unlock();
            const LiveClock::time_point t0 = LiveClock::now();
            const TilePair p = a == tile ? registerNow(a, b, *image, *other) : registerNow(a, b, *other, *image);
            const double took = liveSince(t0);
            lock.lock();
            m_registrationS += took;
            m_pairs[{a, b}] = p.reg;
            if (m_events.pairRegistered) {  // kept first, so what the event says can be asked back
                lock.unlock();
                m_events.pairRegistered(p);
                lock.lock();
            }
        }
        m_done[static_cast<std::size_t>(tile)] = 1;
        ++m_doneCount;
        releaseFinished(tile);
        trimHeld();
        if (m_events.tileRead && m_options.thumbnailPx > 0) {  // after its pairs: "read" means registered too
            lock.unlock();
            m_events.tileRead(tile, image->grey.width, image->grey.height, std::make_shared<const ImageU16>(thumbnail(image->grey, m_options.thumbnailPx)));
            lock.lock();
        }
    }
}

void LiveStitcher::cancel()
{
    std::lock_guard<std::mutex> lock(m_mutex);
    m_cancelled = true;
    m_queue.clear();
    m_wake.notify_all();
}

motion::msg::Checked<StitchResult> LiveStitcher::finish()
{
    using Result = motion::msg::Checked<StitchResult>;
    {
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_finished)
            return Result::fail(motion::msg::make("imaging.live.cancelled"));
        m_finished = true;
        m_finishing = true;
        m_wake.notify_all();
    }
    if (m_worker.joinable())
        m_worker.join();
    // The worker is gone: what follows runs on the caller's thread alone.
    std::unique_lock<std::mutex> lock(m_mutex);
    if (m_cancelled)
        return Result::fail(motion::msg::make("imaging.live.cancelled"));
    if (motion::msg::hasErrors(m_problems))
        return Result::refused(m_problems);
    if (m_addedCount < tileCount() || m_doneCount < tileCount())
        return Result::fail(motion::msg::make("imaging.live.incomplete", {motion::msg::integer("taken", m_addedCount, motion::msg::Unit::None),
                                                                          motion::msg::integer("total", tileCount(), motion::msg::Unit::None)}));
    StitchResult r;
    r.tiles = m_tiles;
    r.tileWidth = m_tileW;
    r.tileHeight = m_tileH;
    r.kind = m_kind;
    std::vector<Eigen::Vector2d> stage;
    for (const StitchTile& t : m_tiles)
        stage.push_back(t.stagePx);
    // The batch's pairs, from the measured positions; any the plan did not foresee is
    // registered now from the files.
    const LiveClock::time_point t0 = LiveClock::now();
    r.pairs = neighbourPairs(stage, m_tileW, m_tileH, m_options.registration.minOverlapPx);
    for (TilePair& p : r.pairs) {
        const auto found = m_pairs.find({p.a, p.b});
        if (found != m_pairs.end()) {
            p.reg = found->second;
            continue;
        }
        const auto ia = imageOf(p.a, lock);
        const auto ib = ia ? imageOf(p.b, lock) : nullptr;
        if (!ia || !ib)
            return Result::refused(m_problems);
        p = registerNow(p.a, p.b, *ia, *ib);
    }
    if (m_options.planCamera) {
        // As the batch stitch: the few pairs tried again are read back from their files.
        r.planCamera = m_options.planCamera;
        const GeometryTileLoader load = [this, &lock](int i) -> std::shared_ptr<const ImageU16> {
            const auto t = imageOf(i, lock);
            return t ? std::shared_ptr<const ImageU16>(t, &t->grey) : nullptr;
        };
        r.cameraCheck = checkGeometry(stage, r.pairs, m_tileW, m_tileH, *m_options.planCamera, load, m_options.registration);
    }
    m_held.clear();
    r.registrationS = m_registrationS + liveSince(t0);
    const LiveClock::time_point t1 = LiveClock::now();
    PlacementOptions po = m_options.placement;
    po.maxCorrectionPx = std::min(po.maxCorrectionPx, m_options.registration.maxShiftPx);  // as the batch stitch
    r.placement = placeTiles(stage, r.pairs, po);
    r.frame = mosaicFrame(r.placement.positionsPx, m_tileW, m_tileH);
    r.placementS = liveSince(t1);
    return Result::ok(std::move(r));
}

int LiveStitcher::tilesAdded() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_addedCount;
}

int LiveStitcher::tilesRegistered() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_doneCount;
}

int LiveStitcher::pairsRegistered() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return static_cast<int>(m_pairs.size());
}

double LiveStitcher::peakHeldMegabytes() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_peakHeldMb;
}

int LiveStitcher::tilesReadAgain() const
{
    std::lock_guard<std::mutex> lock(m_mutex);
    return m_readAgain;
}

} // namespace imaging
