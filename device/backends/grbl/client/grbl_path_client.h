#pragma once
// The GRBL backend's path queue: the segments of a pattern streamed as G1 lines and G2/G3 arcs
// (centre form) through the client's character-counting streamer. GRBL keeps no segment
// numbers, so the host keeps a window of the segments it sent and tells from each status report
// which one the machine is on (GRBL follows the G-code geometry exactly, its arcs within $12):
// segmentDone and finished come at the poll rate, which is also the rate the contour error is
// sampled at (docs/grbl.md). Hold and resume are GRBL's feed hold and cycle start; clear is a
// feed hold and, at rest, a soft reset that forgets every queued line and keeps the position.
// An error:N on a segment stops the job (the rest is flushed) and names the line.
#include "device/client/path_client.h"

#include <QPointer>

#include <map>

namespace dev {

class GrblClient;

class GrblPathClient : public PathClient {
    Q_OBJECT
public:
    /// Segments sent and not yet completed, at most: the host's window onto GRBL's queue (its
    /// planner and receive buffer hold fewer; the rest wait in the streamer).
    static constexpr int kCapacity = 64;
    /// A reported position this close to a segment is on it (GRBL's arc chords deviate by $12,
    /// 0.002 mm by default; reports carry 0.001 mm).
    static constexpr double kOnSegmentMm = 0.02;

    GrblPathClient(GrblClient* client, QObject* parent = nullptr);

    bool available() const override;
    int maxSegmentsPerAppend() const override { return 16; }
    motion::path::PathLimits limits() const override;
    void refreshLimits(Callback done = {}) override;
    void begin(quint32 firstIndex, Reply done) override;
    void append(quint32 firstIndex, const std::vector<motion::path::Segment>& segments, bool start, bool last, Reply done) override;
    void queryStatus(Reply done) override;
    void hold(Callback done = {}) override;
    void resume(Callback done = {}) override;
    void clear(Callback done = {}) override;

private:
    bool active() const;
    PathQueueState snapshot() const;
    void onReport(quint64 askedUs);
    void onReset(bool expected);
    void onAlarm(int code);
    /// Why is the reason (snapshot().reason, a path.reason.* term); `controllerSaid` what the
    /// controller sent, where it caused the abort ("ALARM:1", "error:15"), carried by aborted().
    void abortWith(dev::proto::PathReason reason, const QString& controllerSaid = {});
    void advanceTo(quint32 index);

    QPointer<GrblClient> m_client;
    dev::proto::PathState m_state = dev::proto::PathState::Idle;
    dev::proto::PathReason m_reason = dev::proto::PathReason::None;
    std::map<quint32, motion::path::Segment> m_segments;  ///< sent, not yet completed
    quint32 m_first = 0, m_next = 0, m_executing = 0;
    bool m_haveLast = false;
    quint32 m_lastIndex = 0;
    int m_linesOpen = 0;            ///< path lines not yet acknowledged
    quint64 m_lastAckUs = 0;
    bool m_started = false;
    bool m_underrunSaid = false;
    bool m_holdAsked = false, m_clearAsked = false;
    double m_speedMmS = 0;
};

} // namespace dev
