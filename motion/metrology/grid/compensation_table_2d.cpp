#include "motion/metrology/grid/compensation_table_2d.h"

#include <algorithm>
#include <cmath>

namespace motion::metrology {
namespace {

struct Cell {
    int i0 = 0, j0 = 0, i1 = 0, j1 = 0;
    double u = 0, v = 0;  ///< 0…1 across the cell
};

Cell cellAt(double x, double y, double ox, double oy, double px, double py, int nx, int ny)
{
    Cell c;
    const double fx = std::clamp((x - ox) / px, 0.0, static_cast<double>(nx - 1));
    const double fy = std::clamp((y - oy) / py, 0.0, static_cast<double>(ny - 1));
    c.i0 = std::min(static_cast<int>(std::floor(fx)), nx - 2);
    c.j0 = std::min(static_cast<int>(std::floor(fy)), ny - 2);
    c.i1 = c.i0 + 1;
    c.j1 = c.j0 + 1;
    c.u = fx - c.i0;
    c.v = fy - c.j0;
    return c;
}

double bilinear(const std::vector<double>& f, const Cell& c, int nx)
{
    auto at = [&](int i, int j) { return f[static_cast<std::size_t>(j * nx + i)]; };
    return (1 - c.u) * (1 - c.v) * at(c.i0, c.j0) + c.u * (1 - c.v) * at(c.i1, c.j0) + (1 - c.u) * c.v * at(c.i0, c.j1)
           + c.u * c.v * at(c.i1, c.j1);
}

} // namespace

CompensationTable2D::Correction CompensationTable2D::correctionAt(double xMm, double yMm) const
{
    if (columns < 2 || rows < 2 || correctionXUm.size() != static_cast<std::size_t>(columns * rows)
        || correctionYUm.size() != correctionXUm.size())
        return {};
    const Cell c = cellAt(xMm, yMm, originXMm, originYMm, pitchXMm, pitchYMm, columns, rows);
    return {bilinear(correctionXUm, c, columns), bilinear(correctionYUm, c, columns)};
}

motion::msg::Problems validate(const CompensationTable2D& t)
{
    motion::msg::Problems out;
    auto nodes = [&](int n, const char* path) {
        if (n < kMinTable2DNodes || n > kMaxTable2DNodes)
            out.push_back(motion::msg::error(path, motion::msg::make("compensation2d.nodes_out_of_range",
                                                     {motion::msg::integer("count", n), motion::msg::integer("min", kMinTable2DNodes),
                                                      motion::msg::integer("max", kMaxTable2DNodes)})));
    };
    nodes(t.columns, "grid.columns");
    nodes(t.rows, "grid.rows");
    checkRange(out, "grid.origin_x_mm", t.originXMm, -10000, 10000, motion::msg::Unit::Mm);
    checkRange(out, "grid.origin_y_mm", t.originYMm, -10000, 10000, motion::msg::Unit::Mm);
    checkRange(out, "grid.pitch_x_mm", t.pitchXMm, kMinTable2DPitchMm, 10000, motion::msg::Unit::Mm);
    checkRange(out, "grid.pitch_y_mm", t.pitchYMm, kMinTable2DPitchMm, 10000, motion::msg::Unit::Mm);
    const long long expected = static_cast<long long>(std::max(0, t.columns)) * std::max(0, t.rows);
    if (static_cast<long long>(t.correctionXUm.size()) != expected || t.correctionYUm.size() != t.correctionXUm.size()) {
        out.push_back(motion::msg::error("nodes", motion::msg::make("compensation2d.node_count_wrong",
                                                    {motion::msg::integer("count", static_cast<long long>(t.correctionXUm.size())),
                                                     motion::msg::integer("expected", expected)})));
        return out;
    }
    for (std::size_t k = 0; k < t.correctionXUm.size(); ++k) {
        const std::string node = indexPath("nodes", k);
        checkRange(out, fieldPath(node, "correction_x_um"), t.correctionXUm[k], -kMaxTable2DCorrectionUm,
                   kMaxTable2DCorrectionUm, motion::msg::Unit::Um);
        checkRange(out, fieldPath(node, "correction_y_um"), t.correctionYUm[k], -kMaxTable2DCorrectionUm,
                   kMaxTable2DCorrectionUm, motion::msg::Unit::Um);
    }
    return out;
}

std::optional<CompensationTable2D> compensationFromMap(const GridMapResult& map)
{
    if (map.nodes.size() < 4)
        return std::nullopt;
    // The grid: distinct x of the first row, distinct y of the first column.
    std::vector<double> xs, ys;
    for (const auto& n : map.nodes) {
        if (n.yMm != map.nodes.front().yMm)
            break;
        xs.push_back(n.xMm);
    }
    const std::size_t nx = xs.size();
    if (nx < 2 || map.nodes.size() % nx != 0)
        return std::nullopt;
    const std::size_t ny = map.nodes.size() / nx;
    for (std::size_t j = 0; j < ny; ++j)
        ys.push_back(map.nodes[j * nx].yMm);
    if (ny < 2)
        return std::nullopt;
    CompensationTable2D t;
    t.columns = static_cast<int>(nx);
    t.rows = static_cast<int>(ny);
    t.originXMm = xs.front();
    t.originYMm = ys.front();
    t.pitchXMm = (xs.back() - xs.front()) / static_cast<double>(nx - 1);
    t.pitchYMm = (ys.back() - ys.front()) / static_cast<double>(ny - 1);
    // A map whose nodes are not on one regular grid (to 1 µm) cannot become a table.
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const auto& n = map.nodes[j * nx + i];
            if (std::abs(n.xMm - (t.originXMm + t.pitchXMm * static_cast<double>(i))) > 1e-3
                || std::abs(n.yMm - (t.originYMm + t.pitchYMm * static_cast<double>(j))) > 1e-3)
                return std::nullopt;
        }
    std::vector<double> ex(nx * ny), ey(nx * ny);
    for (std::size_t k = 0; k < ex.size(); ++k) {
        ex[k] = map.nodes[k].exUm;
        ey[k] = map.nodes[k].eyUm;
    }
    t.correctionXUm.assign(nx * ny, 0);
    t.correctionYUm.assign(nx * ny, 0);
    // k = −e(n + k): a fixed point, converging by the error's slope (µm per µm, far
    // below 1) each step.
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const std::size_t k = j * nx + i;
            double kx = -ex[k], ky = -ey[k];
            for (int it = 0; it < 20; ++it) {
                const Cell c = cellAt(xs[i] + kx * 1e-3, ys[j] + ky * 1e-3, t.originXMm, t.originYMm, t.pitchXMm,
                                      t.pitchYMm, t.columns, t.rows);
                kx = -bilinear(ex, c, t.columns);
                ky = -bilinear(ey, c, t.columns);
            }
            t.correctionXUm[k] = kx;
            t.correctionYUm[k] = ky;
        }
    return t;
}

} // namespace motion::metrology
