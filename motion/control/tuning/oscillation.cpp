#include "motion/control/tuning/oscillation.h"
#include "motion/numbers.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace motion::control {
namespace {
constexpr double kMinSamplesPerCycle = 12;

Extremum makeExtremum(const std::vector<double>& y, double periodS, std::size_t i, bool maximum)
{
    Extremum e;
    e.index = i;
    e.maximum = maximum;
    e.value = y[i];
    e.timeS = static_cast<double>(i) * periodS;
    if (i > 0 && i + 1 < y.size()) {
        const double a = y[i - 1], b = y[i], c = y[i + 1];
        const double den = a - 2 * b + c;
        if (std::abs(den) > 1e-300) {
            const double off = std::clamp(0.5 * (a - c) / den, -0.5, 0.5);
            e.timeS += off * periodS;
            e.value = b - 0.25 * (a - c) * off;
        }
    }
    return e;
}

double geometricMeanOfLast(const std::vector<double>& v, std::size_t count)
{
    const std::size_t n = std::min(count, v.size());
    double s = 0;
    for (std::size_t i = v.size() - n; i < v.size(); ++i)
        s += std::log(std::max(v[i], 1e-300));
    return std::exp(s / static_cast<double>(n));
}

OscillationAnalysis fromExtrema(const std::vector<Extremum>& ex)
{
    OscillationAnalysis a;
    a.method = OscillationAnalysis::Method::Extrema;
    a.extrema = static_cast<int>(ex.size());
    if (ex.size() < 4)
        return a;
    std::vector<double> pp;
    for (std::size_t i = 0; i + 1 < ex.size(); ++i)
        pp.push_back(std::abs(ex[i + 1].value - ex[i].value));
    for (std::size_t i = 0; i + 2 < pp.size(); ++i)
        if (pp[i] > 0)
            a.ratios.push_back(pp[i + 2] / pp[i]);
    if (a.ratios.empty())
        return a;
    a.oscillating = true;
    a.ratio = geometricMeanOfLast(a.ratios, 4);
    a.lastPeakToPeak = pp.back();
    // Period: same-polarity extrema two apart, over the same cycles as the ratio.
    const std::size_t use = std::min<std::size_t>(ex.size() - 2, 8);
    double sum = 0;
    for (std::size_t i = ex.size() - 2 - use; i + 2 < ex.size(); ++i)
        sum += ex[i + 2].timeS - ex[i].timeS;
    a.periodS = sum / static_cast<double>(use);
    return a;
}

OscillationAnalysis fitDampedSine(const std::vector<double>& y, double periodS, std::size_t from)
{
    OscillationAnalysis a;
    a.method = OscillationAnalysis::Method::DampedSineFit;
    if (y.size() < from + 8)
        return a;
    // y_k = a1·y_{k−1} + a2·y_{k−2} + c, least squares (centred for conditioning).
    const std::size_t n = y.size() - from - 2;
    double mean = 0;
    for (std::size_t k = from; k < y.size(); ++k)
        mean += y[k];
    mean /= static_cast<double>(y.size() - from);
    Eigen::MatrixXd A(static_cast<Eigen::Index>(n), 3);
    Eigen::VectorXd b(static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t k = from + 2 + i;
        A(static_cast<Eigen::Index>(i), 0) = y[k - 1] - mean;
        A(static_cast<Eigen::Index>(i), 1) = y[k - 2] - mean;
        A(static_cast<Eigen::Index>(i), 2) = 1;
        b(static_cast<Eigen::Index>(i)) = y[k] - mean;
    }
    const Eigen::Vector3d p = A.colPivHouseholderQr().solve(b);
    const double a1 = p(0), a2 = p(1);
    // Roots of z² − a1·z − a2: a complex pair ρ·e^{±jθ} is an oscillation.
    if (a1 * a1 + 4 * a2 >= 0 || -a2 <= 0)
        return a;
    const double rho = std::sqrt(-a2);
    const double cosTheta = std::clamp(a1 / (2 * rho), -1.0, 1.0);
    const double theta = std::acos(cosTheta);
    if (theta < 1e-6)
        return a;
    const double samplesPerCycle = 2 * kPi / theta;
    a.oscillating = true;
    a.ratio = std::pow(rho, samplesPerCycle);
    a.ratios = {a.ratio};
    a.periodS = samplesPerCycle * periodS;
    const std::size_t last = std::min<std::size_t>(y.size() - from, static_cast<std::size_t>(std::ceil(samplesPerCycle)) + 1);
    const auto [lo, hi] = std::minmax_element(y.end() - static_cast<std::ptrdiff_t>(last), y.end());
    a.lastPeakToPeak = *hi - *lo;
    return a;
}

/// Times of rising crossings of y through `level` in [from, to), interpolated.
std::vector<double> risingCrossings(const std::vector<double>& y, double level, std::size_t from, std::size_t to)
{
    std::vector<double> t;
    for (std::size_t k = std::max<std::size_t>(from, 1); k < to; ++k)
        if (y[k - 1] < level && y[k] >= level)
            t.push_back(static_cast<double>(k - 1) + (level - y[k - 1]) / (y[k] - y[k - 1]));
    return t;
}
} // namespace

