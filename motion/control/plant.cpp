#include "motion/control/plant.h"
#include "motion/numbers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace motion::control {
namespace {

std::string trim(std::string_view s)
{
    std::size_t a = 0, b = s.size();
    while (a < b && (s[a] == ' ' || s[a] == '\t'))
        ++a;
    while (b > a && (s[b - 1] == ' ' || s[b - 1] == '\t'))
        --b;
    return std::string(s.substr(a, b - a));
}

std::string num(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    return buf;
}

/// Phase lag of the plant at ω, as a positive number (π at the crossover).
double phaseLag(const PlantSpec& p, double w) { return p.order * std::atan(w * p.tauS) + w * p.delayS; }

} // namespace

std::string PlantSpec::text() const
{
    std::string s = kind == Kind::Fopdt ? "fopdt:K=" + num(gain) + ",tau=" + num(tauS) + ",L=" + num(delayS)
                                        : "lag:K=" + num(gain) + ",tau=" + num(tauS) + ",n=" + std::to_string(order);
    if (periodS != PlantSpec{}.periodS)
        s += ",Ts=" + num(periodS);
    return s;
}

PlanResult<PlantSpec> parsePlant(std::string_view text)
{
    using R = PlanResult<PlantSpec>;
    const std::string all = trim(text);
    const auto colon = all.find(':');
    const std::string kind = trim(std::string_view(all).substr(0, colon == std::string::npos ? all.size() : colon));
    PlantSpec p;
    std::vector<std::string> fields;
    if (kind == "fopdt") {
        p.kind = PlantSpec::Kind::Fopdt;
        fields = {"K", "tau", "L", "Ts"};
    } else if (kind == "lag") {
        p.kind = PlantSpec::Kind::Lag;
        fields = {"K", "tau", "n", "Ts"};
    } else {
        return R::fail("unknown plant kind '" + kind + "': use fopdt:K=..,tau=..,L=.. or lag:K=..,tau=..,n=..");
    }
    const std::string list = "K, tau, " + fields[2] + ", Ts";
    if (colon == std::string::npos)
        return R::fail(kind + ": no fields given (fields: " + list + ")");
    std::vector<bool> seen(fields.size(), false);
    double values[4] = {1, 1, 0, PlantSpec{}.periodS};
    std::string rest = all.substr(colon + 1);
    std::size_t at = 0;
    while (at <= rest.size()) {
        const std::size_t comma = std::min(rest.find(',', at), rest.size());
        const std::string item = trim(std::string_view(rest).substr(at, comma - at));
        at = comma + 1;
        if (item.empty())
            return R::fail(kind + ": empty field (fields: " + list + ")");
        const auto eq = item.find('=');
        const std::string name = trim(std::string_view(item).substr(0, eq == std::string::npos ? item.size() : eq));
        const auto it = std::find(fields.begin(), fields.end(), name);
        if (it == fields.end())
            return R::fail(kind + ": unknown field '" + name + "' (fields: " + list + ")");
        const std::size_t idx = static_cast<std::size_t>(it - fields.begin());
        if (eq == std::string::npos)
            return R::fail(kind + ": " + name + " has no value (write " + name + "=NUMBER)");
        if (seen[idx])
            return R::fail(kind + ": " + name + " is given twice");
        seen[idx] = true;
        const std::string valueText = trim(std::string_view(item).substr(eq + 1));
        char* end = nullptr;
        const double v = std::strtod(valueText.c_str(), &end);
        if (valueText.empty() || end != valueText.c_str() + valueText.size() || !std::isfinite(v))
            return R::fail(kind + ": " + name + " must be a number (got '" + valueText + "')");
        values[idx] = v;
    }
    for (std::size_t i = 0; i < 3; ++i)
        if (!seen[i])
            return R::fail(kind + ": " + fields[i] + " is missing (fields: " + list + ")");
    p.gain = values[0];
    p.tauS = values[1];
    p.periodS = values[3];
    if (!(p.gain > 0))
        return R::fail(kind + ": K must be above 0 (got " + num(p.gain) + ")");
    if (!(p.periodS > 0) || p.periodS > 0.1)
        return R::fail(kind + ": Ts must be above 0 and at most 0.1 s (got " + num(p.periodS) + ")");
    if (p.kind == PlantSpec::Kind::Fopdt) {
        p.delayS = values[2];
        p.order = 1;
        if (p.tauS < 0)
            return R::fail(kind + ": tau must not be negative (got " + num(p.tauS) + ")");
        if (p.delayS < 0)
            return R::fail(kind + ": L must not be negative (got " + num(p.delayS) + ")");
        if (p.tauS == 0 && p.delayS == 0)
            return R::fail(kind + ": tau and L are both 0: that is a pure gain, not a plant to tune");
        if (p.tauS == 0)
            p.order = 0;  // a pure dead time
        if (p.delayS > 1e5 * p.periodS)
            return R::fail(kind + ": L is more than 100000 control periods (L = " + num(p.delayS) + " s, Ts = " + num(p.periodS)
                           + " s): use a longer Ts");
    } else {
        const double n = values[2];
        if (!(n >= 1 && n <= 12 && n == std::floor(n)))
            return R::fail(kind + ": n must be a whole number from 1 to 12 (got " + num(n) + ")");
        p.order = static_cast<int>(n);
        if (!(p.tauS > 0))
            return R::fail(kind + ": tau must be above 0 (got " + num(p.tauS) + ")");
    }
    return R::ok(p);
}

