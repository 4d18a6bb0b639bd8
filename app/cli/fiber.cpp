#include "fiber.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sys/mman.h>
#include <ucontext.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define BP_FIBER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BP_FIBER_ASAN 1
#endif
#endif
#ifdef BP_FIBER_ASAN
#include <sanitizer/common_interface_defs.h>
#endif

namespace app::cli {

namespace {
thread_local Fiber* t_current = nullptr;
thread_local Fiber* t_starting = nullptr;

long long nowMs()
{
    return std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::size_t pageSize()
{
    const long p = ::sysconf(_SC_PAGESIZE);
    return p > 0 ? static_cast<std::size_t>(p) : 4096;
}
} // namespace

struct Fiber::Context {
    ucontext_t fiber{};
    ucontext_t caller{};
    void* mapping = nullptr;     ///< guard page + stack
    std::size_t mappingBytes = 0;
    char* stackBottom = nullptr; ///< lowest usable address
    std::size_t stackBytes = 0;
    // AddressSanitizer's view of the stacks (unused without it).
    void* fakeStack = nullptr;
    const void* callerBottom = nullptr;
    std::size_t callerSize = 0;
};

Fiber::Fiber(std::function<void()> body) : m_body(std::move(body)), m_ctx(std::make_unique<Context>())
{
    const std::size_t guard = pageSize();
    m_ctx->mappingBytes = kStackBytes + guard;
    m_ctx->mapping = ::mmap(nullptr, m_ctx->mappingBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if (m_ctx->mapping == MAP_FAILED) {
        std::fputs("benchpilot: cannot map a fiber stack\n", stderr);
        std::abort();
    }
    ::mprotect(m_ctx->mapping, guard, PROT_NONE);  // stacks grow down: the guard sits below
    m_ctx->stackBottom = static_cast<char*>(m_ctx->mapping) + guard;
    m_ctx->stackBytes = kStackBytes;
}

Fiber::~Fiber()
{
    if (m_started && !m_finished) {
        // Its frames would never unwind (objects on it would leak or, worse, stay
        // connected to signals): a caller bug the server guards against.
        std::fputs("benchpilot: a fiber was destroyed before it finished; its stack is kept\n", stderr);
        return;
    }
    ::munmap(m_ctx->mapping, m_ctx->mappingBytes);
}

Fiber* Fiber::current() { return t_current; }

void Fiber::entry()
{
    Fiber* self = t_starting;
    t_starting = nullptr;
#ifdef BP_FIBER_ASAN
    __sanitizer_finish_switch_fiber(nullptr, &self->m_ctx->callerBottom, &self->m_ctx->callerSize);
#endif
    self->m_body();
    self->m_body = nullptr;  // captured objects go while the fiber still runs
    self->m_finished = true;
    self->switchOut();
    // Never resumed after finishing.
    std::abort();
}

void Fiber::switchOut()
{
    Context& c = *m_ctx;
#ifdef BP_FIBER_ASAN
    // A finished fiber's fake stack is released (nullptr); a waiting one keeps it.
    __sanitizer_start_switch_fiber(m_finished ? nullptr : &c.fakeStack, c.callerBottom, c.callerSize);
#endif
    t_current = nullptr;
    ::swapcontext(&c.fiber, &c.caller);
#ifdef BP_FIBER_ASAN
    __sanitizer_finish_switch_fiber(c.fakeStack, &c.callerBottom, &c.callerSize);
#endif
}

bool Fiber::resume()
{
    if (m_finished)
        return true;
    if (t_current) {
        std::fputs("benchpilot: a fiber resumed from another fiber\n", stderr);
        std::abort();
    }
    Context& c = *m_ctx;
    if (!m_started) {
        m_started = true;
        ::getcontext(&c.fiber);
        c.fiber.uc_stack.ss_sp = c.stackBottom;
        c.fiber.uc_stack.ss_size = c.stackBytes;
        c.fiber.uc_link = nullptr;
        ::makecontext(&c.fiber, &Fiber::entry, 0);
        t_starting = this;
    }
    m_waitDone = nullptr;
#ifdef BP_FIBER_ASAN
    void* callerFake = nullptr;
    __sanitizer_start_switch_fiber(&callerFake, c.stackBottom, c.stackBytes);
#endif
    t_current = this;
    ::swapcontext(&c.caller, &c.fiber);
    t_current = nullptr;
#ifdef BP_FIBER_ASAN
    __sanitizer_finish_switch_fiber(callerFake, nullptr, nullptr);
#endif
    return m_finished;
}

bool Fiber::ready() const
{
    if (m_finished)
        return false;
    if (!m_started || m_cancelled || !m_waitDone)
        return true;
    return nowMs() >= m_waitDeadlineMs || m_waitDone();
}

void Fiber::cancel() { m_cancelled = true; }

bool Fiber::waitUntil(const std::function<bool()>& done, int timeoutMs)
{
    if (done())
        return true;
    const long long deadline = nowMs() + (timeoutMs < 0 ? 0 : timeoutMs);
    while (!m_cancelled) {
        m_waitDone = done;
        m_waitDeadlineMs = deadline;
        switchOut();
        if (done())
            return true;
        if (nowMs() >= deadline)
            return false;
    }
    return done();
}

} // namespace app::cli
