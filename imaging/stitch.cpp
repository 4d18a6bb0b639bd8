#include "imaging/stitch.h"

#include "imaging/tiff_read.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

namespace imaging {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0)
{
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Tiles read on demand and kept while they are used: registration of a grid in
// file order touches a tile, its left and its upper neighbour, so a bounded cache
// holds what is needed without the whole set in memory. Any thread may ask.
class TileCache {
public:
    TileCache(const std::vector<StitchTile>& tiles, std::size_t capacity, const FlatField* flat)
        : m_tiles(tiles), m_capacity(std::max<std::size_t>(3, capacity)), m_flat(flat)
    {
    }

    motion::msg::Checked<std::shared_ptr<const TileImage>> get(int i)
    {
        using Result = motion::msg::Checked<std::shared_ptr<const TileImage>>;
        {
            std::lock_guard<std::mutex> lock(m_mutex);
            auto it = m_held.find(i);
            if (it != m_held.end()) {
                m_order.splice(m_order.begin(), m_order, it->second.second);
                return Result::ok(it->second.first);
            }
        }
        const StitchTile& t = m_tiles[static_cast<std::size_t>(i)];
        motion::msg::Checked<TileImage> read = readTile(t, m_flat);
        if (!read)
            return Result::refused(read.problems());
        auto shared = std::make_shared<const TileImage>(read.take());
        std::lock_guard<std::mutex> lock(m_mutex);
        if (m_held.count(i))
            return Result::ok(m_held[i].first);
        m_order.push_front(i);
        m_held[i] = {shared, m_order.begin()};
        while (m_held.size() > m_capacity) {
            m_held.erase(m_order.back());
            m_order.pop_back();
        }
        return Result::ok(shared);
    }

private:
    const std::vector<StitchTile>& m_tiles;
    std::size_t m_capacity;
    const FlatField* m_flat;
    std::mutex m_mutex;
    std::list<int> m_order;  ///< most recently used first
    std::map<int, std::pair<std::shared_ptr<const TileImage>, std::list<int>::iterator>> m_held;
};

motion::msg::Problem tileProblem(const StitchTile& t, const char* id, std::vector<motion::msg::Arg> args)
{
    return motion::msg::Problem(t.file, 0, 0, "", motion::msg::make(id, std::move(args)));
}

} // namespace

bool areNeighbours(const Eigen::Vector2d& d, int tileW, int tileH, int minOverlapPx)
{
    const double ox = tileW - std::abs(d.x()), oy = tileH - std::abs(d.y());
    if (ox < minOverlapPx || oy < minOverlapPx)
        return false;
    // Side by side, not corner to corner: one way the tiles nearly coincide.
    return !(std::abs(d.x()) > tileW / 2.0 && std::abs(d.y()) > tileH / 2.0);
}

motion::msg::Checked<TileImage> readTile(const StitchTile& t, const FlatField* flat)
{
    motion::msg::Checked<TileImage> read = readTiff(t.path, t.file);
    if (!read || !flat)
        return read;
    TileImage image = read.take();
    motion::msg::Problems problems = flat->apply(image, t.file);
    if (!problems.empty())
        return motion::msg::Checked<TileImage>::refused(std::move(problems));
    return motion::msg::Checked<TileImage>::ok(std::move(image));
}

std::vector<TilePair> neighbourPairs(const std::vector<Eigen::Vector2d>& stagePx, int tileW, int tileH, int minOverlapPx)
{
    std::vector<TilePair> pairs;
    // Sorted by x so the search for overlaps stays near-linear on a grid.
    std::vector<int> byX(stagePx.size());
    for (std::size_t i = 0; i < byX.size(); ++i)
        byX[i] = static_cast<int>(i);
    std::sort(byX.begin(), byX.end(), [&](int a, int b) { return stagePx[static_cast<std::size_t>(a)].x() < stagePx[static_cast<std::size_t>(b)].x(); });
    for (std::size_t i = 0; i < byX.size(); ++i)
        for (std::size_t j = i + 1; j < byX.size(); ++j) {
            const int a0 = byX[i], b0 = byX[j];
            const Eigen::Vector2d d = stagePx[static_cast<std::size_t>(b0)] - stagePx[static_cast<std::size_t>(a0)];
            if (d.x() > tileW - minOverlapPx)
                break;
            if (!areNeighbours(d, tileW, tileH, minOverlapPx))
                continue;
            const int a = std::min(a0, b0), b = std::max(a0, b0);
            TilePair p;
            p.a = a;
            p.b = b;
            pairs.push_back(p);
        }
    // In file order of the later tile: what a scan in that order would have when it came.
    std::sort(pairs.begin(), pairs.end(), [](const TilePair& p, const TilePair& q) { return std::tie(p.b, p.a) < std::tie(q.b, q.a); });
    return pairs;
}

