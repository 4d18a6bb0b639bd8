#pragma once
// benchpilot-sim serving the reference firmware on a pseudo-terminal in a
// private directory, for tests that open it like a serial port (benchpilot-cli
// --port, SerialTransport). Its clock can run faster so homing stays short.
#include "programs.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QTemporaryDir>

namespace itest {

/// benchpilot-sim on a pty in a private directory; stopped with SIGTERM at the end.
class PtySimulator {
public:
    bool start(const QString& instrument, double timeScale = 4)
    {
        if (!m_dir.isValid()) {
            m_error = QStringLiteral("no temporary directory");
            return false;
        }
        m_link = m_dir.filePath(QStringLiteral("ttyBP"));
        m_proc.start(binary("benchpilot-sim"), {QStringLiteral("--instrument"), instrument, QStringLiteral("--pty"), m_link,
                                                 QStringLiteral("--time-scale"), QString::number(timeScale)});
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
