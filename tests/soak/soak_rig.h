#pragma once
// The soak's bench (docs/testing.md, "Soak"): both simulated instruments in this
// process, each a BenchPilotClient on an unpaced loopback to the reference firmware
// with its clock sped up, as the GUI's in-process simulators are composed in app/;
// the TelemetryHub every screen shares; and a live-plot consumer that asks for what the
// Plots screen asks for and reads the stores on its frame timer the way its plots do.
#include "device/backends/benchpilot/benchpilot_client.h"
#include "device/link/simulated_link.h"
#include "device/telemetry/telemetry_hub.h"

#include <QObject>
#include <QTimer>

#include <functional>
#include <string>
#include <vector>

namespace soak {

/// What went wrong on one instrument's link (a clean in-process link should show none).
struct LinkTrouble {
    quint64 linkErrorSignals = 0;  ///< Instrument::linkError
    quint64 refusals = 0;          ///< Instrument::requestFailed
    quint64 jogExpired = 0;        ///< JogExpired events: a jog refresh came too late
    quint64 linkDrops = 0;         ///< times the link left Ready
    std::vector<std::string> firstMessages;  ///< the first few, as message ids with arguments
};

/// One instrument: the firmware on the device end, the client on the host end.
class Station : public QObject {
    Q_OBJECT
public:
    Station(dev::proto::DeviceKind kind, double timeScale);
    ~Station() override;

    /// Connects and homes every axis; false (with why) if it cannot.
    bool connectAndHome(int timeoutMs, std::string* why);
    /// Virtual seconds on the firmware's clock.
    double deviceTimeS() { return link.machine().timeS(); }
    int axis(char letter) const { return client.identity().axisIndex(QChar::fromLatin1(letter)); }

    dev::SimulatedLink link;
    dev::BenchPilotClient client;
    LinkTrouble trouble;
    const char* name;

private:
    void note(const std::string& what);
};

/// Runs `then(ok)` once a fresh status reading shows every axis at rest (asked for
/// directly, not waited for on the 50 ms poll, which is seconds of device time here).
void whenStill(dev::Instrument* client, QObject* context, std::function<void(bool)> then, int triesLeft = 5000);

/// A live plot without the widget: the Plots screen's consumer of the hub (every channel of
/// both instruments, one wish), redrawn at most every 16 ms after data arrive, each redraw
/// asking the stores of the channels on show for min/max per pixel column over the window,
/// as PlotPanel does. On show: kShownChannels at a time (three plots of two traces), moving
/// on by that many each frame so every store is read every few frames. Drawing all 35 every
/// frame was most of the soak's CPU (ChannelStore::lowerBound per column) and is more than
/// any screen asks for.
class PlotConsumer : public QObject {
    Q_OBJECT
public:
    static constexpr int kFrameMs = 16;   ///< the Plots screen's frame interval
    static constexpr int kColumns = 1200; ///< a wide plot's pixel columns
    static constexpr int kShownChannels = 6;

    PlotConsumer(dev::tele::TelemetryHub& hub, int rateHz);
    /// Says what it wants (once both instruments are identified).
    void want();
    quint64 frames() const { return m_frames; }
    quint64 emptyReads() const { return m_emptyReads; }  ///< a wanted channel with no store to read
    std::size_t channels() const { return m_keys.size(); }
    /// Heap bytes the hub's stores of the wanted channels hold now.
    std::size_t storeBytes() const;

private:
    void redraw();

    dev::tele::TelemetryHub& m_hub;
    int m_rateHz;
    QVector<dev::tele::ChannelKey> m_keys;
    QTimer m_frame;
    std::vector<dev::tele::MinMax> m_columns;
    quint64 m_frames = 0, m_emptyReads = 0;
    int m_firstShown = 0;
};

} // namespace soak
