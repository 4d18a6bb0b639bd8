#pragma once
// One instrument as the application holds it: its client and whatever link it
// is on now (simulator or serial port). Switching links never restarts the app.
#include "device/client/instrument_client.h"
#include "widgets/connection_bar.h"

#include <QObject>
#include <QPointer>

namespace app {

class InstrumentSession : public QObject {
    Q_OBJECT
public:
    InstrumentSession(proto::DeviceKind kind, const QString& name, QObject* parent = nullptr);
    ~InstrumentSession() override;

    dev::InstrumentClient* client() { return m_client; }
    proto::DeviceKind kind() const { return m_kind; }
    QString name() const { return m_name; }
    ui::ConnectionChoice choice() const { return m_choice; }
    /// Drops the present link (if any) and connects through the chosen one.
    void connectTo(const ui::ConnectionChoice& choice);
    void disconnectLink();
    /// The in-process simulator's link, when that is what is connected (for tests and benches).
    QObject* link() const { return m_link; }

private:
    proto::DeviceKind m_kind;
    QString m_name;
    dev::InstrumentClient* m_client;
    QPointer<QObject> m_link;
    ui::ConnectionChoice m_choice;
};

} // namespace app
