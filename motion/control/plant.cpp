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

motion::msg::Checked<PlantSpec> parsePlant(std::string_view text)
{
    using R = motion::msg::Checked<PlantSpec>;
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
        return R::fail(motion::msg::make("tuning.plant.unknown_kind", {motion::msg::verbatim("kind", kind)}));
    }
    const std::string list = "K, tau, " + fields[2] + ", Ts";
    const motion::msg::Arg kindArg = motion::msg::verbatim("kind", kind), listArg = motion::msg::verbatim("fields", list);
    auto fieldArg = [](const std::string& name) { return motion::msg::verbatim("field", name); };
    if (colon == std::string::npos)
        return R::fail(motion::msg::make("tuning.plant.no_fields", {kindArg, listArg}));
    std::vector<bool> seen(fields.size(), false);
    double values[4] = {1, 1, 0, PlantSpec{}.periodS};
    std::string rest = all.substr(colon + 1);
    std::size_t at = 0;
    while (at <= rest.size()) {
        const std::size_t comma = std::min(rest.find(',', at), rest.size());
        const std::string item = trim(std::string_view(rest).substr(at, comma - at));
        at = comma + 1;
        if (item.empty())
            return R::fail(motion::msg::make("tuning.plant.empty_field", {kindArg, listArg}));
        const auto eq = item.find('=');
        const std::string name = trim(std::string_view(item).substr(0, eq == std::string::npos ? item.size() : eq));
        const auto it = std::find(fields.begin(), fields.end(), name);
        if (it == fields.end())
            return R::fail(motion::msg::make("tuning.plant.unknown_field", {kindArg, fieldArg(name), listArg}));
        const std::size_t idx = static_cast<std::size_t>(it - fields.begin());
        if (eq == std::string::npos)
            return R::fail(motion::msg::make("tuning.plant.no_value", {kindArg, fieldArg(name)}));
        if (seen[idx])
            return R::fail(motion::msg::make("tuning.plant.field_twice", {kindArg, fieldArg(name)}));
        seen[idx] = true;
        const std::string valueText = trim(std::string_view(item).substr(eq + 1));
        char* end = nullptr;
        const double v = std::strtod(valueText.c_str(), &end);
        if (valueText.empty() || end != valueText.c_str() + valueText.size() || !std::isfinite(v))
            return R::fail(motion::msg::make("tuning.plant.not_a_number", {kindArg, fieldArg(name), motion::msg::verbatim("text", valueText.substr(0, 40))}));
        values[idx] = v;
    }
    for (std::size_t i = 0; i < 3; ++i)
        if (!seen[i])
            return R::fail(motion::msg::make("tuning.plant.field_missing", {kindArg, fieldArg(fields[i]), listArg}));
    p.gain = values[0];
    p.tauS = values[1];
    p.periodS = values[3];
    if (!(p.gain > 0))
        return R::fail(motion::msg::make("tuning.plant.not_positive", {kindArg, fieldArg("K"), motion::msg::real("value", p.gain)}));
    if (!(p.periodS > 0) || p.periodS > 0.1)
        return R::fail(motion::msg::make("tuning.plant.period_out_of_range", {kindArg, motion::msg::real("value", p.periodS, motion::msg::Unit::S), motion::msg::real("max", 0.1, motion::msg::Unit::S)}));
    if (p.kind == PlantSpec::Kind::Fopdt) {
        p.delayS = values[2];
        p.order = 1;
        if (p.tauS < 0)
            return R::fail(motion::msg::make("tuning.plant.negative", {kindArg, fieldArg("tau"), motion::msg::real("value", p.tauS)}));
        if (p.delayS < 0)
            return R::fail(motion::msg::make("tuning.plant.negative", {kindArg, fieldArg("L"), motion::msg::real("value", p.delayS)}));
        if (p.tauS == 0 && p.delayS == 0)
            return R::fail(motion::msg::make("tuning.plant.pure_gain", {kindArg}));
        if (p.tauS == 0)
            p.order = 0;  // a pure dead time
        if (p.delayS > 1e5 * p.periodS)
            return R::fail(motion::msg::make("tuning.plant.delay_too_long", {kindArg, motion::msg::real("delay", p.delayS, motion::msg::Unit::S),
                                                                     motion::msg::real("period", p.periodS, motion::msg::Unit::S)}));
    } else {
        const double n = values[2];
        if (!(n >= 1 && n <= 12 && n == std::floor(n)))
            return R::fail(motion::msg::make("tuning.plant.order_invalid", {kindArg, motion::msg::real("value", n)}));
        p.order = static_cast<int>(n);
        if (!(p.tauS > 0))
            return R::fail(motion::msg::make("tuning.plant.not_positive", {kindArg, fieldArg("tau"), motion::msg::real("value", p.tauS)}));
    }
    return R::ok(p);
}

std::complex<double> frequencyResponse(const PlantSpec& p, double w)
{
    const std::complex<double> lag(1.0, w * p.tauS);
    return p.gain * std::exp(std::complex<double>(0, -w * p.delayS)) / std::pow(lag, p.order);
}

motion::msg::Message whyNoUltimateGain(const PlantSpec& p)
{
    if (p.delayS > 0 || p.order >= 3)
        return {};
    if (p.kind == PlantSpec::Kind::Fopdt)
        return motion::msg::make("tuning.plant.first_order_no_ku");
    return motion::msg::make("tuning.plant.lag_no_ku", {motion::msg::integer("order", p.order, motion::msg::Unit::None), motion::msg::integer("phase", 90 * p.order, motion::msg::Unit::Deg)});
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
