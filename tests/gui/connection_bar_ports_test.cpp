// The connection bar's port list as the system gives it (QSerialPortInfo, faked here behind
// ConnectionBar::PortLister): a USB adapter reads as what it is and its serial number, not
// only /dev/ttyUSB0; the choice carries the serial number, and a remembered adapter that
// comes back under another /dev name is chosen there, not the name another adapter now has.
#include "widgets/connection_bar.h"

#include <QComboBox>

#include <gtest/gtest.h>

namespace {

using Port = dev::SerialTransport::PortInfo;

QComboBox* sourceCombo(ui::ConnectionBar& bar) { return bar.findChildren<QComboBox*>().value(0); }

QStringList labels(QComboBox* c)
{
    QStringList out;
    for (int i = 0; i < c->count(); ++i)
        out << c->itemText(i);
    return out;
}

TEST(ConnectionBarPorts, AdaptersReadAsWhatTheyAreWithTheirSerialNumbers)
{
    ui::ConnectionBar bar(QStringLiteral("Stage"));
    bar.setPortLister([] {
        return QList<Port>{{QStringLiteral("/dev/ttyUSB0"), QStringLiteral("FT232R USB UART"), QStringLiteral("FTDI"), QStringLiteral("A10KZ3QF")},
                           {QStringLiteral("/dev/ttyACM0"), QStringLiteral("Arduino Uno"), QStringLiteral("Arduino (www.arduino.cc)"), QStringLiteral("75833353035351F0E1A1")},
                           {QStringLiteral("/dev/ttyS0"), QString(), QString(), QString()}};
    });
    const QStringList shown = labels(sourceCombo(bar));
    EXPECT_TRUE(shown.contains(QStringLiteral("/dev/ttyUSB0 — FTDI FT232R USB UART, serial number A10KZ3QF"))) << shown.join(QLatin1Char('|')).toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("/dev/ttyACM0 — Arduino (www.arduino.cc) Arduino Uno, serial number 75833353035351F0E1A1")))
        << shown.join(QLatin1Char('|')).toStdString();
    EXPECT_TRUE(shown.contains(QStringLiteral("/dev/ttyS0"))) << shown.join(QLatin1Char('|')).toStdString();

    // A manufacturer the description already names is not said twice.
    EXPECT_EQ(ui::ConnectionBar::portLabel({QStringLiteral("/dev/ttyUSB1"), QStringLiteral("CP2102 USB to UART Bridge Controller"),
                                            QStringLiteral("Silicon Labs"), QStringLiteral("0001")}),
              QStringLiteral("/dev/ttyUSB1 — Silicon Labs CP2102 USB to UART Bridge Controller, serial number 0001"));
    EXPECT_EQ(ui::ConnectionBar::portLabel({QStringLiteral("/dev/ttyUSB1"), QStringLiteral("FTDI FT232R"), QStringLiteral("FTDI"), QString()}),
              QStringLiteral("/dev/ttyUSB1 — FTDI FT232R"));

    // Choosing the adapter from the list carries its serial number to the session.
    QComboBox* source = sourceCombo(bar);
    source->setCurrentIndex(source->findData(QStringLiteral("/dev/ttyUSB0")));
    const ui::ConnectionChoice c = bar.choice();
    EXPECT_FALSE(c.simulator);
    EXPECT_EQ(c.port, QStringLiteral("/dev/ttyUSB0"));
    EXPECT_EQ(c.serialNumber, QStringLiteral("A10KZ3QF"));
}

TEST(ConnectionBarPorts, ARepluggedAdapterIsFoundByItsSerialNumber)
{
    QList<Port> ports{{QStringLiteral("/dev/ttyUSB0"), QStringLiteral("FT232R USB UART"), QStringLiteral("FTDI"), QStringLiteral("A10KZ3QF")}};
    ui::ConnectionBar bar(QStringLiteral("Stage"));
    bar.setPortLister([&ports] { return ports; });
    ui::ConnectionChoice remembered;
    remembered.simulator = false;
    remembered.port = QStringLiteral("/dev/ttyUSB0");
    remembered.serialNumber = QStringLiteral("A10KZ3QF");

    // Replugged after another adapter took ttyUSB0: ours is ttyUSB1 now.
    ports = {{QStringLiteral("/dev/ttyUSB0"), QStringLiteral("CP2102 USB to UART Bridge Controller"), QStringLiteral("Silicon Labs"), QStringLiteral("0001")},
             {QStringLiteral("/dev/ttyUSB1"), QStringLiteral("FT232R USB UART"), QStringLiteral("FTDI"), QStringLiteral("A10KZ3QF")}};
    bar.refreshPorts();
    bar.setChoice(remembered);
    EXPECT_EQ(bar.choice().port, QStringLiteral("/dev/ttyUSB1"));
    EXPECT_EQ(bar.choice().serialNumber, QStringLiteral("A10KZ3QF"));

    // Unplugged: the remembered adapter stays chosen (not found), and when it comes back
    // under yet another name a refresh finds it there.
    ports = {};
    bar.refreshPorts();
    EXPECT_EQ(bar.choice().serialNumber, QStringLiteral("A10KZ3QF"));
    ports = {{QStringLiteral("/dev/ttyUSB2"), QStringLiteral("FT232R USB UART"), QStringLiteral("FTDI"), QStringLiteral("A10KZ3QF")}};
    bar.refreshPorts();
    EXPECT_EQ(bar.choice().port, QStringLiteral("/dev/ttyUSB2"));

    // A port chosen without a serial number (a built-in one, a typed path) is found by its name.
    ui::ConnectionChoice plain;
    plain.simulator = false;
    plain.port = QStringLiteral("/dev/ttyUSB2");
    bar.setChoice(plain);
    EXPECT_EQ(bar.choice().port, QStringLiteral("/dev/ttyUSB2"));
}

} // namespace
