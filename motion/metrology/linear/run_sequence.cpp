#include "motion/metrology/linear/run_sequence.h"

#include <cmath>
#include <string>
#include <unordered_map>

namespace motion::metrology {

std::vector<Stop> runSequence(const AxisTest& t)
{
    std::vector<Stop> out;
    if (hasErrors(validate(t)))
        return out;
    const std::vector<double> p = targetsOf(t);
    const double below = p.front() - t.overrunMm, above = p.back() + t.overrunMm;
    for (int cycle = 1; cycle <= t.cycles; ++cycle) {
        for (std::size_t i = 0; i < p.size(); ++i) {
            Stop s{cycle, Direction::Up, i, p[i], std::nullopt, i == 0 ? below : p[i - 1]};
            if (i == 0)
                s.overrunMm = below;
            out.push_back(s);
        }
        if (!t.bidirectional)
            continue;
        for (std::size_t k = p.size(); k-- > 0;) {
            Stop s{cycle, Direction::Down, k, p[k], std::nullopt, k + 1 == p.size() ? above : p[k + 1]};
            if (k + 1 == p.size())
                s.overrunMm = above;
            out.push_back(s);
        }
    }
    return out;
}

std::size_t readingCount(const AxisTest& t)
{
    return targetsOf(t).size() * static_cast<std::size_t>(t.cycles) * (t.bidirectional ? 2u : 1u);
}

} // namespace motion::metrology

namespace motion::metrology {

motion::msg::Problems checkAgainstPlan(const AxisTest& t, const std::vector<Reading>& readings)
{
    motion::msg::Problems out;
    const std::vector<Stop> plan = runSequence(t);
    if (plan.empty())
        return validate(t);
    if (readings.size() != plan.size())
        out.push_back({"readings", motion::msg::make("accuracy.reading_count_wrong", {motion::msg::integer("count", static_cast<long long>(readings.size())),
                                                                              motion::msg::integer("expected", static_cast<long long>(plan.size()))})});
    auto key = [](double targetMm, Direction d, int cycle) {
        return std::to_string(std::llround(targetMm * 1e6)) + (d == Direction::Up ? "u" : "d") + std::to_string(cycle);
    };
    std::unordered_map<std::string, std::size_t> planned;
    for (std::size_t i = 0; i < plan.size(); ++i)
        planned.emplace(key(plan[i].targetMm, plan[i].direction, plan[i].cycle), i);
    std::vector<bool> read(plan.size(), false);
    for (std::size_t k = 0; k < readings.size(); ++k) {
        const Reading& r = readings[k];
        const auto it = planned.find(key(r.targetMm, r.direction, r.cycle));
        if (it == planned.end())
            out.push_back({indexPath("readings", k),
                           motion::msg::make("accuracy.reading_not_in_plan", {motion::msg::real("target", r.targetMm, motion::msg::Unit::Mm),
                                                                      motion::msg::term("direction", directionTermId(r.direction)), motion::msg::integer("cycle", r.cycle)})});
        else
            read[it->second] = true;
    }
    for (std::size_t i = 0; i < plan.size(); ++i)
        if (!read[i]) {
            out.push_back({"readings", motion::msg::make("accuracy.reading_missing", {motion::msg::real("target", plan[i].targetMm, motion::msg::Unit::Mm),
                                                                              motion::msg::term("direction", directionTermId(plan[i].direction)),
                                                                              motion::msg::integer("cycle", plan[i].cycle)})});
            break;
        }
    return out;
}

} // namespace motion::metrology
