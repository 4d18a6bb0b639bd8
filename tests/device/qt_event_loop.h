#pragma once
// test_device is plain C++ but for the telemetry hub's tests: they make the Qt
// application object on first use and wait on a real event loop.
#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

#include <functional>

namespace devtest {

inline void ensureApp()
{
    if (QCoreApplication::instance())
        return;
    static int argc = 1;
    static char name[] = "test_device";
    static char* argv[] = {name, nullptr};
    static QCoreApplication* app = new QCoreApplication(argc, argv);
    (void)app;
}

/// Runs the event loop until `done` holds or `timeoutMs` pass; whether it holds.
inline bool waitFor(const std::function<bool()>& done, int timeoutMs = 5000)
{
    if (done())
        return true;
    QEventLoop loop;
    QTimer poll, limit;
    QObject::connect(&poll, &QTimer::timeout, &loop, [&] {
        if (done())
            loop.quit();
    });
    QObject::connect(&limit, &QTimer::timeout, &loop, &QEventLoop::quit);
    poll.start(1);
    limit.setSingleShot(true);
    limit.start(timeoutMs);
    loop.exec();
    return done();
}

} // namespace devtest
