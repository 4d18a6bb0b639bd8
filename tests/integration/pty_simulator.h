#pragma once
// benchpilot-sim serving the reference firmware on a pseudo-terminal, for tests
// that run benchpilot-cli (or a SerialTransport) over a real serial path: the
// machine's state outlives the programs that talk to it.
#include "programs.h"

#include <QElapsedTimer>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

namespace itest {

/// The last line of a program's output that parses as a JSON object (--json prints one per line).
inline QJsonObject lastJson(const QString& text)
{
    const QStringList lines = text.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    for (auto it = lines.crbegin(); it != lines.crend(); ++it) {
        const auto doc = QJsonDocument::fromJson(it->toUtf8());
        if (doc.isObject())
            return doc.object();
    }
    return {};
}

/// benchpilot-sim on a pty in a private directory; stopped with SIGTERM at the end.
class PtySimulator {
public:
    /// `extraArgs`: more options for benchpilot-sim (e.g. --protocol grbl).
    bool start(const QString& instrument, double timeScale = 4, const QStringList& extraArgs = {})
    {
        if (!m_dir.isValid()) {
            m_error = QStringLiteral("no temporary directory");
            return false;
        }
        m_link = m_dir.filePath(QStringLiteral("ttyBP"));
        m_proc.start(binary("benchpilot-sim"), QStringList{QStringLiteral("--instrument"), instrument, QStringLiteral("--pty"),
                                                           m_link, QStringLiteral("--time-scale"), QString::number(timeScale)}
                                                   + extraArgs);
        if (!m_proc.waitForStarted(10000)) {
            m_error = QStringLiteral("could not start %1: %2").arg(binary("benchpilot-sim"), m_proc.errorString());
            return false;
        }
        QElapsedTimer t;
        t.start();
        while (!m_proc.canReadLine() && t.elapsed() < 10000 && m_proc.state() == QProcess::Running)
            m_proc.waitForReadyRead(200);
        if (!m_proc.canReadLine()) {
            m_error = QStringLiteral("benchpilot-sim printed no line: %1").arg(QString::fromUtf8(m_proc.readAllStandardError()));
            return false;
        }
        m_line = QString::fromUtf8(m_proc.readLine()).trimmed();
        return true;
    }
    ~PtySimulator()
    {
        if (m_proc.state() != QProcess::NotRunning) {
            m_proc.terminate();
            if (!m_proc.waitForFinished(5000)) {
                m_proc.kill();
                m_proc.waitForFinished(5000);
            }
        }
    }
    QString link() const { return m_link; }
    QString line() const { return m_line; }
    QString error() const { return m_error; }
    QProcess& process() { return m_proc; }

private:
    QTemporaryDir m_dir;
    QProcess m_proc;
    QString m_link, m_line, m_error;
};


} // namespace itest