std::complex<double> frequencyResponse(const PlantSpec& p, double w)
{
    const std::complex<double> lag(1.0, w * p.tauS);
    return p.gain * std::exp(std::complex<double>(0, -w * p.delayS)) / std::pow(lag, p.order);
}

std::string whyNoUltimateGain(const PlantSpec& p)
{
    if (p.delayS > 0 || p.order >= 3)
        return {};
    if (p.kind == PlantSpec::Kind::Fopdt)
        return "a first-order plant without dead time never lags by 180°: P control cannot make it oscillate, so it has no finite ultimate gain";
    return "a lag of order " + std::to_string(p.order) + " lags less than " + std::to_string(90 * p.order)
        + "° at every frequency, never 180°: P control cannot make it oscillate, so it has no finite ultimate gain";
}

std::optional<UltimatePoint> ultimatePoint(const PlantSpec& p)
{
    if (!whyNoUltimateGain(p).empty())
        return std::nullopt;
    double w;
    if (p.delayS == 0) {
        w = std::tan(kPi / p.order) / p.tauS;  // n·atan(ωτ) = π
    } else {
        // The lag grows monotonically with ω: bracket the crossover, then bisect.
        double lo = 0, hi = kPi / p.delayS;  // ωL alone reaches π there
        for (int i = 0; i < 200; ++i) {
            const double mid = 0.5 * (lo + hi);
            (phaseLag(p, mid) < kPi ? lo : hi) = mid;
        }
        w = 0.5 * (lo + hi);
    }
    UltimatePoint u;
    u.omegaRadS = w;
    u.tuS = 2 * kPi / w;
    u.ku = std::pow(1 + (w * p.tauS) * (w * p.tauS), 0.5 * p.order) / p.gain;
    return u;
}

// ---- simulation ------------------------------------------------------------------

namespace {
/// Transition of n equal lags over dt: x_i ← Σ_d phi[d]·x_{i−d} + gamma[i]·u.
void lagTransition(int n, double tauS, double gain, double dt, double* phi, double* gamma)
{
    const double a = std::exp(-dt / tauS), q = dt / tauS;
    double term = 1, sum = 0;  // q^d/d!
    for (int d = 0; d < n; ++d) {
        phi[d] = a * term;
        sum += term;
        gamma[d] = gain * (1 - a * sum);
        term *= q / (d + 1);
    }
}
} // namespace

PlantSim::PlantSim(const PlantSpec& spec) : m_spec(spec), m_order(std::clamp(spec.order, 0, kMaxOrder))
{
    const double periods = spec.delayS / spec.periodS;
    m_wholeDelay = static_cast<std::size_t>(std::floor(periods + 1e-9));
    double frac = periods - static_cast<double>(m_wholeDelay);
    if (frac < 1e-9)
        frac = 0;
    m_split = frac > 0;
    if (m_order > 0) {
        if (m_split) {
            lagTransition(m_order, spec.tauS, spec.gain, frac * spec.periodS, m_phi1, m_gamma1);
            lagTransition(m_order, spec.tauS, spec.gain, (1 - frac) * spec.periodS, m_phi2, m_gamma2);
        } else {
            lagTransition(m_order, spec.tauS, spec.gain, spec.periodS, m_phi2, m_gamma2);
        }
    }
    m_history.assign(m_wholeDelay + 2, 0.0);
}

void PlantSim::settleAt(double u)
{
    std::fill(m_history.begin(), m_history.end(), u);
    for (int i = 0; i < m_order; ++i)
        m_x[i] = m_spec.gain * u;
    m_lastDelayedInput = u;
}

void PlantSim::advance(const double* phi, const double* gamma, double u)
{
    double old[kMaxOrder];
    std::copy(m_x, m_x + m_order, old);
    for (int i = 0; i < m_order; ++i) {
        double v = gamma[i] * u;
        for (int d = 0; d <= i; ++d)
            v += phi[d] * old[i - d];
        m_x[i] = v;
    }
}

void PlantSim::step(double u)
{
    // Ring indices wrap by comparison: a modulo here would cost more than the lag itself.
    const std::size_t size = m_history.size();
    if (++m_head == size)
        m_head = 0;
    m_history[m_head] = u;
    std::size_t now = m_head + size - m_wholeDelay;  // u_{k−m}
    if (now >= size)
        now -= size;
    if (m_split && m_order > 0)
        advance(m_phi1, m_gamma1, m_history[now == 0 ? size - 1 : now - 1]);  // u_{k−m−1}
    if (m_order > 0)
        advance(m_phi2, m_gamma2, m_history[now]);
    m_lastDelayedInput = m_history[now];
}

} // namespace motion::control
