#pragma once
// Waiting in integration tests: runs the real event loop (timers, transports,
// the in-process simulator) until a condition holds. Timeouts are generous
// upper bounds for a loaded machine, never measurements.
#include <QEventLoop>
#include <QTimer>

#include <functional>

namespace itest {

/// Runs the event loop until `done()` is true or `timeoutMs` pass; returns `done()`.
inline bool waitFor(const std::function<bool()>& done, int timeoutMs)
{
    if (done())
        return true;
    QEventLoop loop;
    QTimer poll;
    poll.setInterval(2);
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    QTimer limit;
    limit.setSingleShot(true);
    QObject::connect(&limit, &QTimer::timeout, &loop, &QEventLoop::quit);
    poll.start();
    limit.start(timeoutMs);
    loop.exec();
    return done();
}

/// Lets the event loop run for `ms` (the simulator keeps moving meanwhile).
inline void spin(int ms)
{
    waitFor([] { return false; }, ms);
}

} // namespace itest
