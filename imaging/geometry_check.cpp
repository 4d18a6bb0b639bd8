#include "imaging/geometry_check.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace imaging {

GeometryCheck checkGeometry(const std::vector<Eigen::Vector2d>& stagePx, const std::vector<TilePair>& pairs, int tileW, int tileH,
                            const PlanCameraGeometry& plan, const GeometryTileLoader& load, const RegistrationOptions& registration,
                            const GeometryCheckOptions& options)
{
    GeometryCheck out;
    const Eigen::Matrix2d planM = cameraStageMatrix(plan.pixelUm, plan.pixelUm, plan.rotationDeg, plan.imageYAlongPlusY);
    // The readings of a step a wrong plan may have hidden: mirrored along either image axis,
    // turned half round, or as planned but beyond the stitch's bound.
    const Eigen::Matrix2d readings[] = {Eigen::Vector2d(1, -1).asDiagonal(), Eigen::Vector2d(-1, 1).asDiagonal(), -Eigen::Matrix2d::Identity(),
                                        Eigen::Matrix2d::Identity()};
    RegistrationOptions wide = registration;
    wide.maxShiftPx = std::max(registration.maxShiftPx, options.searchShareOfTile * std::min(tileW, tileH));
    // The best shift under any reading, other than `besides` (a reading already found wrong).
    auto registerAnyWay = [&](const TilePair& p, const Eigen::Vector2d& e, const std::optional<Eigen::Vector2d>& besides) {
        std::optional<Eigen::Vector2d> shift;
        if (!load)
            return shift;
        const auto a = load(p.a);
        const std::shared_ptr<const ImageU16> b = a ? load(p.b) : nullptr;
        if (!a || !b)
            return shift;
        double best = -1;
        for (const Eigen::Matrix2d& h : readings) {
            const PairRegistration r = registerPair(*a, *b, h * e, wide);
            if (r.accepted() && r.ncc > best && !(besides && (r.shiftPx - *besides).norm() < 2)) {
                best = r.ncc;
                shift = r.shiftPx;
            }
        }
        return shift;
    };

    struct Used {
        const TilePair* pair;
        Eigen::Vector2d e;
        int way;
        bool retried;
    };
    std::vector<Used> used;
    std::vector<CameraStageSample> samples;
    int tried[2] = {0, 0};
    int count[2] = {0, 0};
    for (const TilePair& p : pairs) {
        const Eigen::Vector2d e = stagePx[static_cast<std::size_t>(p.b)] - stagePx[static_cast<std::size_t>(p.a)];
        const int way = std::fabs(e.x()) >= std::fabs(e.y()) ? 0 : 1;
        if (count[way] >= options.pairsEachWay)
            continue;
        std::optional<Eigen::Vector2d> shift;
        if (p.reg.accepted()) {
            shift = p.reg.shiftPx;
        } else if (tried[way] < options.pairsEachWay) {
            ++tried[way];
            shift = registerAnyWay(p, e, std::nullopt);
        }
        if (!shift)
            continue;
        ++count[way];
        used.push_back({&p, e, way, !p.reg.accepted()});
        samples.push_back({planM * e, *shift});
    }
    // A pair the stitch accepted under the wrong plan can be a chance match: while the
    // pairs disagree, the worst is read again the other ways (once), or left out.
    std::optional<CameraStageFit> fit = fitCameraStage(samples);
    for (int round = 0; round < 2 * options.pairsEachWay && (!fit || fit->residualMaxPx > options.maxResidualPx); ++round) {
        std::size_t worst = 0;
        double worstPx = -1;
        if (fit) {
            const Eigen::Matrix2d a = fit->stageUmPerPx.inverse();
            for (std::size_t k = 0; k < samples.size(); ++k) {
                const double r = (samples[k].imageShiftPx - a * samples[k].stageStepUm).norm();
                // Outliers against a fit they spoilt are not always the largest residual;
                // a pair not yet read again goes first among near equals.
                const double score = r + (used[k].retried ? 0 : 0.5);
                if (score > worstPx) {
                    worstPx = score;
                    worst = k;
                }
            }
        } else {
            for (std::size_t k = 0; k < used.size(); ++k)
                if (!used[k].retried) {
                    worst = k;
                    worstPx = 0;
                    break;
                }
            if (worstPx < 0)
                break;
        }
        std::optional<Eigen::Vector2d> again;
        if (!used[worst].retried)
            again = registerAnyWay(*used[worst].pair, used[worst].e, samples[worst].imageShiftPx);
        if (again) {
            samples[worst].imageShiftPx = *again;
            used[worst].retried = true;
        } else {
            --count[used[worst].way];
            samples.erase(samples.begin() + static_cast<std::ptrdiff_t>(worst));
            used.erase(used.begin() + static_cast<std::ptrdiff_t>(worst));
        }
        fit = fitCameraStage(samples);
    }
    out.pairsUsed = static_cast<int>(samples.size());
    if (count[0] == 0 || count[1] == 0 || !fit || fit->residualMaxPx > options.maxResidualPx)
        return out;
    out.measured = true;
    out.fit = *fit;
    out.mirrorOff = fit->imageYAlongPlusY != plan.imageYAlongPlusY;
    out.rotationOff = std::fabs(wrapDegrees(fit->rotationDeg - plan.rotationDeg)) > options.rotationToleranceDeg;
    out.pixelOff = std::fabs(out.measuredPixelUm() / plan.pixelUm - 1) > options.pixelToleranceShare;
    return out;
}

std::vector<motion::msg::Message> geometryAdvice(const GeometryCheck& c, const PlanCameraGeometry& plan)
{
    namespace msg = motion::msg;
    std::vector<msg::Message> out;
    if (!c.measured)
        return out;
    const auto imageY = [](bool plusY) { return msg::verbatim("image_y", plusY ? "stage-plus-y" : "stage-minus-y"); };
    if (c.mirrorOff)
        out.push_back(msg::make("imaging.camera_check.mirrored", {imageY(c.fit.imageYAlongPlusY), msg::verbatim("plan_image_y", plan.imageYAlongPlusY ? "stage-plus-y" : "stage-minus-y")}));
    if (c.rotationOff)
        out.push_back(msg::make("imaging.camera_check.rotated", {msg::real("measured", c.fit.rotationDeg, msg::Unit::Deg), msg::real("plan", plan.rotationDeg, msg::Unit::Deg)}));
    if (c.pixelOff)
        out.push_back(msg::make("imaging.camera_check.pixel", {msg::real("measured", c.measuredPixelUm(), msg::Unit::Um), msg::real("plan", plan.pixelUm, msg::Unit::Um)}));
    return out;
}

} // namespace imaging
