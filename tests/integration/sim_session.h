#pragma once
// An BenchPilotClient connected to the in-process simulator over a loopback
// pair, with what a test needs to watch it: every event, link error and
// refusal the client reported, and helpers that wait on the real event loop.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/simulated_link.h"
#include "motion/message_print.h"
#include "tap_transport.h"
#include "wait.h"

#include <gtest/gtest.h>

#include <optional>
#include <vector>

namespace itest {

/// The loopback emulates a real UART at this rate unless a test says otherwise.
constexpr qint32 kLinkBaud = 115200;
/// No pacing: bytes arrive on the next event-loop turn. A sped-up simulator's wire
/// is sped up with it (LoopbackPair::setTimeScale), so pacing stays right either way;
/// unpaced is for tests that judge the device, not the wire.
constexpr qint32 kUnpaced = 0;

class SimSession {
public:
    explicit SimSession(dev::proto::DeviceKind kind, qint32 baud = kLinkBaud)
        : link(kind, baud), tap(link.hostEnd())
    {
        watch();
    }
    /// A simulator of this machine (a stage with errors of the test's own).
    SimSession(const dev::sim::MachineConfig& config, qint32 baud) : link(config, baud), tap(link.hostEnd()) { watch(); }
    ~SimSession() { client.setTransport(nullptr); }

private:
    void watch()
    {
        QObject::connect(&client, &dev::BenchPilotClient::eventReceived, &client,
                         [this](const dev::DeviceEvent& e) { events.push_back(e); });
        QObject::connect(&client, &dev::BenchPilotClient::linkError, &client,
                         [this](const motion::msg::Message& m) {
                             linkMessages.push_back(m);
                             linkErrors << QString::fromStdString(motion::msg::debugString(m));
                         });
        QObject::connect(&client, &dev::BenchPilotClient::requestFailed, &client,
                         [this](const dev::RequestError& e) { failures.push_back(e); });
        QObject::connect(&client, &dev::BenchPilotClient::statusChanged, &client, [this] { ++statusCount; });
        client.setTransport(&tap);
    }

public:
    /// connectLink() and wait until Ready (or anything final).
    bool connect(int timeoutMs = 5000)
    {
        client.connectLink();
        waitFor([this] { return client.state() == dev::LinkState::Ready || client.state() == dev::LinkState::Disconnected; },
                timeoutMs);
        return client.state() == dev::LinkState::Ready;
    }

    int axis(char letter) const { return client.identity().axisIndex(QChar::fromLatin1(letter)); }
    const dev::AxisReadout& readout(char letter) const { return client.status().axes[axis(letter)]; }

    /// Sends one request through `send` and waits for its answer; nullopt means accepted.
    /// A request the client never answers is a test failure (and reported as a Timeout).
    std::optional<dev::RequestError> call(const std::function<void(dev::BenchPilotClient::Callback)>& send,
                                          int timeoutMs = 5000)
    {
        bool done = false;
        std::optional<dev::RequestError> result;
        send([&done, &result](const std::optional<dev::RequestError>& e) {
            result = e;
            done = true;
        });
        if (!waitFor([&done] { return done; }, timeoutMs)) {
            ADD_FAILURE() << "the client never completed the request";
            dev::RequestError e;
            e.kind = dev::RequestError::Kind::Timeout;
            e.message = motion::msg::make("request.no_reply", {motion::msg::verbatim("request", "the test's request"), motion::msg::integer("attempts", 1),
                                                       motion::msg::real("seconds", timeoutMs / 1000.0, motion::msg::Unit::S)});
            return e;
        }
        return result;
    }

    /// Waits for two status polls newer than now that show no axis moving.
    bool waitStill(int timeoutMs = 15000)
    {
        const int from = statusCount;
        return waitFor(
            [this, from] {
                return client.state() == dev::LinkState::Ready && statusCount >= from + 2 && !client.status().anyMoving();
            },
            timeoutMs);
    }

    /// Matches events of any axis in findEvent() and friends (−1 is the whole instrument).
    static constexpr int kAnyAxis = -2;

    /// Index in `events` of the first event of `kind` on `axisIndex` at or after `from`; −1 if none.
    int findEvent(dev::proto::EventKind kind, int axisIndex, std::size_t from = 0) const
    {
        for (std::size_t i = from; i < events.size(); ++i)
            if (events[i].kind == kind && (axisIndex < -1 || events[i].axis == axisIndex))
                return static_cast<int>(i);
        return -1;
    }
    bool waitEvent(dev::proto::EventKind kind, int axisIndex, std::size_t from = 0, int timeoutMs = 10000)
    {
        return waitFor([&] { return findEvent(kind, axisIndex, from) >= 0; }, timeoutMs);
    }
    int countEvents(dev::proto::EventKind kind, int axisIndex, std::size_t from = 0) const
    {
        int n = 0;
        for (std::size_t i = from; i < events.size(); ++i)
            if (events[i].kind == kind && (axisIndex < -1 || events[i].axis == axisIndex))
                ++n;
        return n;
    }

    /// Homes every axis with the simulator's clock sped up (homing covers the whole
    /// travel at search speed), then gives the clock back at real time.
    bool homeAll(double timeScale = 20)
    {
        link.host().setTimeScale(timeScale);
        const auto err = call([this](auto cb) { client.home(0, cb); });
        if (err) {
            ADD_FAILURE() << "home refused: " << motion::msg::debugString(err->message);
            link.host().setTimeScale(1);
            return false;
        }
        const bool ok = waitFor(
            [this] {
                if (client.state() != dev::LinkState::Ready)
                    return true;
                for (const auto& a : client.status().axes)
                    if (!a.homed || a.moving)
                        return false;
                return true;
            },
            20000);
        link.host().setTimeScale(1);
        return ok && client.state() == dev::LinkState::Ready && waitStill();
    }

    dev::SimulatedLink link;
    TapTransport tap;
    dev::BenchPilotClient client;
    std::vector<dev::DeviceEvent> events;
    std::vector<motion::msg::Message> linkMessages;  ///< every linkError, in order
    QStringList linkErrors;                  ///< the same as debug strings, for failure output
    std::vector<dev::RequestError> failures;
    int statusCount = 0;
};

} // namespace itest
