#pragma once
// The host's side of a device path queue, as an interface a runner streams through: begin a
// path, append LINE/ARC segments as the queue has room (every answer says how much), hold,
// resume, clear, and hear when segments complete. An Instrument hands out its PathClient
// (Instrument::paths()). The BenchPilot backend's speaks PATH_* messages
// (device/backends/benchpilot/protocol_path_client.h); a GRBL backend implements the same
// calls with G1/G2/G3 lines, its planner-buffer count for the free slots and its status
// reports for the executing line.
#include "device/client/request_error.h"
#include "device/protocol/messages_path.h"
#include "motion/path/junction_planner.h"
#include "motion/path/path_geometry.h"

#include <QObject>
#include <QPointer>

#include <functional>
#include <optional>
#include <vector>

namespace dev {

/// The queue's state in host units, as the last answer reported it.
struct PathQueueState {
    dev::proto::PathState state = dev::proto::PathState::Idle;
    int capacity = 0;
    int freeSlots = 0;
    quint32 nextIndex = 0;         ///< the index the next append must start with
    quint32 executingIndex = 0;    ///< segment in progress; the ones before it are done
    double speedMmS = 0;
    int underruns = 0;
    dev::proto::PathReason reason = dev::proto::PathReason::None;
    double accelMmS2 = 0;
    double junctionDeviationMm = 0;
};
/// Terms for people (ui::words::term): "path.state.running", "path.reason.host_silent", …
const char* pathStateTerm(dev::proto::PathState s);
const char* pathReasonTerm(dev::proto::PathReason r);

class PathClient : public QObject {
    Q_OBJECT
public:
    using Reply = std::function<void(const std::optional<RequestError>&, const PathQueueState&)>;
    using Callback = std::function<void(const std::optional<RequestError>&)>;

    explicit PathClient(QObject* parent = nullptr) : QObject(parent) {}

    /// The instrument can run queued paths now (connected, and it has the capability).
    virtual bool available() const = 0;
    /// Most segments one append may carry.
    virtual int maxSegmentsPerAppend() const = 0;
    /// The device's path limits, for timing a path before it runs (from the last answer, or
    /// the device's defaults after refreshLimits()).
    virtual motion::path::PathLimits limits() const = 0;
    virtual void refreshLimits(Callback done = {}) = 0;

    /// Starts a new path whose first segment will carry `firstIndex`; it starts where the
    /// machine is now.
    virtual void begin(quint32 firstIndex, Reply done) = 0;
    /// Queues segments (each starts where the one before ends). `start`: run now; `last`: the
    /// path ends at rest after these.
    virtual void append(quint32 firstIndex, const std::vector<motion::path::Segment>& segments, bool start, bool last,
                        Reply done) = 0;
    virtual void queryStatus(Reply done) = 0;
    virtual void hold(Callback done = {}) = 0;     ///< realtime: slow down along the path, keep the queue
    virtual void resume(Callback done = {}) = 0;   ///< realtime
    virtual void clear(Callback done = {}) = 0;    ///< realtime: slow down, then forget the queue

signals:
    void started(quint32 index);
    void segmentDone(quint32 index);
    void underrun(quint32 afterIndex);
    void finished(quint32 lastIndex, quint64 deviceTimeUs);
    void held(quint32 index, const QString& why);
    void aborted(quint32 index, const QString& why);
    /// Device time of PATH_STARTED, for timing the run on the device's clock.
    void startedAt(quint64 deviceTimeUs);
};

} // namespace dev