std::vector<Extremum> findExtrema(const std::vector<double>& y, double periodS, std::size_t from, double swing)
{
    std::vector<Extremum> out;
    if (y.size() <= from + 1)
        return out;
    int dir = 0;  // 0 until the signal has moved by `swing`; then +1 rising (candidate maximum), −1 falling
    std::size_t hi = from, lo = from, cand = from;
    for (std::size_t k = from + 1; k < y.size(); ++k) {
        if (dir == 0) {
            if (y[k] > y[hi])
                hi = k;
            if (y[k] < y[lo])
                lo = k;
            if (y[hi] - y[lo] > swing) {
                dir = hi > lo ? 1 : -1;
                cand = dir > 0 ? hi : lo;
            }
        } else if (dir > 0) {
            if (y[k] > y[cand]) {
                cand = k;
            } else if (y[k] < y[cand] - swing) {
                out.push_back(makeExtremum(y, periodS, cand, true));
                dir = -1;
                cand = k;
            }
        } else {
            if (y[k] < y[cand]) {
                cand = k;
            } else if (y[k] > y[cand] + swing) {
                out.push_back(makeExtremum(y, periodS, cand, false));
                dir = 1;
                cand = k;
            }
        }
    }
    return out;
}

OscillationAnalysis analyzeOscillation(const std::vector<double>& y, double periodS, std::size_t from, double swing)
{
    const auto ex = findExtrema(y, periodS, from, swing);
    if (ex.size() >= 3) {
        double spacing = 0;
        for (std::size_t i = 1; i < ex.size(); ++i)
            spacing += static_cast<double>(ex[i].index - ex[i - 1].index);
        spacing /= static_cast<double>(ex.size() - 1);
        if (2 * spacing < kMinSamplesPerCycle) {
            // Too few samples a cycle for the peaks: fit from the first extremum on
            // (what comes before it is the step's own transient).
            auto fit = fitDampedSine(y, periodS, ex.front().index);
            fit.extrema = static_cast<int>(ex.size());
            return fit;
        }
    }
    return fromExtrema(ex);
}

double FrequencyPoint::phaseRad() const
{
    double p = std::arg(g);
    if (p > 0)
        p -= 2 * kPi;
    return p;
}

FrequencyPoint fourierPoint(const Record& r, std::size_t first, std::size_t samples, double w, InputModel input)
{
    FrequencyPoint fp;
    fp.omegaRadS = w;
    const std::size_t end = std::min(r.size(), first + samples);
    if (end <= first)
        return fp;
    double ym = 0, um = 0;
    for (std::size_t k = first; k < end; ++k) {
        ym += r.measured[k];
        um += r.output[k];
    }
    ym /= static_cast<double>(end - first);
    um /= static_cast<double>(end - first);
    // A slow drift of the output (a plant still settling onto the new cycle)
    // would leak into the harmonic; the means of the first and the last whole
    // cycle of the window measure it without bias from the oscillation itself.
    const double T = r.periodS;
    const std::size_t cycle = static_cast<std::size_t>(std::lround(2 * kPi / (w * T)));
    double slope = 0;
    if (cycle >= 1 && end - first >= 2 * cycle) {
        double a = 0, b = 0;
        for (std::size_t k = 0; k < cycle; ++k) {
            a += r.measured[first + k];
            b += r.measured[end - cycle + k];
        }
        slope = (b - a) / static_cast<double>(cycle) / static_cast<double>(end - first - cycle);
    }
    const double mid = 0.5 * static_cast<double>(first + end - 1);
    std::complex<double> Y, U;
    for (std::size_t k = first; k < end; ++k) {
        const std::complex<double> rot = std::polar(1.0, -w * static_cast<double>(k) * T);
        Y += (r.measured[k] - ym - slope * (static_cast<double>(k) - mid)) * rot;
        U += (r.output[k] - um) * rot;
    }
    Y *= T;
    if (input == InputModel::Held)
        U *= (1.0 - std::polar(1.0, -w * T)) / std::complex<double>(0, w);  // ∫ over each held period, exactly
    else
        U *= T;
    fp.g = std::abs(U) > 0 ? Y / U : std::complex<double>();
    return fp;
}

