#pragma once
// Where one instrument's connection is chosen: the simulator, a serial port the system lists,
// or any path typed in (the pty of benchpilot-sim, a symlink in /dev/serial/by-id); a baud rate
// (115200 by default, what GRBL boards use); and the machine profile that says how a GRBL
// controller is wired to the instrument (docs/grbl.md). Switched at run time; the protocol a
// port speaks is detected when it connects (a BenchPilot HELLO or a GRBL banner).
#include "device/client/instrument_types.h"
#include "device/link/serial_transport.h"
#include "motion/metrology/grid/stage_errors.h"

#include <QWidget>

#include <functional>
#include <optional>

class QComboBox;
class QLabel;
class QPushButton;
class QToolButton;

namespace ui {

class ElidedLabel;
class StatusLamp;

struct ConnectionChoice {
    bool simulator = true;
    QString port;          ///< when not simulated: a listed port or a typed path
    /// A USB adapter's serial number, when the port was chosen from the list: the same
    /// adapter plugged in again under another /dev name is found by it.
    QString serialNumber;
    qint32 baud = 115200;
    QString profile;       ///< machine profile file; empty: the default wiring (and detect the protocol)
    /// The simulated stage's errors (benchpilot --sim stage --stage-errors FILE), for this
    /// run only; none: the built-in stage's.
    std::optional<motion::metrology::StageErrors> stageErrors;
    bool operator==(const ConnectionChoice& o) const
    {
        return simulator == o.simulator && port == o.port && serialNumber == o.serialNumber && baud == o.baud && profile == o.profile;
    }
};

class ConnectionBar : public QWidget {
    Q_OBJECT
public:
    ConnectionBar(const QString& title, QWidget* parent = nullptr);
    /// The instrument's name, worded anew when the language changes.
    void setTitle(const QString& title);
    ConnectionChoice choice() const;
    void setChoice(const ConnectionChoice& c);
    void showState(dev::LinkState state, const QString& identity);
    /// A note beside the lamp while the session works on something the link state does not
    /// say (detecting the protocol on a port); empty clears it.
    void showActivity(const QString& text);
    /// Offers a machine profile file in the list (and chooses it when `choose`).
    void addProfile(const QString& path, bool choose = true);
    QStringList profiles() const;
    static QList<qint32> baudRates();

    /// Where the port list comes from (the system's, QSerialPortInfo; tests give their own).
    using PortLister = std::function<QList<dev::SerialTransport::PortInfo>()>;
    void setPortLister(PortLister lister);
    /// How a listed port reads: its /dev name, what the adapter says it is, its serial number.
    static QString portLabel(const dev::SerialTransport::PortInfo& port);

public slots:
    void refreshPorts();

signals:
    void connectRequested(const ui::ConnectionChoice& choice);
    void disconnectRequested();
    /// "Open a profile file…" was chosen: the composition root shows the file dialog and
    /// calls addProfile() with the answer.
    void profileFileRequested();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void updateTexts();
    int openProfileIndex() const;

    PortLister m_listPorts = &dev::SerialTransport::availablePorts;
    QString m_titleText;
    QLabel* m_title;
    StatusLamp* m_lamp;
    QComboBox* m_source;
    QToolButton* m_refresh;
    QComboBox* m_baud;
    QComboBox* m_profile;
    QPushButton* m_connect;
    ElidedLabel* m_identity;
    dev::LinkState m_state = dev::LinkState::Disconnected;
    QString m_identityText, m_activity;
    int m_lastProfile = 0;
    bool m_returnQueued = false;
};

} // namespace ui

Q_DECLARE_METATYPE(ui::ConnectionChoice)
