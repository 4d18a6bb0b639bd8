#pragma once
// A command running on a stack of its own, so that a wait inside it suspends the
// command instead of nesting an event loop.
//
// Why: benchpilot-cli's commands are written straight down ("home, wait until still,
// print the status") and wait with spinUntil(). In the CLI's own process a nested
// QEventLoop is harmless. Inside the GUI (the scripting API, app/api/) a nested loop
// on behalf of a socket client would re-enter the screens and the job runners in the
// middle of whatever they were doing. Running the same command on a Fiber turns each
// wait into "suspend until the condition holds": the GUI's one event loop keeps
// running, and the command continues from a plain timer slot. The commands are
// written once and serve both (README.md, "Where a command runs").
//
// Rules for code that runs on a fiber (every command body):
//  - wait only with spinUntil() (it notices the fiber), never with QEventLoop::exec();
//  - never wait inside a slot: Qt keeps per-thread bookkeeping for a signal being
//    delivered, and a slot suspended half-way would leave it pointing into this stack.
//
// Stacks are mmap'ed with a guard page below them (an overflow faults instead of
// corrupting the heap); AddressSanitizer is told about every switch.
#include <cstddef>
#include <functional>
#include <memory>

namespace app::cli {

class Fiber {
public:
    static constexpr std::size_t kStackBytes = 1024 * 1024;  ///< reserved; pages are committed as touched

    explicit Fiber(std::function<void()> body);
    ~Fiber();  ///< a fiber must have finished (see cancel()) before it is destroyed
    Fiber(const Fiber&) = delete;
    Fiber& operator=(const Fiber&) = delete;

    /// Runs the body until it finishes or waits; returns true once it has finished.
    /// Call from the thread's own stack (never from another fiber).
    bool resume();
    bool finished() const { return m_finished; }
    /// True while the fiber is suspended in a wait whose condition now holds, whose
    /// deadline has passed, or that was cancelled: resume() will make progress.
    bool ready() const;
    /// Every wait from now on returns at once as timed out, so the body runs to its end
    /// within a few resumes (used when the server shuts down).
    void cancel();
    bool cancelled() const { return m_cancelled; }

    /// The fiber running on this thread now, or nullptr on the thread's own stack.
    static Fiber* current();
    /// From inside the body: suspends until `done()` or `timeoutMs` (false then).
    bool waitUntil(const std::function<bool()>& done, int timeoutMs);

private:
    struct Context;
    static void entry();
    void switchOut();

    std::function<void()> m_body;
    std::unique_ptr<Context> m_ctx;
    bool m_started = false;
    bool m_finished = false;
    bool m_cancelled = false;
    // The wait the fiber is suspended in.
    std::function<bool()> m_waitDone;
    long long m_waitDeadlineMs = 0;  ///< QDeadlineTimer-free: steady clock ms
};

} // namespace app::cli
