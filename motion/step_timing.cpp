#include "motion/step_timing.h"

#include <algorithm>
#include <cmath>

namespace motion {

std::vector<double> stepInstantsS(const Profile& profile, double stepMm)
{
    std::vector<double> out;
    if (!(stepMm > 0.0) || !std::isfinite(stepMm))
        return out;
    const double length = std::fabs(profile.distance());
    const double sign = profile.distance() < 0.0 ? -1.0 : 1.0;
    // A hair of tolerance so a move of exactly k steps is not rounded down to k-1 by float noise.
    const auto steps = static_cast<std::int64_t>(std::floor(length / stepMm + 1e-9));
    out.reserve(static_cast<std::size_t>(std::max<std::int64_t>(steps, 0)));
    const double T = profile.duration();
    double lo = 0.0;
    for (std::int64_t k = 1; k <= steps; ++k) {
        const double target = std::min(static_cast<double>(k) * stepMm, length);
        double a = lo, b = T;
        double t = lo;
        // Newton from the previous instant, kept inside [a, b]; falls back to bisection where the
        // speed is zero (rest-to-rest ends) or a step overshoots the bracket.
        for (int it = 0; it < 100; ++it) {
            const ProfileSample smp = profile.at(t);
            const double f = sign * smp.s - target;
            if (f < 0.0)
                a = t;
            else
                b = t;
            if (std::fabs(f) <= 1e-12 * std::max(1.0, length) || b - a <= 1e-15 * std::max(1.0, T))
                break;
            const double v = sign * smp.v;
            double next = v > 0.0 ? t - f / v : 0.5 * (a + b);
            if (!(next > a && next < b))
                next = 0.5 * (a + b);
            t = next;
        }
        if (k == steps && std::fabs(static_cast<double>(steps) * stepMm - length) <= 1e-9 * stepMm)
            t = T;  // the last step is the end of the move
        out.push_back(t);
        lo = t;
    }
    return out;
}

StepTable buildStepTable(const std::vector<double>& instantsS, const StepTimerConfig& config)
{
    StepTable table;
    const double clock = config.clockHz;
    const auto interrupt = static_cast<std::uint32_t>(std::llround(config.interruptPeriodS * clock));
    table.interruptTicks = interrupt;
    if (instantsS.empty() || interrupt == 0)
        return table;
    const auto minTicks = static_cast<std::uint32_t>(std::llround(clock / config.maxRateHz));
    const auto maxTicks = static_cast<std::uint32_t>(std::llround(clock / config.minRateHz));
    table.entries.reserve(instantsS.size());
    std::int64_t prevAbsTicks = 0;
    std::int64_t prevMatch = config.firstMatchTicks;
    std::int64_t compensation = 0;  // seed: PWMMatch[next] = -1 after a zero-match correction
    std::uint64_t totalTicks = 0;
    double prevInstant = 0.0;
    for (double instant : instantsS) {
        StepTableEntry e;
        e.idealPeriodS = instant - prevInstant;
        prevInstant = instant;
        const std::int64_t absTicks = std::llround(instant * clock);
        std::int64_t period = absTicks - prevAbsTicks;
        prevAbsTicks = absTicks;
        if (period < minTicks) {
            period = minTicks;
            e.clamped = true;
        } else if (period > maxTicks) {
            period = maxTicks;
            e.clamped = true;
        }
        if (e.clamped)
            ++table.clampedCount;
        e.periodTicks = static_cast<std::uint32_t>(period);
        totalTicks += static_cast<std::uint64_t>(period);
        // Seed 001 formula (1): pulse time counted from the start of the previous edge's period.
        const std::int64_t pulse = period + prevMatch + compensation;
        e.wholePeriods = static_cast<std::uint32_t>(pulse / interrupt);
        std::int64_t match = pulse % interrupt;
        compensation = 0;
        if (match == 0) {
            match = 1;  // one tick late now …
            compensation = -1;  // … and one tick early next time
            e.zeroCorrected = true;
            ++table.zeroCorrections;
        }
        e.matchTicks = static_cast<std::int32_t>(match);
        prevMatch = match;
        table.maxWholePeriods = std::max(table.maxWholePeriods, e.wholePeriods);
        table.entries.push_back(e);
    }
    table.idealDurationS = instantsS.back();
    table.tableDurationS = static_cast<double>(totalTicks) / clock;
    table.timeErrorS = table.tableDurationS - table.idealDurationS;
    return table;
}

StepTable stepTableForProfile(const Profile& profile, double stepMm, const StepTimerConfig& config)
{
    return buildStepTable(stepInstantsS(profile, stepMm), config);
}

std::optional<TrapezoidProfile> seed001Profile(const Seed001Move& move)
{
    TrapezoidParams p;
    p.startSpeedMmS = move.startRateHz;
    p.topSpeedMmS = move.topRateHz;
    p.accelMmS2 = move.accelHzS;
    p.decelMmS2 = move.decelHzS;
    p.plateauMm = static_cast<double>(move.plateauSteps);
    return TrapezoidProfile::plan(static_cast<double>(move.totalSteps), p);
}

std::vector<double> seed001StepInstantsS(const Seed001Move& move)
{
    std::vector<double> out;
    const auto profile = seed001Profile(move);
    if (!profile || move.totalSteps <= 0 || !(move.startRateHz > 0.0))
        return out;
    // Step budget from the seed's rules (the same as the continuous profile's), in whole steps.
    const std::int64_t N = move.totalSteps;
    const std::int64_t P = profile->constantSpeed() ? 0 : move.plateauSteps;
    const double v0 = move.startRateHz, vTop = profile->reachedTopSpeedMmS();
    const auto decelSteps = static_cast<std::int64_t>(std::llround(profile->decelLengthMm()));
    out.reserve(static_cast<std::size_t>(N));
    enum class Status { StartPlateau, Accelerate, Cruise, Decelerate, StopPlateau };  // seed: RuningStatus
    Status status = P > 0 ? Status::StartPlateau : Status::Accelerate;
    if (profile->constantSpeed())
        status = Status::Cruise;
    double v = v0;
    double t = 0.0;
    for (std::int64_t k = 1; k <= N; ++k) {
        const std::int64_t remaining = N - k + 1;  // including this step
        if (status == Status::StartPlateau && k > P)
            status = Status::Accelerate;
        if ((status == Status::Accelerate || status == Status::Cruise) && !profile->constantSpeed()
            && remaining <= decelSteps + P)
            status = Status::Decelerate;
        if (status == Status::Decelerate && remaining <= P)
            status = Status::StopPlateau;
        const double t0 = 1.0 / v;  // previous period, standing in for the new one
        switch (status) {
        case Status::StartPlateau:
        case Status::StopPlateau:
            v = v0;  // the plateau runs at the start speed even if deceleration had not got there
            break;
        case Status::Accelerate:
            v = std::min(vTop, v + move.accelHzS * t0);
            if (v >= vTop)
                status = Status::Cruise;
            break;
        case Status::Cruise:
            break;
        case Status::Decelerate:
            v = std::max(v0, v - move.decelHzS * t0);
            break;
        }
        t += 1.0 / v;
        out.push_back(t);
    }
    return out;
}

}  // namespace motion
