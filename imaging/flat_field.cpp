#include "imaging/flat_field.h"

#include "imaging/tiff_read.h"

#include <algorithm>
#include <cmath>

namespace imaging {
namespace {

motion::msg::Problem flatProblem(const std::string& file, const char* id, std::vector<motion::msg::Arg> args)
{
    return motion::msg::Problem(file, 0, 0, "", motion::msg::make(id, std::move(args)));
}

/// A blank darker than this above the dark level, anywhere, is a hole, not shading:
/// a gain of more than 1/kMinFraction would lift the noise as much as the light.
constexpr double kMinFraction = 0.1;
/// More than this share of clipped samples: the blank saturated and says nothing there.
constexpr double kMaxClippedShare = 0.01;

} // namespace

motion::msg::Checked<FlatField> FlatField::fromBlank(const ImageU16& blank, double darkLevel, const std::string& shownName)
{
    using Result = motion::msg::Checked<FlatField>;
    if (blank.empty())
        return Result::refused({flatProblem(shownName, "imaging.flat.empty", {})});
    const std::size_t n = blank.px.size();
    const std::uint16_t top = *std::max_element(blank.px.begin(), blank.px.end());
    // 8-bit images are widened as they are read, so their ceiling is 255.
    const std::uint16_t ceiling = top <= 255 ? 255 : 65535;
    std::size_t clipped = 0;
    double sum = 0;
    for (std::uint16_t v : blank.px) {
        clipped += v >= ceiling;
        sum += v - darkLevel;
    }
    const double mean = sum / static_cast<double>(n);
    if (mean <= 0)
        return Result::refused({flatProblem(shownName, "imaging.flat.dark",
                                        {motion::msg::real("mean", mean + darkLevel),
                                         motion::msg::real("dark", darkLevel)})});
    if (static_cast<double>(clipped) > kMaxClippedShare * static_cast<double>(n))
        return Result::refused({flatProblem(shownName, "imaging.flat.clipped",
                                        {                                         motion::msg::real("percent", 100.0 * static_cast<double>(clipped) / static_cast<double>(n))})});
    FlatField f;
    f.m_name = shownName;
    f.m_width = blank.width;
    f.m_height = blank.height;
    f.m_dark = darkLevel;
    f.m_gain.resize(n);
    std::size_t holes = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double level = blank.px[i] - darkLevel;
        if (level < kMinFraction * mean) {
            ++holes;
            f.m_gain[i] = 1.0f / static_cast<float>(kMinFraction);
        } else {
            f.m_gain[i] = static_cast<float>(mean / level);
        }
        f.m_maxGain = std::max(f.m_maxGain, static_cast<double>(f.m_gain[i]));
    }
    if (static_cast<double>(holes) > kMaxClippedShare * static_cast<double>(n))
        return Result::refused({flatProblem(shownName, "imaging.flat.holes",
                                            {                                             motion::msg::real("percent", 100.0 * static_cast<double>(holes) / static_cast<double>(n))})});
    return Result::ok(std::move(f));
}

motion::msg::Checked<FlatField> FlatField::fromFile(const std::string& path, double darkLevel, const std::string& shownName)
{
    const std::string name = shownName.empty() ? path : shownName;
    motion::msg::Checked<TileImage> read = readTiff(path, name);
    if (!read)
        return motion::msg::Checked<FlatField>::refused(read.problems());
    return fromBlank(read->grey, darkLevel, name);
}

motion::msg::Problems FlatField::checkSize(int width, int height, const std::string& shownName) const
{
    if (width == m_width && height == m_height)
        return {};
    return {flatProblem(shownName, "imaging.flat.size",
                        {motion::msg::verbatim("flat", m_name), motion::msg::integer("width", width, motion::msg::Unit::None),
                         motion::msg::integer("height", height, motion::msg::Unit::None), motion::msg::integer("flat_width", m_width, motion::msg::Unit::None),
                         motion::msg::integer("flat_height", m_height, motion::msg::Unit::None)})};
}

motion::msg::Problems FlatField::apply(TileImage& tile, const std::string& shownName) const
{
    motion::msg::Problems size = checkSize(tile.grey.width, tile.grey.height, shownName);
    if (!size.empty())
        return size;
    const float dark = static_cast<float>(m_dark);
    const long ceiling = tile.kind == SampleKind::Grey16 ? 65535L : 255L;
    std::vector<std::uint16_t>& px = tile.grey.px;
    for (std::size_t i = 0; i < px.size(); ++i) {
        const float v = (static_cast<float>(px[i]) - dark) * m_gain[i];
        px[i] = static_cast<std::uint16_t>(std::clamp(std::lround(v), 0L, ceiling));
    }
    return {};
}

} // namespace imaging
