#pragma once
// Where one instrument's connection is chosen: the simulator or any serial port
// the system lists, with a baud rate; switched at run time.
#include "device/client/instrument_types.h"

#include <QWidget>

class QComboBox;
class QLabel;
class QPushButton;

namespace ui {

class StatusLamp;

struct ConnectionChoice {
    bool simulator = true;
    QString port;          ///< when not simulated
    qint32 baud = 115200;
    bool operator==(const ConnectionChoice& o) const { return simulator == o.simulator && port == o.port && baud == o.baud; }
};

class ConnectionBar : public QWidget {
    Q_OBJECT
public:
    ConnectionBar(const QString& title, QWidget* parent = nullptr);
    ConnectionChoice choice() const;
    void setChoice(const ConnectionChoice& c);
    void showState(dev::LinkState state, const QString& identity);
    static QList<qint32> baudRates();

public slots:
    void refreshPorts();

signals:
    void connectRequested(const ui::ConnectionChoice& choice);
    void disconnectRequested();

private:
    QLabel* m_title;
    StatusLamp* m_lamp;
    QComboBox* m_source;
    QComboBox* m_baud;
    QPushButton* m_connect;
    QLabel* m_identity;
    dev::LinkState m_state = dev::LinkState::Disconnected;
};

} // namespace ui
