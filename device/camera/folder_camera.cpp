#include "device/camera/folder_camera.h"

#include "device/camera/command_camera.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>

namespace dev::camera {

FolderCamera::FolderCamera(const QString& folder, QObject* parent) : Camera(parent), m_folder(folder)
{
    m_look.setInterval(kLookEveryMs);
    connect(&m_look, &QTimer::timeout, this, &FolderCamera::look);
}

Capabilities FolderCamera::capabilities() const
{
    Capabilities c;
    c.needsTriggerOutput = true;
    return c;
}

void FolderCamera::open()
{
    if (!QFileInfo(m_folder).isDir()) {
        emit failed(0, motion::msg::Problem("", motion::msg::make("camera.folder.missing", {motion::msg::verbatim("folder", m_folder.toStdString())})));
        return;
    }
    m_open = true;
    emit opened();
}

void FolderCamera::close()
{
    m_look.stop();
    m_waiting = false;
    m_open = false;
    emit closed();
}

QHash<QString, qint64> FolderCamera::sizes() const
{
    QHash<QString, qint64> out;
    const auto entries = QDir(m_folder).entryInfoList(QDir::Files | QDir::NoDotAndDotDot);
    for (const QFileInfo& fi : entries)
        out.insert(fi.fileName(), fi.size());
    return out;
}

void FolderCamera::capture(const CaptureRequest& request)
{
    if (!QFileInfo(m_folder).isDir()) {
        emit failed(request.id, motion::msg::Problem("", motion::msg::make("camera.folder.missing", {motion::msg::verbatim("folder", m_folder.toStdString())})));
        return;
    }
    if (m_waiting) {
        emit failed(request.id, motion::msg::Problem("", motion::msg::make("camera.folder.busy", {motion::msg::verbatim("folder", m_folder.toStdString())})));
        return;
    }
    m_request = request;
    m_before = sizes();
    m_lastSeen.clear();
    m_startedMs = QDateTime::currentMSecsSinceEpoch();
    m_waiting = true;
    m_look.start();
}

void FolderCamera::look()
{
    if (!m_waiting)
        return;
    const QHash<QString, qint64> now = sizes();
    for (auto it = now.begin(); it != now.end(); ++it) {
        if (m_before.contains(it.key()) || it.key().endsWith(QLatin1String(".part")) || it.key().startsWith(QLatin1Char('.')))
            continue;  // there before, or still being written under a temporary name
        const auto seen = m_lastSeen.find(it.key());
        if (seen == m_lastSeen.end() || seen.value() != it.value() || it.value() == 0) {
            m_lastSeen.insert(it.key(), it.value());  // new or still growing: look again
            continue;
        }
        // Complete: the same size as one look ago.
        m_look.stop();
        m_waiting = false;
        Frame frame;
        motion::msg::Message error;
        if (!readImageFile(QDir(m_folder).filePath(it.key()), &frame, &error)) {
            emit failed(m_request.id, motion::msg::Problem("", error));
            return;
        }
        frame.exposureMs = m_exposureMs;
        frame.sequence = ++m_sequence;
        emit captured(m_request.id, frame);
        return;
    }
    if (QDateTime::currentMSecsSinceEpoch() - m_startedMs > static_cast<qint64>(m_timeoutS * 1000)) {
        m_look.stop();
        m_waiting = false;
        emit failed(m_request.id, motion::msg::Problem("", motion::msg::make("camera.folder.timeout", {motion::msg::verbatim("folder", m_folder.toStdString()),
                                                                                       motion::msg::real("seconds", m_timeoutS, motion::msg::Unit::S)})));
    }
}

} // namespace dev::camera
