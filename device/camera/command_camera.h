#pragma once
// command:CMD — the operator's own capture program (gphoto2, fswebcam, libcamera-still …),
// run once per image WITHOUT a shell: the command line is split into words (quotes group
// words, as a shell would, but nothing is expanded), {file} {tile} {x_mm} {y_mm} are filled
// in, and the file it wrote is read (TIFF 8/16-bit through libtiff, anything else through
// QImage) and removed. A non-zero exit, a timeout or no file fails the capture with the
// program's own stderr in the message.
#include "device/camera/camera.h"

#include <QPointer>
#include <QProcess>

namespace dev::camera {

/// Reads an image file into a Frame: TIFF by libtiff (keeps 16 bits), others by QImage.
bool readImageFile(const QString& path, Frame* frame, motion::msg::Message* error);

class CommandCamera : public Camera {
    Q_OBJECT
public:
    explicit CommandCamera(const QString& commandLine, QObject* parent = nullptr);
    ~CommandCamera() override;

    QString source() const override { return QStringLiteral("command:") + m_command; }
    Capabilities capabilities() const override { return {}; }
    void open() override;
    void close() override;
    bool isOpen() const override { return m_open; }
    void setExposureMs(double ms) override { m_exposureMs = ms; }
    double exposureMs() const override { return m_exposureMs; }
    void capture(const CaptureRequest& request) override;

    /// Longest a capture may take before the program is killed.
    void setTimeoutS(double s) { m_timeoutS = s; }

private:
    void finish(int exitCode, QProcess::ExitStatus status);
    void fail(const motion::msg::Message& m);

    QString m_command;
    bool m_open = false;
    double m_exposureMs = 0;
    double m_timeoutS = 60;
    QPointer<QProcess> m_process;
    CaptureRequest m_request;
    QString m_file;
    bool m_timedOut = false;
    std::uint64_t m_sequence = 0;
};

} // namespace dev::camera
