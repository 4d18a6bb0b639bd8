#pragma once
#include "device/link/transport.h"

class QSerialPort;

namespace dev {

/// The only place that includes QSerialPort: 8N1, no flow control.
class SerialTransport final : public Transport {
    Q_OBJECT
public:
    SerialTransport(const QString& portName, qint32 baud, QObject* parent = nullptr);
    ~SerialTransport() override;

    void open() override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray& bytes) override;
    QString describe() const override;

    /// What the system says of a port (QSerialPortInfo), for people to tell adapters apart.
    struct PortInfo {
        QString name;          ///< what QSerialPort opens: "/dev/ttyUSB0", or a path
        QString description;   ///< the adapter's product text ("FT232R USB UART"); empty for a built-in port
        QString manufacturer;  ///< "FTDI"; often empty
        QString serialNumber;  ///< the USB serial number: the same adapter keeps it on any /dev name
    };
    static QList<PortInfo> availablePorts();

private:
    QSerialPort* m_port;
    QString m_name;
    qint32 m_baud;
};

} // namespace dev
