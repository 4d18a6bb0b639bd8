#include "motion/plans/recipes/well_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace motion::plates {

namespace {

/// Wells' pairwise moves repeat on a grid (a 384-well plate has 384 distinct
/// offsets among its 73 536 pairs): each offset's time is computed once.
class CostMemo {
public:
    explicit CostMemo(const MoveCost& cost) : m_cost(cost) {}
    double operator()(const PointMm& a, const PointMm& b)
    {
        const double dx = std::abs(a.x - b.x), dy = std::abs(a.y - b.y);
        const unsigned long long key = (static_cast<unsigned long long>(std::llround(dx * 1e4)) << 32)
            ^ static_cast<unsigned long long>(std::llround(dy * 1e4));
        const auto it = m_seen.find(key);
        if (it != m_seen.end())
            return it->second;
        const double t = m_cost(a, b);
        m_seen.emplace(key, t);
        return t;
    }

private:
    const MoveCost& m_cost;
    std::unordered_map<unsigned long long, double> m_seen;
};

std::vector<std::size_t> byGrid(const std::vector<WellId>& ids, bool columnsFirst, bool snake)
{
    std::vector<std::size_t> idx(ids.size());
    std::iota(idx.begin(), idx.end(), 0);
    auto major = [&](std::size_t i) { return columnsFirst ? ids[i].column : ids[i].row; };
    auto minor = [&](std::size_t i) { return columnsFirst ? ids[i].row : ids[i].column; };
    // Snake: the minor index runs backwards on every other line that has wells
    // (counted among the lines the step uses, so a step on rows B and D turns at B's end).
    std::vector<int> lines;
    for (const WellId& w : ids)
        lines.push_back(columnsFirst ? w.column : w.row);
    std::sort(lines.begin(), lines.end());
    lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    auto backwards = [&](int line) {
        return snake && (std::lower_bound(lines.begin(), lines.end(), line) - lines.begin()) % 2 == 1;
    };
    std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) {
        if (major(a) != major(b))
            return major(a) < major(b);
        return backwards(major(a)) ? minor(a) > minor(b) : minor(a) < minor(b);
    });
    return idx;
}

/// Largest step the 2-opt pass keeps a full table of move times for (8 MB); a
/// larger step keeps the nearest-neighbour walk.
constexpr std::size_t kMaxTwoOpt = 1024;

std::vector<std::size_t> shortest(const std::vector<PointMm>& at, const MoveCost& cost)
{
    // The walk starts at the well written first, not where the tip happens to be:
    // a resumed run (the tip elsewhere) must plan the same sequence as its log.
    const std::size_t n = at.size();
    CostMemo c(cost);
    std::vector<std::size_t> path;
    path.reserve(n);
    std::vector<char> used(n, 0);
    path.push_back(0);
    used[0] = 1;
    for (std::size_t k = 1; k < n; ++k) {
        const PointMm here = at[path.back()];
        std::size_t best = n;
        double bestT = 0;
        for (std::size_t i = 0; i < n; ++i) {
            if (used[i])
                continue;
            const double t = c(here, at[i]);
            if (best == n || t < bestT - 1e-12) {
                best = i;
                bestT = t;
            }
        }
        used[best] = 1;
        path.push_back(best);
    }
    if (n < 4 || n > kMaxTwoOpt)
        return path;
    std::vector<double> table(n * n);
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t b = a; b < n; ++b)
            table[a * n + b] = table[b * n + a] = c(at[a], at[b]);
    auto d = [&](std::size_t a, std::size_t b) { return table[path[a] * n + path[b]]; };
    // An open path with a fixed start: reversing path[i+1 … j] replaces the
    // edges (i, i+1) and (j, j+1) by (i, j) and (i+1, j+1); the last well has no
    // edge after it. First improvement, in index order: deterministic.
    for (int pass = 0; pass < 100; ++pass) {
        bool improved = false;
        for (std::size_t i = 0; i + 2 < n; ++i)
            for (std::size_t j = i + 2; j < n; ++j) {
                const double before = d(i, i + 1) + (j + 1 < n ? d(j, j + 1) : 0.0);
                const double after = d(i, j) + (j + 1 < n ? d(i + 1, j + 1) : 0.0);
                if (after < before - 1e-9) {
                    std::reverse(path.begin() + static_cast<std::ptrdiff_t>(i + 1), path.begin() + static_cast<std::ptrdiff_t>(j + 1));
                    improved = true;
                }
            }
        if (!improved)
            break;
    }
    return path;
}

} // namespace

std::vector<std::size_t> wellOrderIndices(WellOrder order, const std::vector<WellId>& ids, const std::vector<PointMm>& at, const MoveCost& cost)
{
    switch (order) {
    case WellOrder::AsWritten: break;
    case WellOrder::ColumnMajor: return byGrid(ids, true, false);
    case WellOrder::SnakeRows: return byGrid(ids, false, true);
    case WellOrder::SnakeColumns: return byGrid(ids, true, true);
    case WellOrder::Shortest: return shortest(at, cost);
    }
    std::vector<std::size_t> idx(ids.size());
    std::iota(idx.begin(), idx.end(), 0);
    return idx;
}

double pathCost(const std::vector<std::size_t>& sequence, const std::vector<PointMm>& at, const PointMm& from, const MoveCost& cost)
{
    double t = 0;
    PointMm here = from;
    for (std::size_t i : sequence) {
        t += cost(here, at[i]);
        here = at[i];
    }
    return t;
}

} // namespace motion::plates
