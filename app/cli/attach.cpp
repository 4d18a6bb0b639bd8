// benchpilot-cli --attach: the same command through the running GUI's scripting API
// (docs/api.md). The words go over the socket as one cli.run call; the GUI runs them
// with the same parser and the same command code, on its own instruments, and streams
// back what the command printed (cli.output notifications), then the exit code. So a
// script that shells out gets the same output and exit codes whether or not the GUI is
// open. Ctrl+C sends call.cancel: the command is interrupted as it would be here (a
// recipe run aborts and its tip rises).
#include "command.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLocalSocket>

#include <csignal>
#include <optional>
#include <unistd.h>

namespace app::cli {
namespace {

QString tr(const char* text) { return QCoreApplication::translate("app::cli", text); }

volatile std::sig_atomic_t g_interrupted = 0;
void onInterrupt(int) { g_interrupted = 1; }

constexpr int kConnectTimeoutMs = 3000;

bool sendLine(QLocalSocket& socket, const QJsonObject& message)
{
    const QByteArray line = QJsonDocument(message).toJson(QJsonDocument::Compact) + '\n';
    socket.write(line);
    return socket.waitForBytesWritten(kConnectTimeoutMs) || socket.bytesToWrite() == 0;
}

} // namespace

namespace {
/// XDG_RUNTIME_DIR as the program was started with it, once noted (noteUsersRuntimeDir).
std::optional<QString>& usersRuntimeDir()
{
    static std::optional<QString> dir;
    return dir;
}
} // namespace

void noteUsersRuntimeDir() { usersRuntimeDir() = qEnvironmentVariable("XDG_RUNTIME_DIR"); }

QString apiSocketPathFor(const QString& runtimeDir, uint uid)
{
    // Spelled as benchpilot.py's default_socket_path() does (os.path.join), character for
    // character: the Python client and the CLI must find the GUI in the same place.
    if (!runtimeDir.isEmpty())
        return runtimeDir + (runtimeDir.endsWith(QLatin1Char('/')) ? QString() : QStringLiteral("/")) + QStringLiteral("benchpilot/api.sock");
    return QStringLiteral("/tmp/benchpilot-%1/api.sock").arg(uid);
}

QString defaultApiSocketPath()
{
    const std::optional<QString>& noted = usersRuntimeDir();
    return apiSocketPathFor(noted ? *noted : qEnvironmentVariable("XDG_RUNTIME_DIR"), ::getuid());
}

int runAttached(const QStringList& args, const QString& socketPath, QTextStream& out, QTextStream& err)
{
    const QString path = socketPath.isEmpty() ? defaultApiSocketPath() : socketPath;
    QLocalSocket socket;
    socket.connectToServer(path);
    if (!socket.waitForConnected(kConnectTimeoutMs)) {
        const bool nobody = socket.error() == QLocalSocket::ServerNotFoundError || socket.error() == QLocalSocket::ConnectionRefusedError
            || !QFileInfo::exists(path);
        err << "benchpilot-cli: "
            << (nobody ? tr("no BenchPilot GUI is running with its API at %1. Start benchpilot (with --api-socket %1 if "
                            "that is where it should listen), or leave out --attach to open the instrument directly.")
                             .arg(path)
                       : tr("cannot reach the BenchPilot GUI at %1: %2").arg(path, socket.errorString()))
            << "\n";
        err.flush();
        return LinkTrouble;
    }
    const int callId = 1;
    if (!sendLine(socket, QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")},
                                      {QStringLiteral("id"), callId},
                                      {QStringLiteral("method"), QStringLiteral("cli.run")},
                                      {QStringLiteral("params"),
                                       QJsonObject{{QStringLiteral("argv"), QJsonArray::fromStringList(args)},
                                                   {QStringLiteral("cwd"), QDir::currentPath()},
                                                   {QStringLiteral("client"), QStringLiteral("benchpilot-cli")}}}})) {
        err << "benchpilot-cli: " << tr("the GUI at %1 does not take the command: %2").arg(path, socket.errorString()) << "\n";
        err.flush();
        return LinkTrouble;
    }
    g_interrupted = 0;
    auto oldInt = std::signal(SIGINT, onInterrupt);
    auto oldTerm = std::signal(SIGTERM, onInterrupt);
    bool cancelSent = false;
    int exitCode = -1;
    QByteArray buffer;
    while (exitCode < 0) {
        if (g_interrupted && !cancelSent) {
            cancelSent = true;
            sendLine(socket, QJsonObject{{QStringLiteral("jsonrpc"), QStringLiteral("2.0")},
                                         {QStringLiteral("method"), QStringLiteral("call.cancel")},
                                         {QStringLiteral("params"), QJsonObject{{QStringLiteral("call"), callId}}}});
        }
        if (socket.state() != QLocalSocket::ConnectedState && socket.bytesAvailable() == 0)
            break;
        if (!socket.waitForReadyRead(100) && socket.bytesAvailable() == 0)
            continue;
        buffer += socket.readAll();
        for (int nl = buffer.indexOf('\n'); nl >= 0 && exitCode < 0; nl = buffer.indexOf('\n')) {
            const QByteArray line = buffer.left(nl);
            buffer.remove(0, nl + 1);
            const QJsonObject m = QJsonDocument::fromJson(line).object();
            if (m.value(QStringLiteral("method")).toString() == QLatin1String("cli.output")) {
                const QJsonObject p = m.value(QStringLiteral("params")).toObject();
                QTextStream& stream = p.value(QStringLiteral("stream")).toString() == QLatin1String("stderr") ? err : out;
                stream << p.value(QStringLiteral("text")).toString();
                stream.flush();
            } else if (m.contains(QStringLiteral("id")) && m.value(QStringLiteral("id")).toInt() == callId) {
                if (m.contains(QStringLiteral("result"))) {
                    exitCode = m.value(QStringLiteral("result")).toObject().value(QStringLiteral("exit_code")).toInt(LinkTrouble);
                } else {
                    const QJsonObject e = m.value(QStringLiteral("error")).toObject();
                    err << "benchpilot-cli: " << e.value(QStringLiteral("message")).toString() << "\n";
                    err.flush();
                    exitCode = LinkTrouble;
                }
            }
        }
    }
    std::signal(SIGINT, oldInt);
    std::signal(SIGTERM, oldTerm);
    if (exitCode < 0) {
        err << "benchpilot-cli: " << tr("the GUI closed the connection before the command finished") << "\n";
        err.flush();
        return LinkTrouble;
    }
    return exitCode;
}

} // namespace app::cli
