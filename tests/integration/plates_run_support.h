#pragma once
// Running recipes on the in-process simulated analyzer: a homed session with a
// sped-up clock, plans from where the machine stands, and what the run log says.
#include "device/files/plates/deck_file.h"
#include "device/files/recipes/run_log.h"
#include "device/files/text_file.h"
#include "device/jobs/recipe_runner.h"
#include "sim_session.h"

#include <QTemporaryDir>

#include <map>

namespace platestest {

/// Virtual seconds per wall second while recipes run (the link is unpaced).
/// A simulator built with the sanitizers is some ten times slower and cannot
/// keep a clock that fast and still answer the host in time.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kRunTimeScale = 5;
#else
constexpr double kRunTimeScale = 20;
#endif

inline motion::plates::Recipe samplingRecipe(const std::string& wells, double volumeUl = 10, std::optional<double> speedUlS = {})
{
    motion::plates::Recipe r;
    r.name = "sampling";
    r.plates = {{"samples", "1", "sbs-96", 55, 70}};
    motion::plates::Step s;
    s.type = motion::plates::StepType::Aspirate;
    s.wells = {wells};
    s.volumeUl = volumeUl;
    s.speedUlS = speedUlS;
    r.steps = {s};
    return r;
}

inline motion::plates::PlanContext builtinContext()
{
    motion::plates::PlanContext c;
    c.deck = dev::files::plates::builtinDeck();
    for (auto& lw : motion::plates::builtinLabware())
        c.labware[lw.id] = lw;
    return c;
}

inline motion::plates::RecipePlan planFor(const motion::plates::Recipe& r, const dev::BenchPilotClient& client)
{
    motion::plates::StartState s;
    const auto& a = client.status().axes;
    if (a.size() >= 4)
        s = {a[0].commanded, a[1].commanded, a[2].commanded, a[3].commanded};
    return motion::plates::planRecipe(r, builtinContext(), s);
}

/// A resumed run's plan: from where the logged run began (its plunger), so the
/// syringe's accounting is the original run's.
inline motion::plates::RecipePlan planForResume(const motion::plates::Recipe& r, const dev::BenchPilotClient& client, const QString& log)
{
    return motion::plates::planRecipe(r, builtinContext(), dev::jobs::RecipeRunner::resumeStart(log, client));
}

/// Per op: how many "start" and "done" lines the log has.
struct LogCounts {
    std::map<int, int> starts, dones, pumps, skips;
    int stops = 0, resumes = 0, finished = 0;
};

inline LogCounts countLog(const QString& path)
{
    LogCounts c;
    std::string text;
    QString error;
    if (!dev::files::readText(path, &text, &error))
        return c;
    std::size_t from = 0;
    while (from < text.size()) {
        std::size_t end = text.find('\n', from);
        if (end == std::string::npos)
            end = text.size();
        const auto parsed = dev::files::json::parse(std::string_view(text).substr(from, end - from));
        from = end + 1;
        if (!parsed)
            continue;
        const auto* ev = parsed.value->find("event");
        const auto* op = parsed.value->find("op");
        const std::string e = ev ? ev->asString() : "";
        const int i = op ? static_cast<int>(op->asNumber()) : -1;
        if (e == "start")
            ++c.starts[i];
        else if (e == "done")
            ++c.dones[i];
        else if (e == "pump")
            ++c.pumps[i];
        else if (e == "skip")
            ++c.skips[i];
        else if (e == "stop")
            ++c.stops;
        else if (e == "resume")
            ++c.resumes;
        else if (e == "finished")
            ++c.finished;
    }
    return c;
}

inline dev::files::plates::RunLogState readLog(const QString& path)
{
    std::string text;
    QString error;
    dev::files::readText(path, &text, &error);
    return dev::files::plates::readRunLog(text);
}

/// Waits for the runner to leave its running states.
inline bool waitSettled(const dev::jobs::RecipeRunner& r, int timeoutMs)
{
    return itest::waitFor(
        [&] {
            const auto s = r.state();
            return s == dev::jobs::RunState::Finished || s == dev::jobs::RunState::Stopped || s == dev::jobs::RunState::Paused;
        },
        timeoutMs);
}

} // namespace platestest
