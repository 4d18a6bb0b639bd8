#pragma once
// sim:PATH — the simulated camera benchpilot-sim serves on a local socket (--camera-socket
// PATH, sim_camera_server.h). Only that process knows the simulated stage's TRUE work point,
// so a stage driven over benchpilot-sim's pty gets images in which the stage's errors show.
//
// open() connects and waits for the server's hello; captures asked meanwhile wait and are
// sent when it comes. A capture is one request on the socket, sent when capture() is called,
// so its exposure starts after the call. The live view asks for one frame at a time and for
// the next only once that one has come: a slow reader drops frames, nothing queues.
//
// Failures, each naming the socket: no server there (camera.socket.no_server); no hello or no
// answer in time (camera.socket.timeout); the server gone (camera.socket.lost: every capture
// waiting fails, and every later one until the camera is opened again); an answer that cannot
// be read (camera.socket.garbled, with the reader's reason; the connection is dropped); an
// error the server sent (camera.socket.server_error).
//
// Threads: one thread, the object's; the socket is read as data arrives (no blocking call).
#include "device/camera/camera.h"
#include "device/camera/sim_wire.h"

#include <QElapsedTimer>
#include <QPointer>
#include <QTimer>

#include <map>
#include <vector>

class QLocalSocket;

namespace dev::camera {

class SimSocketCamera : public Camera {
    Q_OBJECT
public:
    explicit SimSocketCamera(const QString& path, QObject* parent = nullptr);
    ~SimSocketCamera() override;

    QString source() const override { return QStringLiteral("sim:") + m_path; }
    Capabilities capabilities() const override;
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    void startLive() override;
    void stopLive() override;
    void setExposureMs(double ms) override;
    double exposureMs() const override { return m_exposureMs; }
    void capture(const CaptureRequest& request) override;

    /// Longest wait for the server's hello, and for an answer beyond its exposure.
    void setTimeoutsMs(int helloMs, int answerGraceMs);
    /// What the server said it shows; meaningful once opened().
    const SimWireHello& hello() const { return m_hello; }

private:
    /// Drops the socket and every capture asked, each failed with `why` (and request 0
    /// first when `toRequestZero`: the live view and whoever opened).
    void dropAll(const motion::msg::Message& why, bool toRequestZero);
    struct Asked {
        std::uint64_t requestId = 0;
        bool live = false;
        qint64 deadlineMs = 0;   ///< on m_clock
        qint64 waitMs = 0;       ///< the exposure and the grace it was given
        std::int64_t sentHostUs = 0;
    };

    void connectNow();
    void send(std::uint64_t requestId, bool live, const std::optional<CameraGeometry>& geometry);
    void readAnswers();
    void onFrame(SimWireFrame&& frame);
    void onServerError(const SimWireError& error);
    /// A capture asked that will not be answered: its requester hears `why` (the live
    /// view on request 0, and it stops).
    void failAsked(const Asked& a, const motion::msg::Message& why);
    /// The link is unusable: every waiting capture fails with `why`, and so does every later one.
    void goDead(const motion::msg::Message& why);
    void armDeadline();
    void onDeadline();
    void scheduleLive();
    motion::msg::Message socketMessage(const char* id) const;

    QString m_path;
    QPointer<QLocalSocket> m_socket;
    SimWireReader m_reader{SimWireReader::Side::Client};
    bool m_open = false;
    bool m_opening = false;
    bool m_live = false;
    bool m_liveInFlight = false;
    double m_exposureMs = 10;
    int m_helloTimeoutMs;
    int m_answerGraceMs;
    std::map<std::uint64_t, Asked> m_asked;      ///< by wire id
    std::vector<CaptureRequest> m_waiting;        ///< asked before the hello came
    std::optional<motion::msg::Message> m_dead;   ///< why the link broke, until opened again
    std::uint64_t m_nextWireId = 1;
    std::uint64_t m_sequence = 0;
    SimWireHello m_hello;
    QElapsedTimer m_clock;
    QTimer m_deadline;
    QTimer m_liveTimer;
};

} // namespace dev::camera
