// benchpilot-cli's own InvocationHost: each command opens a link of its own (the
// in-process simulator, benchpilot-sim's pty or a serial port), and SIGINT/SIGTERM
// interrupt it on the event loop (a recipe run aborts cleanly: the tip rises, the log
// can resume).
#include "cli_session.h"
#include "command.h"

#include <QSocketNotifier>

#include <csignal>
#include <sys/socket.h>
#include <unistd.h>

namespace app::cli {
namespace {

int g_signalPipe[2] = {-1, -1};
void onSignal(int)
{
    const char c = 1;
    [[maybe_unused]] const auto n = ::write(g_signalPipe[1], &c, 1);
}

/// SIGINT / SIGTERM call `interrupt` on the event loop while alive.
class SignalInterrupt {
public:
    explicit SignalInterrupt(std::function<void()> interrupt)
    {
        if (::socketpair(AF_UNIX, SOCK_STREAM, 0, g_signalPipe) != 0)
            return;
        m_notifier = std::make_unique<QSocketNotifier>(g_signalPipe[0], QSocketNotifier::Read);
        QObject::connect(m_notifier.get(), &QSocketNotifier::activated, m_notifier.get(), [interrupt] {
            char c;
            [[maybe_unused]] const auto n = ::read(g_signalPipe[0], &c, 1);
            interrupt();
        });
        m_oldInt = std::signal(SIGINT, onSignal);
        m_oldTerm = std::signal(SIGTERM, onSignal);
    }
    ~SignalInterrupt()
    {
        if (!m_notifier)
            return;
        std::signal(SIGINT, m_oldInt);
        std::signal(SIGTERM, m_oldTerm);
        m_notifier.reset();
        ::close(g_signalPipe[0]);
        ::close(g_signalPipe[1]);
        g_signalPipe[0] = g_signalPipe[1] = -1;
    }
    SignalInterrupt(const SignalInterrupt&) = delete;
    SignalInterrupt& operator=(const SignalInterrupt&) = delete;

private:
    std::unique_ptr<QSocketNotifier> m_notifier;
    void (*m_oldInt)(int) = SIG_DFL;
    void (*m_oldTerm)(int) = SIG_DFL;
};

class LocalHost final : public InvocationHost {
public:
    std::unique_ptr<CliSession> openSession(Invocation& inv) override
    {
        LinkOptions o = inv.link();  // runCli has refused --sim with --port
        if (o.sim.isEmpty() && o.port.isEmpty())
            o.sim = QStringLiteral("analyzer");
        auto session = std::make_unique<CliSession>(inv, o);
        if (!session->connectDevice())
            return nullptr;
        return session;
    }
    std::shared_ptr<void> onInterrupt(std::function<void()> interrupt) override
    {
        return std::make_shared<SignalInterrupt>(std::move(interrupt));
    }
};

} // namespace

std::unique_ptr<InvocationHost> makeLocalHost() { return std::make_unique<LocalHost>(); }

} // namespace app::cli
