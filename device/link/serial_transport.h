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

    struct PortInfo {
        QString name;         ///< what QSerialPort opens: "ttyUSB0", or a path
        QString description;  ///< manufacturer and description, for people
    };
    static QList<PortInfo> availablePorts();

private:
    QSerialPort* m_port;
    QString m_name;
    qint32 m_baud;
};

} // namespace dev
