#include "device/camera/specimen.h"

#include <algorithm>
#include <cmath>
#include <random>

namespace dev::camera {

namespace {

constexpr int kFineSize = 1024;         ///< texels a side; a power of two (indices wrap by mask)
constexpr double kFineTexelUm = 0.5;
constexpr int kCoarseSize = 256;
constexpr double kCoarseTexelUm = 16;   ///< 4.1 mm period: the denser and looser patches
/// Added to texel coordinates so that truncation is floor for any point within ±500 mm of
/// the origin; a multiple of both table sizes, so it does not move the pattern.
constexpr double kTexelBias = 1048576.0;
/// The slide's second look-up of the fine table, transposed and scaled so that the sum
/// of the two repeats only over metres (10 717 periods of one against 10 000 of the
/// other): no two tiles of a scan see the same texture, which phase correlation would
/// otherwise confuse. Transposed rather than turned: a turned look-up walks across the
/// table's rows and misses the cache at every pixel (a third of a frame's time), while
/// a transposed copy of the table keeps both walks along memory.
constexpr double kSecondLayerScale = 1.0 / 1.0717;
/// The coarse patches change over 16 µm texels: sampled every this many pixels along a
/// row and interpolated between (exact within a texel, as bilinear is linear along a line
/// of constant v, and within 1e-3 of it where a row turns with the camera).
constexpr int kCoarseEvery = 8;
constexpr int kNucleiPerTile = 2600;    ///< about one every 10 µm, as in dense tissue

/// Box blur with wrap-around, along rows then columns, `passes` times: close to a
/// Gaussian of σ = r·sqrt(passes·(r+1)/(3r))… near enough for texture.
void boxBlurWrap(std::vector<float>& img, int size, int radius, int passes)
{
    if (radius <= 0)
        return;
    std::vector<float> line(static_cast<std::size_t>(size));
    const float norm = 1.0f / static_cast<float>(2 * radius + 1);
    const int mask = size - 1;
    for (int p = 0; p < passes; ++p) {
        for (int dir = 0; dir < 2; ++dir) {
            for (int a = 0; a < size; ++a) {
                auto idx = [&](int b) {
                    return dir == 0 ? static_cast<std::size_t>(a) * size + static_cast<std::size_t>(b & mask)
                                    : static_cast<std::size_t>(b & mask) * size + static_cast<std::size_t>(a);
                };
                float sum = 0;
                for (int b = -radius; b <= radius; ++b)
                    sum += img[idx(b)];
                for (int b = 0; b < size; ++b) {
                    line[static_cast<std::size_t>(b)] = sum * norm;
                    sum += img[idx(b + radius + 1)] - img[idx(b - radius)];
                }
                for (int b = 0; b < size; ++b)
                    img[idx(b)] = line[static_cast<std::size_t>(b)];
            }
        }
    }
}

void normalise(std::vector<float>& img)
{
    const auto [lo, hi] = std::minmax_element(img.begin(), img.end());
    const float a = *lo, span = std::max(1e-6f, *hi - *lo);
    for (float& v : img)
        v = (v - a) / span;
}

std::vector<float> noiseField(std::mt19937_64& rng, int size, int radius, int passes)
{
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<float> img(static_cast<std::size_t>(size) * size);
    for (float& v : img)
        v = u(rng);
    boxBlurWrap(img, size, radius, passes);
    normalise(img);
    return img;
}

/// Texel coordinates in 32.16 fixed point: a row walks them by adding a step, and the
/// integer and fraction come out by a shift and a mask (no double-to-int per pixel).
constexpr int kFixBits = 16;
constexpr double kFixOne = 65536.0;
constexpr float kFixInv = 1.0f / 65536.0f;

inline std::int64_t toFix(double texels) { return static_cast<std::int64_t>(std::llround(texels * kFixOne)); }

inline float bilinear(const float* t, int mask, int shift, std::int64_t u, std::int64_t v)
{
    const int x0 = static_cast<int>(u >> kFixBits) & mask, y0 = static_cast<int>(v >> kFixBits) & mask;
    const float fu = static_cast<float>(u & 0xFFFF) * kFixInv, fv = static_cast<float>(v & 0xFFFF) * kFixInv;
    const int x1 = (x0 + 1) & mask, y1 = (y0 + 1) & mask;
    const float* r0 = t + (static_cast<std::ptrdiff_t>(y0) << shift);
    const float* r1 = t + (static_cast<std::ptrdiff_t>(y1) << shift);
    const float a = r0[x0] + (r0[x1] - r0[x0]) * fu;
    const float b = r1[x0] + (r1[x1] - r1[x0]) * fu;
    return a + (b - a) * fv;
}

struct RowPair {
    const float* r0;
    const float* r1;
};

/// The two table rows a bilinear look-up at `v` reads.
inline RowPair rowPair(const float* t, int mask, int shift, std::int64_t v)
{
    const int y0 = static_cast<int>(v >> kFixBits) & mask;
    return {t + (static_cast<std::ptrdiff_t>(y0) << shift), t + (static_cast<std::ptrdiff_t>((y0 + 1) & mask) << shift)};
}

/// bilinear() with its rows and v weight found already: the same arithmetic, so the same value.
inline float bilinearAlongRow(const RowPair& rows, float fv, int mask, std::int64_t u)
{
    const int x0 = static_cast<int>(u >> kFixBits) & mask;
    const float fu = static_cast<float>(u & 0xFFFF) * kFixInv;
    const int x1 = (x0 + 1) & mask;
    const float a = rows.r0[x0] + (rows.r0[x1] - rows.r0[x0]) * fu;
    const float b = rows.r1[x0] + (rows.r1[x1] - rows.r1[x0]) * fu;
    return a + (b - a) * fv;
}

/// 0 inside, 1 outside, a linear ramp `width` wide centred on the edge at distance `edge`.
inline float ramp(double distance, double edge, double width)
{
    const double t = (distance - edge) / width + 0.5;
    return static_cast<float>(t <= 0 ? 0 : (t >= 1 ? 1 : t));
}

} // namespace

std::optional<SpecimenKind> specimenFromName(std::string_view name)
{
    if (name == "slide")
        return SpecimenKind::Slide;
    if (name == "grid-plate")
        return SpecimenKind::GridPlate;
    if (name == "line-scales")
        return SpecimenKind::LineScales;
    return std::nullopt;
}

const char* specimenName(SpecimenKind kind)
{
    switch (kind) {
    case SpecimenKind::Slide: return "slide";
    case SpecimenKind::GridPlate: return "grid-plate";
    case SpecimenKind::LineScales: return "line-scales";
    }
    return "slide";
}

std::vector<std::string> specimenNames() { return {"slide", "grid-plate", "line-scales"}; }

Specimen::Specimen(SpecimenKind kind, std::uint64_t seed, double blurUm) : m_kind(kind), m_seed(seed), m_blurUm(std::max(0.0, blurUm))
{
    if (kind == SpecimenKind::Slide)
        buildSlide();
}

void Specimen::buildSlide()
{
    std::mt19937_64 rng(m_seed * 0x9E3779B97F4A7C15ull + 1);
    // Fibres and granules: two bands of smoothed noise (≈1 µm and ≈4 µm).
    const std::vector<float> grain = noiseField(rng, kFineSize, 2, 3);
    const std::vector<float> fibre = noiseField(rng, kFineSize, 8, 3);
    // Nuclei: dark discs 5–10 µm across with a soft edge, placed at random (wrapping).
    std::vector<float> nuclei(static_cast<std::size_t>(kFineSize) * kFineSize, 0.0f);
    std::uniform_real_distribution<double> pos(0, kFineSize), rad(5.0, 10.0), dens(0.5, 1.0);
    for (int k = 0; k < kNucleiPerTile; ++k) {
        const double cx = pos(rng), cy = pos(rng), r = rad(rng), d = dens(rng);
        const int r0 = static_cast<int>(std::ceil(r + 1));
        for (int y = -r0; y <= r0; ++y)
            for (int x = -r0; x <= r0; ++x) {
                const double dist = std::hypot(x + std::floor(cx) - cx, y + std::floor(cy) - cy);
                const float inside = 1.0f - ramp(dist, r, 1.5);
                if (inside <= 0)
                    continue;
                const int tx = (static_cast<int>(cx) + x) & (kFineSize - 1), ty = (static_cast<int>(cy) + y) & (kFineSize - 1);
                float& v = nuclei[static_cast<std::size_t>(ty) * kFineSize + static_cast<std::size_t>(tx)];
                v = std::max(v, static_cast<float>(inside * d));
            }
    }
    // Absorbance of the tissue: the fibres and granules weakly, the nuclei strongly.
    m_fine.resize(nuclei.size());
    for (std::size_t i = 0; i < m_fine.size(); ++i)
        m_fine[i] = std::min(1.0f, 0.22f * grain[i] + 0.30f * fibre[i] + 0.55f * nuclei[i]);
    // The optics' blur, baked into the table: three box passes of radius r have
    // σ² = r(r+1) texels², so r is the one closest to the asked σ.
    const double sigmaTexels = m_blurUm / kFineTexelUm;
    const int r = static_cast<int>(std::lround(std::max(0.0, (-1 + std::sqrt(1 + 4 * sigmaTexels * sigmaTexels)) / 2)));
    boxBlurWrap(m_fine, kFineSize, r, 3);
    m_fineT.resize(m_fine.size());
    for (std::size_t y = 0; y < static_cast<std::size_t>(kFineSize); ++y)
        for (std::size_t x = 0; x < static_cast<std::size_t>(kFineSize); ++x)
            m_fineT[x * kFineSize + y] = m_fine[y * kFineSize + x];
    // Patches: where the tissue is dense or loose, 0.45 … 1 (loose tissue still has texture).
    m_coarse = noiseField(rng, kCoarseSize, 6, 3);
    for (float& v : m_coarse) {
        const float t = std::clamp((v - 0.3f) / 0.4f, 0.0f, 1.0f);
        v = 0.45f + 0.55f * t * t * (3 - 2 * t);
    }
}

void Specimen::sampleRow(float* out, int n, double x0, double y0, double dx, double dy) const
{
    switch (m_kind) {
    case SpecimenKind::Slide: slideRow(out, n, x0, y0, dx, dy); return;
    case SpecimenKind::GridPlate: gridRow(out, n, x0, y0, dx, dy); return;
    case SpecimenKind::LineScales: scalesRow(out, n, x0, y0, dx, dy); return;
    }
}

float Specimen::at(double xMm, double yMm) const
{
    float v = 0;
    sampleRow(&v, 1, xMm, yMm, 1e-4, 0);
    return v;
}

void Specimen::slideRow(float* out, int n, double x0, double y0, double dx, double dy) const
{
    constexpr double kPerMmFine = 1000.0 / kFineTexelUm, kPerMmCoarse = 1000.0 / kCoarseTexelUm;
    constexpr double k2 = kSecondLayerScale * kPerMmFine;
    // Texel coordinates walk linearly along the row: start and step for each look-up. The
    // second layer reads the transposed table at (y, x) scaled: the same texture, its
    // axes swapped, at another scale.
    std::int64_t u1 = toFix(x0 * kPerMmFine + kTexelBias), v1 = toFix(y0 * kPerMmFine + kTexelBias);
    const std::int64_t du1 = toFix(dx * kPerMmFine), dv1 = toFix(dy * kPerMmFine);
    std::int64_t u2 = toFix(k2 * x0 + kTexelBias + 311.0), v2 = toFix(k2 * y0 + kTexelBias + 577.0);
    const std::int64_t du2 = toFix(k2 * dx), dv2 = toFix(k2 * dy);
    std::int64_t uc = toFix(x0 * kPerMmCoarse + kTexelBias), vc = toFix(y0 * kPerMmCoarse + kTexelBias);
    const std::int64_t duc = toFix(dx * kPerMmCoarse * kCoarseEvery), dvc = toFix(dy * kPerMmCoarse * kCoarseEvery);
    // The bare glass: only rows that come near the disc pay for the distance.
    const double x1 = x0 + dx * n, y1 = y0 + dy * n;
    const double near = kSlideGlassRadiusMm + std::hypot(dx, dy) * n + 0.1;
    const bool glassNear = std::hypot(x0 - kSlideGlassCentreXMm, y0 - kSlideGlassCentreYMm) < near
        || std::hypot(x1 - kSlideGlassCentreXMm, y1 - kSlideGlassCentreYMm) < near;
    const float* fine = m_fine.data();
    const float* fineT = m_fineT.data();
    const float* coarse = m_coarse.data();
    constexpr int kFineShift = 10, kCoarseShift = 8;
    static_assert((1 << kFineShift) == kFineSize && (1 << kCoarseShift) == kCoarseSize, "shift matches the table size");
    // A row along the table's rows (no camera rotation, the usual case) reads the same
    // two table rows throughout: their pointers and the v weight are found once.
    const bool alongRow1 = dv1 == 0 && dv2 == 0;
    const RowPair row1 = rowPair(fine, kFineSize - 1, kFineShift, v1), row2 = rowPair(fineT, kFineSize - 1, kFineShift, v2);
    const float fv1 = static_cast<float>(v1 & 0xFFFF) * kFixInv, fv2 = static_cast<float>(v2 & 0xFFFF) * kFixInv;
    float densityA = bilinear(coarse, kCoarseSize - 1, kCoarseShift, uc, vc);
    for (int k0 = 0; k0 < n; k0 += kCoarseEvery) {
        uc += duc, vc += dvc;
        const float densityB = bilinear(coarse, kCoarseSize - 1, kCoarseShift, uc, vc);
        const float densityStep = (densityB - densityA) * (1.0f / kCoarseEvery);
        const int end = std::min(n, k0 + kCoarseEvery);
        float density = densityA;
        for (int k = k0; k < end; ++k) {
            const float a = 0.5f * (alongRow1 ? bilinearAlongRow(row1, fv1, kFineSize - 1, u1) + bilinearAlongRow(row2, fv2, kFineSize - 1, u2)
                                              : bilinear(fine, kFineSize - 1, kFineShift, u1, v1) + bilinear(fineT, kFineSize - 1, kFineShift, u2, v2));
            float d = density;
            if (glassNear) {
                const double r = std::hypot(x0 + dx * k - kSlideGlassCentreXMm, y0 + dy * k - kSlideGlassCentreYMm);
                d *= ramp(r, kSlideGlassRadiusMm, 0.05);  // a 50 µm edge: the tissue thins out
            }
            out[k] = kGlassTransmittance * (1.0f - 0.85f * d * a);
            u1 += du1, v1 += dv1, u2 += du2, v2 += dv2;
            density += densityStep;
        }
        densityA = densityB;
    }
}

void Specimen::gridRow(float* out, int n, double x0, double y0, double dx, double dy) const
{
    // Into the plate's frame: the point less the offset, turned back by the plate's rotation.
    const double th = kGridPlateRotationDeg * M_PI / 180;
    const double c = std::cos(th), s = std::sin(th);
    const double px = x0 - kGridPlateOffsetXMm, py = y0 - kGridPlateOffsetYMm;
    double qx = (c * px + s * py) / kGridPlatePitchMm, qy = (-s * px + c * py) / kGridPlatePitchMm;
    const double dqx = (c * dx + s * dy) / kGridPlatePitchMm, dqy = (-s * dx + c * dy) / kGridPlatePitchMm;
    const double edge = std::max(std::hypot(dx, dy), 2.5 * m_blurUm * 1e-3) / kGridPlatePitchMm;
    const double radius = kGridPlateDotDiameterMm / 2 / kGridPlatePitchMm;
    for (int k = 0; k < n; ++k) {
        const double ex = qx - std::nearbyint(qx), ey = qy - std::nearbyint(qy);
        const float outside = ramp(std::sqrt(ex * ex + ey * ey), radius, edge);
        out[k] = kChromeTransmittance + (kGlassTransmittance - kChromeTransmittance) * outside;
        qx += dqx, qy += dqy;
    }
}

void Specimen::scalesRow(float* out, int n, double x0, double y0, double dx, double dy) const
{
    const double edge = std::max(std::hypot(dx, dy), 2.5 * m_blurUm * 1e-3);
    const double half = kScaleLineWidthMm / 2;
    // One scale: graduations at along = k·0.1 mm (0 … 100), each line across from 0 to its length.
    auto line = [&](double along, double across) -> float {
        if (along < -0.05 || along > 100.05 || across < -edge || across > kScaleLongLineMm + edge)
            return 1.0f;
        const double g = along / kScaleGraduationMm;
        const double nearest = std::nearbyint(g);
        const bool longLine = static_cast<long long>(nearest) % 10 == 0;
        const double length = longLine ? kScaleLongLineMm : kScaleShortLineMm;
        const float acrossOut = std::max(ramp(-across, 0, edge), ramp(across, length, edge));
        const float alongOut = ramp(std::fabs(g - nearest) * kScaleGraduationMm, half, edge);
        return std::max(acrossOut, alongOut);
    };
    for (int k = 0; k < n; ++k) {
        const double x = x0 + dx * k, y = y0 + dy * k;
        const float outside = std::min(line(x, y - kScaleXAxisAtYMm), line(y, x - kScaleYAxisAtXMm));
        out[k] = kChromeTransmittance + (kGlassTransmittance - kChromeTransmittance) * outside;
    }
}

} // namespace dev::camera