RelayAnalysis analyzeRelay(const Record& r, double d, double eps, InputModel input)
{
    RelayAnalysis a;
    const std::size_t n = r.size();
    if (n < 16) {
        a.problem = motion::msg::make("tuning.relay.record_too_short");
        return a;
    }
    // Zero crossings of the output around the mean of its second half.
    double mean = 0;
    for (std::size_t k = n / 2; k < n; ++k)
        mean += r.measured[k];
    mean /= static_cast<double>(n - n / 2);
    const auto t = risingCrossings(r.measured, mean, 0, n);
    if (t.size() < 4) {
        a.problem = motion::msg::make("tuning.relay.no_oscillation");
        return a;
    }
    // The last cycles whose periods agree with the last one within 2 %: stable.
    std::vector<double> periods;
    for (std::size_t i = 1; i < t.size(); ++i)
        periods.push_back(t[i] - t[i - 1]);
    const double lastP = periods.back();
    if (lastP <= 2.5) {
        a.problem = motion::msg::make("tuning.relay.chatter");
        return a;
    }
    // The relay switches only at a sample, so a limit cycle that is not a whole number
    // of samples long alternates (the stage: 5.15, 5.85, 5.15, … samples). Each
    // crossing may move by up to a sample; an even number of cycles averages the
    // alternation out exactly.
    const double tolerance = std::max(0.02 * lastP, 1.0);
    std::size_t firstStable = periods.size() - 1;
    while (firstStable > 0 && std::abs(periods[firstStable - 1] - lastP) <= tolerance && periods.size() - firstStable < 8)
        --firstStable;
    if ((periods.size() - firstStable) % 2 == 1 && periods.size() - firstStable > 2)
        ++firstStable;
    const std::size_t cycles = periods.size() - firstStable;
    if (cycles < 2) {
        a.problem = motion::msg::make("tuning.relay.unsettled");
        return a;
    }
    double sumP = 0;
    for (std::size_t i = firstStable; i < periods.size(); ++i)
        sumP += periods[i];
    const double pSamples = sumP / static_cast<double>(cycles);
    a.periodS = pSamples * r.periodS;
    a.cycles = static_cast<int>(cycles);
    const double tStart = t[firstStable], tEnd = t.back();
    a.first = static_cast<std::size_t>(std::ceil(tStart));
    a.samples = static_cast<std::size_t>(std::lround(tEnd - tStart));
    double amp = 0;
    for (std::size_t c = 0; c < cycles; ++c) {
        const std::size_t lo = static_cast<std::size_t>(std::ceil(t[firstStable + c]));
        const std::size_t hi = std::min(n, static_cast<std::size_t>(std::ceil(t[firstStable + c + 1])) + 1);
        const auto [mn, mx] = std::minmax_element(r.measured.begin() + static_cast<std::ptrdiff_t>(lo),
                                                  r.measured.begin() + static_cast<std::ptrdiff_t>(hi));
        amp += 0.5 * (*mx - *mn);
    }
    a.amplitude = amp / static_cast<double>(cycles);
    if (a.amplitude <= eps) {
        a.problem = motion::msg::make("tuning.relay.below_hysteresis");
        return a;
    }
    a.kuDescribing = 4 * d / (kPi * std::sqrt(a.amplitude * a.amplitude - eps * eps));
    const double w = 2 * kPi / a.periodS;
    a.fundamental = fourierPoint(r, a.first, a.samples, w, input);
    a.third = fourierPoint(r, a.first, a.samples, 3 * w, input);
    // The third harmonic needs a few samples per cycle of its own to mean anything.
    a.thirdUsable = 3 * w * r.periodS < kPi / 4 && a.third.gain() > 0 && std::isfinite(a.third.gain());
    a.ok = true;
    return a;
}

FrequencyPoint analyzeForced(const Record& r, long periodSamples, int skipCycles, InputModel input)
{
    const std::size_t p = static_cast<std::size_t>(std::max(2L, periodSamples));
    const std::size_t first = p * static_cast<std::size_t>(std::max(0, skipCycles));
    const std::size_t whole = r.size() > first ? (r.size() - first) / p : 0;
    return fourierPoint(r, first, whole * p, 2 * kPi / (static_cast<double>(p) * r.periodS), input);
}

} // namespace motion::control
