// The stitch's outputs besides the mosaic: Fiji's registered TileConfiguration and
// the JSON report (docs/stitching.md, "The report"). Numbers in the C locale.
#include "imaging/stitch.h"

#include <cmath>
#include <locale>
#include <sstream>

namespace imaging {
namespace {

void jsonString(std::ostringstream& s, const std::string& text)
{
    s << '"';
    for (unsigned char c : text) {
        switch (c) {
        case '"': s << "\\\""; break;
        case '\\': s << "\\\\"; break;
        case '\n': s << "\\n"; break;
        case '\r': s << "\\r"; break;
        case '\t': s << "\\t"; break;
        default:
            if (c < 0x20) {
                static const char* hex = "0123456789abcdef";
                s << "\\u00" << hex[c >> 4] << hex[c & 15];
            } else {
                s << static_cast<char>(c);
            }
        }
    }
    s << '"';
}

/// Rounded to 1/1000 px: more digits would claim what registration cannot know.
double milli(double v)
{
    const double r = std::round(v * 1000.0) / 1000.0;
    return r == 0 ? 0.0 : r;  // no "-0"
}

void pair2(std::ostringstream& s, const Eigen::Vector2d& v)
{
    s << '[' << milli(v.x()) << ',' << milli(v.y()) << ']';
}

} // namespace

std::string registeredTileConfiguration(const StitchResult& r)
{
    std::vector<TileEntry> entries;
    const Eigen::Vector2d origin = r.frame.originPx.cast<double>();
    for (std::size_t i = 0; i < r.tiles.size(); ++i)
        entries.push_back({r.tiles[i].file, r.placement.positionsPx[i] - origin, 0});
    return tileConfigurationText(entries);
}

std::string stitchJson(const StitchResult& r, double seconds, const std::string& mosaicFile)
{
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(12);
    const Eigen::Vector2d origin = r.frame.originPx.cast<double>();
    s << "{\"tiles\":[";
    int byStage = 0;
    for (std::size_t i = 0; i < r.tiles.size(); ++i) {
        const bool stage = r.placement.placedByStage[i];
        byStage += stage;
        s << (i ? "," : "") << "{\"file\":";
        jsonString(s, r.tiles[i].file);
        s << ",\"stage_px\":";
        pair2(s, r.tiles[i].stagePx - origin);
        s << ",\"registered_px\":";
        pair2(s, r.placement.positionsPx[i] - origin);
        s << ",\"correction_px\":";
        pair2(s, r.placement.positionsPx[i] - r.tiles[i].stagePx);
        s << ",\"placed_by\":\"" << (stage ? "stage" : "registration") << "\"}";
    }
    s << "],\"pairs\":[";
    for (std::size_t k = 0; k < r.pairs.size(); ++k) {
        const TilePair& p = r.pairs[k];
        s << (k ? "," : "") << "{\"a\":";
        jsonString(s, r.tiles[static_cast<std::size_t>(p.a)].file);
        s << ",\"b\":";
        jsonString(s, r.tiles[static_cast<std::size_t>(p.b)].file);
        s << ",\"shift_px\":";
        pair2(s, p.reg.shiftPx);
        s << ",\"expected_px\":";
        pair2(s, r.tiles[static_cast<std::size_t>(p.b)].stagePx - r.tiles[static_cast<std::size_t>(p.a)].stagePx);
        s << ",\"score\":" << milli(p.reg.ncc) << ",\"accepted\":" << (p.reg.accepted() ? "true" : "false") << ",\"status\":\""
          << pairStatusName(p.reg.status) << "\"";
        if (k < r.placement.residualPx.size() && (p.reg.accepted() || p.reg.status == PairStatus::Outlier))
            s << ",\"residual_px\":" << milli(r.placement.residualPx[k]);
        s << '}';
    }
    s << "],\"rms_correction_px\":" << milli(r.placement.rmsCorrectionPx) << ",\"worst_correction_px\":" << milli(r.placement.worstCorrectionPx)
      << ",\"pairs_rejected\":" << r.placement.rejectedPairs << ",\"tiles_placed_by_stage\":" << byStage;
    const StageModel& m = r.placement.stageModel;
    auto tenth = [](double v) { return std::round(v * 10) / 10 == 0 ? 0.0 : std::round(v * 10) / 10; };
    s << ",\"stage_model\":{\"used\":" << (m.used ? "true" : "false") << ",\"pairs\":" << m.pairs << ",\"scale_x_ppm\":" << tenth(m.scaleXPpm())
      << ",\"scale_y_ppm\":" << tenth(m.scaleYPpm()) << ",\"rotation_urad\":" << tenth(m.rotationUrad()) << ",\"shear_urad\":" << tenth(m.shearUrad())
      << "},\"rms_beyond_model_px\":" << milli(r.placement.rmsBeyondModelPx) << ",\"worst_beyond_model_px\":" << milli(r.placement.worstBeyondModelPx);
    if (r.cameraCheck && r.planCamera) {
        const GeometryCheck& c = *r.cameraCheck;
        s << ",\"camera_check\":{\"measured\":" << (c.measured ? "true" : "false") << ",\"pairs\":" << c.pairsUsed;
        if (c.measured) {
            s << ",\"pixel_um\":[" << std::round(c.fit.pixelXUm * 1e5) / 1e5 << ',' << std::round(c.fit.pixelYUm * 1e5) / 1e5 << ']'
              << ",\"rotation_deg\":" << milli(c.fit.rotationDeg) << ",\"image_y\":\"" << (c.fit.imageYAlongPlusY ? "stage-plus-y" : "stage-minus-y")
              << "\",\"residual_px\":" << milli(c.fit.residualRmsPx);
        }
        s << ",\"change\":[";
        const char* sep = "";
        if (c.measured && c.mirrorOff) {
            s << sep << "\"camera.image_y\"";
            sep = ",";
        }
        if (c.measured && c.rotationOff) {
            s << sep << "\"camera.rotation_deg\"";
            sep = ",";
        }
        if (c.measured && c.pixelOff)
            s << sep << "\"camera.pixel_um\"";
        s << "]}";
    }
    s << ",\"mosaic\":{\"file\":";
    jsonString(s, mosaicFile);
    s << ",\"width\":" << r.frame.width << ",\"height\":" << r.frame.height << "}";
    s << ",\"seconds\":" << std::round(seconds * 1000) / 1000 << ",\"registration_s\":" << std::round(r.registrationS * 1000) / 1000
      << ",\"placement_s\":" << std::round(r.placementS * 1000) / 1000 << ",\"fusion_s\":" << std::round(r.fusionS * 1000) / 1000 << "}";
    return s.str();
}

} // namespace imaging
