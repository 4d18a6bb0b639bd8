#include "device/link/serial_transport.h"

#include "device/link/port_access.h"

#include <QSerialPort>
#include <QSerialPortInfo>
#include <QTimer>

namespace dev {

SerialTransport::SerialTransport(const QString& portName, qint32 baud, QObject* parent)
    : Transport(parent), m_port(new QSerialPort(this)), m_name(portName), m_baud(baud)
{
    connect(m_port, &QSerialPort::readyRead, this, [this] { emit bytesReceived(m_port->readAll()); });
    connect(m_port, &QSerialPort::errorOccurred, this, [this](QSerialPort::SerialPortError e) {
        // ResourceError is what an unplugged adapter or a vanished pty gives.
        if (e == QSerialPort::ResourceError && m_port->isOpen()) {
            const motion::msg::Message why = motion::msg::make("link.port_went_away", {motion::msg::verbatim("port", m_name.toStdString()),
                                                                       motion::msg::verbatim("detail", m_port->errorString().toStdString())});
            m_port->close();
            emit lost(why);
        }
    });
}

SerialTransport::~SerialTransport() { close(); }

void SerialTransport::open()
{
    if (m_port->isOpen()) {
        // Already open (a protocol probe opened it for the backend that follows): reopening
        // would reset a board that resets on DTR, and lose what it said. Say opened again.
        QTimer::singleShot(0, this, [this] { emit opened(); });
        return;
    }
    m_port->setPortName(m_name);
    m_port->setBaudRate(m_baud);
    m_port->setDataBits(QSerialPort::Data8);
    m_port->setParity(QSerialPort::NoParity);
    m_port->setStopBits(QSerialPort::OneStop);
    m_port->setFlowControl(QSerialPort::NoFlowControl);
    if (!m_port->open(QIODevice::ReadWrite)) {
        // QSerialPort's errorString() is Qt's own text (translated by Qt's catalogue). Its
        // PermissionError is both "you may not" and "another program has it locked".
        const QString location = m_name.startsWith(QLatin1Char('/')) ? m_name : QStringLiteral("/dev/") + m_name;
        const motion::msg::Message why =
            m_port->error() == QSerialPort::PermissionError
                ? permissionProblem(m_name, portAccess(location), m_port->errorString())
                : motion::msg::make(m_port->error() == QSerialPort::DeviceNotFoundError ? "link.no_such_port" : "link.cannot_open",
                            {motion::msg::verbatim("port", m_name.toStdString()), motion::msg::verbatim("detail", m_port->errorString().toStdString())});
        QTimer::singleShot(0, this, [this, why] { emit failed(why); });
        return;
    }
    m_port->clear();
    QTimer::singleShot(0, this, [this] { emit opened(); });
}

void SerialTransport::close()
{
    if (m_port->isOpen())
        m_port->close();
}

bool SerialTransport::isOpen() const { return m_port->isOpen(); }

void SerialTransport::write(const QByteArray& bytes)
{
    if (m_port->isOpen())
        m_port->write(bytes);
}

QString SerialTransport::describe() const { return tr("%1 @ %2 baud").arg(m_name).arg(m_baud); }

QList<SerialTransport::PortInfo> SerialTransport::availablePorts()
{
    QList<PortInfo> out;
    for (const QSerialPortInfo& p : QSerialPortInfo::availablePorts())
        out.push_back({p.systemLocation(), p.description(), p.manufacturer(), p.serialNumber()});
    return out;
}

} // namespace dev
