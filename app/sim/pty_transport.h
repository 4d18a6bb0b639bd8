#pragma once
// The device end of a pseudo-terminal: the simulator reads requests from and
// writes replies to the pty master, while a host opens the slave like any
// serial port (QSerialPort, screen, minicom).
#include "device/link/transport.h"

#include <QSocketNotifier>

namespace app::sim {

class PtyTransport final : public dev::Transport {
    Q_OBJECT
public:
    PtyTransport(QObject* parent = nullptr);
    ~PtyTransport() override;

    /// Creates the pty; false with `error()` set on failure.
    bool create();
    QString slavePath() const { return m_slavePath; }
    QString error() const { return m_error; }

    void open() override;
    void close() override;
    bool isOpen() const override { return m_master >= 0; }
    void write(const QByteArray& bytes) override;
    QString describe() const override { return m_slavePath; }

private:
    void onReadable();
    void flushPending();

    int m_master = -1;
    int m_slaveKeepAlive = -1;  ///< held open so the master never sees EIO while no host is attached
    QString m_slavePath, m_error;
    QSocketNotifier* m_readNotifier = nullptr;
    QSocketNotifier* m_writeNotifier = nullptr;
    QByteArray m_pending;       ///< bytes the kernel buffer could not take yet; bounded below
};

} // namespace app::sim
