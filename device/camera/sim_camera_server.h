#pragma once
// The simulated camera served on a local socket (benchpilot-sim --camera-socket PATH): what
// the objective sees at the simulated stage's TRUE work point, rendered as the in-process
// simulated camera renders it (sim_render.h), for the camera sim:PATH (sim_socket_camera.h)
// in another process. The format is sim_wire.h's.
//
// Threads: lives on the simulator's thread, where the work point is read when a capture
// request arrives (that is when its exposure starts); rendering runs on one worker thread in
// the order asked; a frame is sent no earlier than its exposure would have ended. The
// destructor waits for a render in flight.
//
// Bounds: at most kMaxClients connections and kMaxInFlight captures a connection (more is
// answered "busy"); a connection that sends something unreadable gets an error and is closed.
#include "device/camera/sim_camera.h"
#include "device/camera/sim_wire.h"

#include <QPointer>
#include <QString>
#include <QThreadPool>

#include <future>
#include <map>
#include <memory>

class QLocalServer;
class QLocalSocket;

namespace dev::camera {

class SimCameraServer : public QObject {
    Q_OBJECT
public:
    static constexpr int kMaxClients = 8;
    static constexpr int kMaxInFlight = 4;
    /// A local socket's path is at most this many bytes (sockaddr_un).
    static constexpr int kMaxPathBytes = 107;

    SimCameraServer(WorkPointSource workPoint, const SimCameraSettings& settings, QObject* parent = nullptr);
    ~SimCameraServer() override;

    /// Serves at `path`: refuses a path a live server answers on, or that is not a socket;
    /// replaces a socket left by one that died. false with camera.socket.* in `error`.
    bool listen(const QString& path, motion::msg::Message* error);
    /// Stops serving and removes the socket file.
    void close();
    QString path() const { return m_path; }
    bool isListening() const { return m_server != nullptr; }
    int clientCount() const { return static_cast<int>(m_clients.size()); }

private:
    struct Client {
        QLocalSocket* socket = nullptr;
        SimWireReader reader{SimWireReader::Side::Server};
        int inFlight = 0;
    };

    void accept();
    void read(QLocalSocket* socket);
    void drop(QLocalSocket* socket);
    void render(QLocalSocket* socket, const SimWireCapture& capture, const WorkPoint& at);
    void send(QLocalSocket* socket, const std::string& bytes, bool answersCapture);

    WorkPointSource m_workPoint;
    SimCameraSettings m_settings;
    std::shared_future<std::shared_ptr<const Specimen>> m_specimen;
    QThreadPool m_pool;  ///< one thread: renders in the order asked
    QLocalServer* m_server = nullptr;
    QString m_path;
    std::map<QLocalSocket*, std::unique_ptr<Client>> m_clients;
    std::uint64_t m_sequence = 0;
};

} // namespace dev::camera
