#pragma once
// A GrblClient connected to the simulator's GRBL personality in-process (an unpaced loopback
// pair), with what a test needs to watch it: events, refusals, notes, link errors, and helpers
// that wait on the real event loop. The simulator's clock follows the wall clock times a scale.
#include "device/backends/grbl/client/grbl_client.h"
#include "device/link/simulated_link.h"
#include "device/sim/grbl_firmware.h"
#include "device/sim/machine_config.h"
#include "motion/message_print.h"
#include "wait.h"

#include <gtest/gtest.h>

#include <memory>
#include <optional>
#include <vector>

namespace itest {

struct GrblSessionOptions {
    dev::proto::DeviceKind kind = dev::proto::DeviceKind::Stage;
    bool grblHal = false;
    std::optional<dev::files::MachineProfile> profile;  ///< the default wiring when empty
    qint32 baud = 0;                               ///< 0: unpaced
};

class GrblSession {
public:
    explicit GrblSession(const GrblSessionOptions& o = {})
        : link(std::make_unique<dev::sim::GrblFirmware>(o.kind == dev::proto::DeviceKind::Stage ? dev::sim::stageConfig() : dev::sim::analyzerConfig(),
                                                    o.grblHal ? dev::sim::GrblFirmware::Dialect::GrblHal : dev::sim::GrblFirmware::Dialect::Grbl),
               o.baud),
          client(o.profile ? *o.profile : dev::files::defaultProfile(o.kind), !o.profile.has_value())
    {
        QObject::connect(&client, &dev::Instrument::eventReceived, &client, [this](const dev::DeviceEvent& e) { events.push_back(e); });
        QObject::connect(&client, &dev::Instrument::linkError, &client, [this](const motion::msg::Message& m) {
            linkMessages.push_back(m);
            linkErrors << QString::fromStdString(motion::msg::debugString(m));
        });
        QObject::connect(&client, &dev::Instrument::requestFailed, &client, [this](const dev::RequestError& e) { failures.push_back(e); });
        QObject::connect(&client, &dev::Instrument::noted, &client, [this](const motion::msg::Message& m) { notes.push_back(m); });
        QObject::connect(&client, &dev::Instrument::statusChanged, &client, [this] { ++statusCount; });
        client.setTransport(link.hostEnd());
    }
    ~GrblSession() { client.setTransport(nullptr); }

    dev::sim::GrblFirmware& firmware() { return static_cast<dev::sim::GrblFirmware&>(link.host().device()); }
    double simTimeS() { return firmware().machine().timeS(); }

    bool connect(int timeoutMs = 8000)
    {
        client.connectLink();
        waitFor([this] { return client.state() == dev::LinkState::Ready || client.state() == dev::LinkState::Disconnected; }, timeoutMs);
        return client.state() == dev::LinkState::Ready;
    }

    int axis(char letter) const { return client.identity().axisIndex(QChar::fromLatin1(letter)); }
    const dev::AxisReadout& readout(char letter) const { return client.status().axes[axis(letter)]; }

    std::optional<dev::RequestError> call(const std::function<void(dev::Instrument::Callback)>& send, int timeoutMs = 8000)
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
            return e;
        }
        return result;
    }

    /// Two fresh status reports with nothing moving.
    bool waitStill(int timeoutMs = 15000)
    {
        const int from = statusCount;
        return waitFor([this, from] { return client.isReady() && statusCount >= from + 2 && !client.status().anyMoving(); }, timeoutMs);
    }

    int findEvent(dev::proto::EventKind kind, int axisIndex = -2, std::size_t from = 0) const
    {
        for (std::size_t i = from; i < events.size(); ++i)
            if (events[i].kind == kind && (axisIndex < -1 || events[i].axis == axisIndex))
                return static_cast<int>(i);
        return -1;
    }
    bool waitEvent(dev::proto::EventKind kind, int axisIndex = -2, std::size_t from = 0, int timeoutMs = 10000)
    {
        return waitFor([&] { return findEvent(kind, axisIndex, from) >= 0; }, timeoutMs);
    }

    /// $H with the simulator's clock sped up, then the clock back at real time.
    bool homeAll(double timeScale = 20)
    {
        link.host().setTimeScale(timeScale);
        const std::size_t from = events.size();
        const auto err = call([this](auto cb) { client.home(0, cb); });
        if (err) {
            ADD_FAILURE() << "home refused: " << motion::msg::debugString(err->message);
            link.host().setTimeScale(1);
            return false;
        }
        const bool ok = waitEvent(dev::proto::EventKind::HomeDone, -2, from, 30000);
        link.host().setTimeScale(1);
        return ok && waitStill();
    }

    dev::SimulatedLink link;
    dev::GrblClient client;
    std::vector<dev::DeviceEvent> events;
    std::vector<motion::msg::Message> linkMessages;  ///< every linkError, in order
    QStringList linkErrors;                  ///< the same as debug strings, for failure output
    std::vector<dev::RequestError> failures;
    std::vector<motion::msg::Message> notes;
    int statusCount = 0;
};

} // namespace itest
