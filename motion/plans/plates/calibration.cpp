#include "motion/plans/plates/calibration.h"
#include "motion/numbers.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace motion::plates {
namespace {
using motion::kPi;
}

const char* fitModelName(FitModel m) { return m == FitModel::Similarity ? "similarity" : "scaled-axes"; }

std::vector<TeachPoint> teachWells(const Labware& lw)
{
    std::vector<TeachPoint> out;
    const WellId ids[3] = {{0, 0}, {0, lw.columns - 1}, {lw.rows - 1, 0}};
    for (const WellId& id : ids) {
        const Well* w = lw.well(id);
        if (!w)
            continue;
        const bool dup = std::any_of(out.begin(), out.end(), [&](const TeachPoint& t) { return t.well == wellName(id); });
        if (!dup)
            out.push_back({wellName(id), {w->xMm, w->yMm}, {}});
    }
    return out;
}

namespace {

/// Closed-form 2-D Procrustes without reflection (Umeyama 1991): the rotation
/// and scale that best map the centred plate points onto the machine points.
PlateTransform similarityFit(const std::vector<TeachPoint>& pts)
{
    const double n = static_cast<double>(pts.size());
    double px = 0, py = 0, qx = 0, qy = 0;
    for (const auto& t : pts) {
        px += t.plateMm.x / n;
        py += t.plateMm.y / n;
        qx += t.machineMm.x / n;
        qy += t.machineMm.y / n;
    }
    double sxx = 0, sxy = 0, norm = 0;
    for (const auto& t : pts) {
        const double ax = t.plateMm.x - px, ay = t.plateMm.y - py;
        const double bx = t.machineMm.x - qx, by = t.machineMm.y - qy;
        sxx += ax * bx + ay * by;
        sxy += ax * by - ay * bx;
        norm += ax * ax + ay * ay;
    }
    const double a = sxx / norm, b = sxy / norm;  // [a −b; b a] = scale · rotation
    PlateTransform t;
    t.m11 = a;
    t.m12 = -b;
    t.m21 = b;
    t.m22 = a;
    t.txMm = qx - (a * px - b * py);
    t.tyMm = qy - (b * px + a * py);
    return t;
}

/// Rotation θ, scales sx, sy and offset by Gauss–Newton from the similarity fit:
/// machine = R(θ)·diag(sx, sy)·plate + t.
PlateTransform scaledAxesFit(const std::vector<TeachPoint>& pts, const PlateTransform& start)
{
    Eigen::Matrix<double, 5, 1> x;
    x << std::atan2(start.m21, start.m11), std::hypot(start.m11, start.m21), std::hypot(start.m11, start.m21), start.txMm, start.tyMm;
    const int n = static_cast<int>(pts.size());
    for (int iter = 0; iter < 20; ++iter) {
        Eigen::MatrixXd J(2 * n, 5);
        Eigen::VectorXd r(2 * n);
        const double c = std::cos(x[0]), s = std::sin(x[0]);
        for (int i = 0; i < n; ++i) {
            const double u = x[1] * pts[static_cast<std::size_t>(i)].plateMm.x;
            const double v = x[2] * pts[static_cast<std::size_t>(i)].plateMm.y;
            r[2 * i] = c * u - s * v + x[3] - pts[static_cast<std::size_t>(i)].machineMm.x;
            r[2 * i + 1] = s * u + c * v + x[4] - pts[static_cast<std::size_t>(i)].machineMm.y;
            const double px = pts[static_cast<std::size_t>(i)].plateMm.x, py = pts[static_cast<std::size_t>(i)].plateMm.y;
            J.row(2 * i) << -s * u - c * v, c * px, -s * py, 1, 0;
            J.row(2 * i + 1) << c * u - s * v, s * px, c * py, 0, 1;
        }
        const Eigen::Matrix<double, 5, 1> step = (J.transpose() * J).ldlt().solve(-J.transpose() * r);
        if (!step.allFinite())
            break;
        x += step;
        if (step.norm() < 1e-12)
            break;
    }
    return PlateTransform::make(x[3], x[4], x[0] * 180 / kPi, x[1], x[2]);
}

} // namespace

