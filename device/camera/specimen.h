#pragma once
// The simulated camera's specimens: what lies on the stage, as transmittance (0 … 1) at a
// point given in stage millimetres (the point that sits under the objective when the stage
// reads that position). Seeded and deterministic; docs/camera.md gives each one's map.
//
// - slide: tissue-like texture at several scales (fibres, nuclei, denser and looser
//   patches), not periodic anywhere on the travel, and a disc of bare glass where
//   registration has nothing to hold on to;
// - grid-plate: chrome dots 0.1 mm across every 1 mm over the whole travel, the plate laid
//   with a small offset and rotation (kGridPlate*);
// - line-scales: two glass scales graduated every 0.1 mm (long lines every 1 mm), one
//   along X at Y = 50 mm, one along Y at X = 50 mm.
//
// Speed: the slide's texture is computed once (a few 10 MB of tables) and then looked up
// (bilinear), so a 2048 × 2048 frame costs a few table reads a pixel. Plain C++.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace dev::camera {

enum class SpecimenKind { Slide, GridPlate, LineScales };

std::optional<SpecimenKind> specimenFromName(std::string_view name);
const char* specimenName(SpecimenKind kind);
std::vector<std::string> specimenNames();

// The nominal geometry docs/camera.md states (the calibration measures against these).
constexpr double kGridPlatePitchMm = 1.0;
constexpr double kGridPlateDotDiameterMm = 0.1;
constexpr double kGridPlateOffsetXMm = 0.137;   ///< the dot nominally at (0, 0) sits here
constexpr double kGridPlateOffsetYMm = -0.089;
constexpr double kGridPlateRotationDeg = 0.05;  ///< the plate's rows against stage +X, counter-clockwise
constexpr double kScaleGraduationMm = 0.1;
constexpr double kScaleLineWidthMm = 0.004;
constexpr double kScaleShortLineMm = 0.15;  ///< every 0.1 mm
constexpr double kScaleLongLineMm = 0.3;    ///< every 1 mm
constexpr double kScaleXAxisAtYMm = 50;     ///< the X scale's lines start at this Y and run towards +Y
constexpr double kScaleYAxisAtXMm = 50;     ///< the Y scale's lines start at this X and run towards +X
constexpr double kSlideGlassCentreXMm = 70; ///< the slide's bare glass: a disc here …
constexpr double kSlideGlassCentreYMm = 30;
constexpr double kSlideGlassRadiusMm = 6;   ///< … of this radius

/// Transmittance of bare glass and of the chrome of plates and scales.
constexpr float kGlassTransmittance = 0.92f;
constexpr float kChromeTransmittance = 0.06f;

class Specimen {
public:
    /// `blurUm`: σ of the optics' Gaussian blur at the sample.
    Specimen(SpecimenKind kind, std::uint64_t seed, double blurUm = 0.6);

    SpecimenKind kind() const { return m_kind; }
    std::uint64_t seed() const { return m_seed; }

    /// Transmittance at `n` points x0 + k·dx, y0 + k·dy (mm), k = 0 … n−1, into `out`.
    /// `footprintMm`: the distance between neighbouring points (edges are smoothed over it).
    void sampleRow(float* out, int n, double x0Mm, double y0Mm, double dxMm, double dyMm) const;
    /// One point (tests, and the documentation of the map).
    float at(double xMm, double yMm) const;

private:
    void buildSlide();
    void slideRow(float* out, int n, double x0, double y0, double dx, double dy) const;
    void gridRow(float* out, int n, double x0, double y0, double dx, double dy) const;
    void scalesRow(float* out, int n, double x0, double y0, double dx, double dy) const;

    SpecimenKind m_kind;
    std::uint64_t m_seed;
    double m_blurUm;
    std::vector<float> m_fine;    ///< kFineSize², periodic; texel kFineTexelUm
    std::vector<float> m_fineT;   ///< m_fine transposed: the second layer's rows walk along memory
    std::vector<float> m_coarse;  ///< kCoarseSize², periodic; texel kCoarseTexelUm
};

} // namespace dev::camera
