#include "device/camera/command_camera.h"

#include "device/camera/tile_tiff.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QTimer>

#include <chrono>
#include <cstring>

namespace dev::camera {

namespace {
/// What of the program's stderr goes into a message: its end says what went wrong.
constexpr int kCommandStderrChars = 600;

std::string tail(const QByteArray& bytes)
{
    const QString s = QString::fromLocal8Bit(bytes).trimmed();
    return (s.size() > kCommandStderrChars ? QStringLiteral("…") + s.right(kCommandStderrChars) : s).toStdString();
}
} // namespace

bool readImageFile(const QString& path, Frame* frame, motion::msg::Message* error)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) {
        *error = motion::msg::make("camera.tiff.cannot_read", {motion::msg::verbatim("file", path.toStdString()), motion::msg::verbatim("detail", f.errorString().toStdString())});
        return false;
    }
    const QByteArray magic = f.read(4);
    f.close();
    if (magic.startsWith("II*") || magic.startsWith("MM\0*"))
        return readTiff(path.toStdString(), frame, nullptr, error);
    QImage img(path);
    if (img.isNull()) {
        *error = motion::msg::make("camera.tiff.cannot_read", {motion::msg::verbatim("file", path.toStdString()), motion::msg::verbatim("detail", "not an image Qt can read")});
        return false;
    }
    Frame out;
    out.width = img.width();
    out.height = img.height();
    if (img.format() == QImage::Format_Grayscale16) {
        out.format = PixelFormat::Grey16;
        out.bitDepth = 16;
        out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * 2);
        for (int y = 0; y < out.height; ++y)
            std::memcpy(out.pixels.data() + static_cast<std::size_t>(y) * out.width * 2, img.constScanLine(y), static_cast<std::size_t>(out.width) * 2);
    } else if (img.isGrayscale()) {
        img = img.convertToFormat(QImage::Format_Grayscale8);
        out.format = PixelFormat::Grey8;
        out.bitDepth = 8;
        out.pixels.resize(static_cast<std::size_t>(out.width) * out.height);
        for (int y = 0; y < out.height; ++y)
            std::memcpy(out.pixels.data() + static_cast<std::size_t>(y) * out.width, img.constScanLine(y), static_cast<std::size_t>(out.width));
    } else {
        img = img.convertToFormat(QImage::Format_RGB888);
        out.format = PixelFormat::Rgb8;
        out.bitDepth = 8;
        out.pixels.resize(static_cast<std::size_t>(out.width) * out.height * 3);
        for (int y = 0; y < out.height; ++y)
            std::memcpy(out.pixels.data() + static_cast<std::size_t>(y) * out.width * 3, img.constScanLine(y), static_cast<std::size_t>(out.width) * 3);
    }
    *frame = std::move(out);
    return true;
}

CommandCamera::CommandCamera(const QString& commandLine, QObject* parent) : Camera(parent), m_command(commandLine) {}

CommandCamera::~CommandCamera()
{
    if (m_process) {
        m_process->disconnect(this);
        m_process->kill();
        m_process->waitForFinished(1000);
    }
}

void CommandCamera::open()
{
    m_open = true;
    emit opened();
}

void CommandCamera::close()
{
    m_open = false;
    emit closed();
}

void CommandCamera::capture(const CaptureRequest& request)
{
    if (m_process) {
        emit failed(request.id, motion::msg::Problem("", motion::msg::make("camera.command.busy", {motion::msg::verbatim("command", m_command.toStdString())})));
        return;
    }
    QStringList words = QProcess::splitCommand(m_command);
    if (words.isEmpty()) {
        emit failed(request.id, motion::msg::Problem("", motion::msg::make("camera.source.needs_argument", {motion::msg::verbatim("source", source().toStdString()),
                                                                                             motion::msg::verbatim("kind", "command")})));
        return;
    }
    // The program writes beside the tile, under a name of its own: the tile's file is
    // BenchPilot's TIFF, written whole or not at all.
    const QFileInfo hint(QString::fromStdString(request.fileHint.empty() ? (QDir::tempPath() + QStringLiteral("/benchpilot-snap.tif")).toStdString()
                                                                         : request.fileHint));
    m_file = hint.dir().filePath(hint.completeBaseName() + QStringLiteral(".capture.") + (hint.suffix().isEmpty() ? QStringLiteral("img") : hint.suffix()));
    QFile::remove(m_file);
    for (QString& w : words) {
        w.replace(QLatin1String("{file}"), m_file);
        w.replace(QLatin1String("{tile}"), QString::number(request.tile));
        w.replace(QLatin1String("{x_mm}"), QString::number(request.xMm, 'f', 4));
        w.replace(QLatin1String("{y_mm}"), QString::number(request.yMm, 'f', 4));
    }
    m_request = request;
    m_timedOut = false;
    auto* p = new QProcess(this);
    m_process = p;
    p->setProgram(words.takeFirst());
    p->setArguments(words);
    connect(p, &QProcess::finished, this, &CommandCamera::finish);
    connect(p, &QProcess::errorOccurred, this, [this, p](QProcess::ProcessError e) {
        if (e != QProcess::FailedToStart || m_process != p)
            return;
        m_process = nullptr;
        p->deleteLater();
        fail(motion::msg::make("camera.command.cannot_start", {motion::msg::verbatim("command", m_command.toStdString()), motion::msg::verbatim("detail", p->errorString().toStdString())}));
    });
    QTimer::singleShot(static_cast<int>(m_timeoutS * 1000), p, [this, p] {
        if (m_process != p || p->state() == QProcess::NotRunning)
            return;
        m_timedOut = true;
        p->kill();
    });
    p->start();
}

void CommandCamera::fail(const motion::msg::Message& m)
{
    QFile::remove(m_file);
    emit failed(m_request.id, motion::msg::Problem("", m));
}

void CommandCamera::finish(int exitCode, QProcess::ExitStatus status)
{
    QProcess* p = m_process;
    if (!p)
        return;
    m_process = nullptr;
    p->deleteLater();
    const std::string err = tail(p->readAllStandardError());
    const std::string cmd = m_command.toStdString();
    if (m_timedOut) {
        fail(motion::msg::make("camera.command.timeout", {motion::msg::verbatim("command", cmd), motion::msg::real("seconds", m_timeoutS, motion::msg::Unit::S), motion::msg::verbatim("stderr", err)}));
        return;
    }
    if (status != QProcess::NormalExit || exitCode != 0) {
        fail(motion::msg::make("camera.command.failed", {motion::msg::verbatim("command", cmd), motion::msg::integer("code", status == QProcess::NormalExit ? exitCode : -1, motion::msg::Unit::None),
                                                 motion::msg::verbatim("stderr", err)}));
        return;
    }
    if (!QFileInfo::exists(m_file)) {
        fail(motion::msg::make("camera.command.no_file", {motion::msg::verbatim("command", cmd), motion::msg::verbatim("file", m_file.toStdString()), motion::msg::verbatim("stderr", err)}));
        return;
    }
    Frame frame;
    motion::msg::Message error;
    if (!readImageFile(m_file, &frame, &error)) {
        fail(error);
        return;
    }
    QFile::remove(m_file);
    frame.exposureMs = m_exposureMs;
    frame.sequence = ++m_sequence;
    emit captured(m_request.id, frame);
}

} // namespace dev::camera