motion::msg::Checked<StitchResult> checkTiles(const std::vector<StitchTile>& tiles)
{
    using Result = motion::msg::Checked<StitchResult>;
    if (tiles.empty())
        return Result::fail(motion::msg::make("imaging.tiles.none"));
    motion::msg::Problems problems;
    StitchResult r;
    r.tiles = tiles;
    const StitchTile* first = nullptr;
    TiffInfo firstInfo;
    for (const StitchTile& t : tiles) {
        motion::msg::Checked<TiffInfo> info = readTiffInfo(t.path, t.file);
        if (!info) {
            problems.insert(problems.end(), info.problems().begin(), info.problems().end());
            continue;
        }
        if (!first) {
            first = &t;
            firstInfo = *info;
            continue;
        }
        if (info->width != firstInfo.width || info->height != firstInfo.height)
            problems.push_back(tileProblem(t, "imaging.tiles.mixed_size",
                                           {motion::msg::verbatim("file", t.file), motion::msg::integer("width", info->width, motion::msg::Unit::None),
                                            motion::msg::integer("height", info->height, motion::msg::Unit::None), motion::msg::verbatim("first", first->file),
                                            motion::msg::integer("first_width", firstInfo.width, motion::msg::Unit::None),
                                            motion::msg::integer("first_height", firstInfo.height, motion::msg::Unit::None)}));
        else if (info->kind != firstInfo.kind)
            problems.push_back(tileProblem(t, "imaging.tiles.mixed_kind",
                                           {motion::msg::verbatim("file", t.file), motion::msg::verbatim("kind", sampleKindName(info->kind)),
                                            motion::msg::verbatim("first", first->file), motion::msg::verbatim("first_kind", sampleKindName(firstInfo.kind))}));
    }
    if (motion::msg::hasErrors(problems))
        return Result::refused(std::move(problems));
    r.tileWidth = firstInfo.width;
    r.tileHeight = firstInfo.height;
    r.kind = firstInfo.kind;
    return Result::ok(std::move(r));
}

motion::msg::Checked<StitchResult> stitch(const std::vector<StitchTile>& tiles, const StitchOptions& o)
{
    using Result = motion::msg::Checked<StitchResult>;
    motion::msg::Checked<StitchResult> checked = checkTiles(tiles);
    if (!checked)
        return checked;
    StitchResult r = checked.take();
    if (o.flatField) {
        motion::msg::Problems size = o.flatField->checkSize(r.tileWidth, r.tileHeight, r.tiles.front().file);
        if (!size.empty())
            return Result::refused(std::move(size));
    }
    std::vector<Eigen::Vector2d> stage;
    for (const StitchTile& t : tiles)
        stage.push_back(t.stagePx);

    // Registration, by a few workers pulling pairs in order.
    const Clock::time_point t0 = Clock::now();
    r.pairs = neighbourPairs(stage, r.tileWidth, r.tileHeight, o.registration.minOverlapPx);
    const double tileMb = static_cast<double>(r.tileWidth) * r.tileHeight * 2 / 1e6;
    TileCache cache(r.tiles, static_cast<std::size_t>(o.cacheMegabytes / std::max(0.001, tileMb)), o.flatField.get());
    std::atomic<std::size_t> next{0};
    std::mutex problemMutex;
    motion::msg::Problems problems;
    auto work = [&] {
        for (std::size_t k = next++; k < r.pairs.size(); k = next++) {
            TilePair& p = r.pairs[k];
            auto a = cache.get(p.a);
            auto b = a ? cache.get(p.b) : a;
            if (!a || !b) {
                std::lock_guard<std::mutex> lock(problemMutex);
                for (const motion::msg::Problem& pr : (!a ? a : b).problems())
                    problems.push_back(pr);
                next = r.pairs.size();
                return;
            }
            p.reg = registerPair((*a)->grey, (*b)->grey, stage[static_cast<std::size_t>(p.b)] - stage[static_cast<std::size_t>(p.a)], o.registration);
        }
    };
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    const unsigned n = o.threads > 0 ? static_cast<unsigned>(o.threads) : hw;
    std::vector<std::thread> workers;
    for (unsigned i = 1; i < n; ++i)
        workers.emplace_back(work);
    work();
    for (std::thread& w : workers)
        w.join();
    if (!problems.empty())
        return Result::refused(std::move(problems));
    if (o.planCamera) {
        r.planCamera = o.planCamera;
        const GeometryTileLoader load = [&cache](int i) -> std::shared_ptr<const ImageU16> {
            auto t = cache.get(i);
            return t ? std::shared_ptr<const ImageU16>(*t, &(*t)->grey) : nullptr;
        };
        r.cameraCheck = checkGeometry(stage, r.pairs, r.tileWidth, r.tileHeight, *o.planCamera, load, o.registration);
    }
    r.registrationS = since(t0);

    const Clock::time_point t1 = Clock::now();
    PlacementOptions po = o.placement;
    po.maxCorrectionPx = std::min(po.maxCorrectionPx, o.registration.maxShiftPx);
    r.placement = placeTiles(stage, r.pairs, po);
    r.frame = mosaicFrame(r.placement.positionsPx, r.tileWidth, r.tileHeight);
    r.placementS = since(t1);

    if (!o.mosaicPath.empty()) {
        motion::msg::Problems fused = writeMosaic(r, o);
        if (motion::msg::hasErrors(fused))
            return Result::refused(std::move(fused));
    }
    return Result::ok(std::move(r));
}

motion::msg::Problems writeMosaic(StitchResult& r, const StitchOptions& o)
{
    const Clock::time_point t2 = Clock::now();
    OmeTiffOptions mo = o.mosaic;
    mo.bitsPerSample = r.kind == SampleKind::Grey16 ? 16 : 8;
    if (o.stageMmAt) {
        if (const auto mm = o.stageMmAt(r.frame.originPx.cast<double>())) {
            mo.stageXMm = mm->x();
            mo.stageYMm = mm->y();
        }
    }
    auto writer = OmeTiffWriter::open(o.mosaicPath, r.frame.width, r.frame.height, mo);
    if (!writer)
        return writer.problems();
    motion::msg::Problems fused = fuseTiles(
        r.placement.positionsPx, r.tileWidth, r.tileHeight,
        [&](int i) { return readTile(r.tiles[static_cast<std::size_t>(i)], o.flatField.get()); }, **writer, o.fusion);
    r.fusionS = since(t2);
    return fused;
}

} // namespace imaging
