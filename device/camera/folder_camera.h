#pragma once
// folder:DIR — a camera's own software (the vendor's program, Micro-Manager) saves an image
// each time the stage's trigger output fires it; BenchPilot takes the next COMPLETE new file
// in DIR: one that was not there when the capture began, whose size has stood still for
// two looks kKeptStillMs apart (a file renamed into place is complete at once, and passes
// the same test). The scan runner pulses the trigger output where the stage has one
// (capabilities().needsTriggerOutput); no file within the timeout fails the capture naming
// the folder.
#include "device/camera/camera.h"

#include <QHash>
#include <QTimer>

namespace dev::camera {

class FolderCamera : public Camera {
    Q_OBJECT
public:
    static constexpr int kLookEveryMs = 50;

    explicit FolderCamera(const QString& folder, QObject* parent = nullptr);

    QString source() const override { return QStringLiteral("folder:") + m_folder; }
    Capabilities capabilities() const override;
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    void setExposureMs(double ms) override { m_exposureMs = ms; }
    double exposureMs() const override { return m_exposureMs; }
    void capture(const CaptureRequest& request) override;

    void setTimeoutS(double s) { m_timeoutS = s; }

private:
    void look();
    QHash<QString, qint64> sizes() const;

    QString m_folder;
    bool m_open = false;
    double m_exposureMs = 0;
    double m_timeoutS = 30;
    QTimer m_look;
    bool m_waiting = false;
    CaptureRequest m_request;
    QHash<QString, qint64> m_before;   ///< files there when the capture began
    QHash<QString, qint64> m_lastSeen; ///< new files' sizes at the last look
    qint64 m_startedMs = 0;
    std::uint64_t m_sequence = 0;
};

} // namespace dev::camera