std::optional<CalibrationFit> fitCalibration(const std::vector<TeachPoint>& pts, FitModel model, motion::msg::Message* error,
                                             double slotRotationDeg)
{
    auto fail = [&](const motion::msg::Message& m) {
        if (error)
            *error = m;
        return std::nullopt;
    };
    if (pts.size() < 2)
        return fail(motion::msg::make("plate.calibration.too_few_wells"));
    for (const auto& t : pts)
        if (!std::isfinite(t.plateMm.x + t.plateMm.y + t.machineMm.x + t.machineMm.y))
            return fail(motion::msg::make("plate.calibration.no_position", {textArg("well", t.well)}));
    double spreadPlate = 0, spreadMachine = 0;
    for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
            spreadPlate = std::max(spreadPlate, std::hypot(pts[i].plateMm.x - pts[j].plateMm.x, pts[i].plateMm.y - pts[j].plateMm.y));
            spreadMachine = std::max(spreadMachine,
                                     std::hypot(pts[i].machineMm.x - pts[j].machineMm.x, pts[i].machineMm.y - pts[j].machineMm.y));
        }
    if (spreadPlate < 1 || spreadMachine < 1)
        return fail(motion::msg::make("plate.calibration.too_close"));
    if (model == FitModel::ScaledAxes && pts.size() < 3)
        return fail(motion::msg::make("plate.calibration.scaled_needs_three"));

    CalibrationFit fit;
    fit.model = model;
    fit.transform = similarityFit(pts);
    if (model == FitModel::ScaledAxes) {
        // Three points on one line cannot fix a second scale.
        const auto& a = pts[0].plateMm;
        double area = 0;
        for (std::size_t i = 1; i + 1 < pts.size(); ++i)
            area = std::max(area, std::abs((pts[i].plateMm.x - a.x) * (pts[i + 1].plateMm.y - a.y)
                                           - (pts[i].plateMm.y - a.y) * (pts[i + 1].plateMm.x - a.x)));
        if (area < 1)
            return fail(motion::msg::make("plate.calibration.on_one_line"));
        fit.transform = scaledAxesFit(pts, fit.transform);
    }
    const PlateTransform& t = fit.transform;
    fit.rotationDeg = std::atan2(t.m21, t.m11) * 180 / kPi;
    fit.scaleX = std::hypot(t.m11, t.m21);
    fit.scaleY = std::hypot(t.m12, t.m22);
    double sum2 = 0;
    for (const auto& p : pts) {
        const PointMm m = t.apply(p.plateMm);
        const double r = std::hypot(m.x - p.machineMm.x, m.y - p.machineMm.y);
        fit.residualMm.push_back(r);
        fit.maxResidualMm = std::max(fit.maxResidualMm, r);
        sum2 += r * r;
    }
    fit.rmsResidualMm = std::sqrt(sum2 / static_cast<double>(pts.size()));
    // Least squares spreads one bad point over all of them, so the warning names
    // every residual rather than blaming the largest.
    if (fit.maxResidualMm > kResidualWarnMm) {
        // The list is "A1 0.12, H12 0.3" in mm: well names and numbers a person
        // compares with the table beside the message, the same in every language.
        std::string list;
        for (std::size_t i = 0; i < pts.size(); ++i)
            list += (i ? ", " : "") + pts[i].well + " " + formatMm(std::round(fit.residualMm[i] * 100) / 100);
        fit.warnings.push_back(motion::msg::make("plate.calibration.large_residual",
                                         {mmArg("max", std::round(fit.maxResidualMm * 100) / 100), textArg("list", list),
                                          mmArg("limit", kResidualWarnMm)}));
    }
    for (double s : {fit.scaleX, fit.scaleY})
        if (std::abs(s - 1) > kScaleWarn) {
            fit.warnings.push_back(motion::msg::make("plate.calibration.scale_off", {motion::msg::real("scale", s)}));
            break;
        }
    const double turn = std::remainder(fit.rotationDeg - slotRotationDeg, 360.0);
    if (std::abs(turn) > kRotationWarnDeg)
        fit.warnings.push_back(motion::msg::make("plate.calibration.turned", {motion::msg::real("angle", std::round(turn * 100) / 100, motion::msg::Unit::Deg)}));
    return fit;
}

} // namespace motion::plates
