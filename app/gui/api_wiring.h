#pragma once
// The scripting API as the main window composes it (docs/api.md): the server on the
// instruments' proxies and the telemetry hub, the operator's screens given gated
// instruments (their motion asks first while a script holds control), the strip that
// says who has control with Take back, the API panel (socket, clients, jobs), and the
// API's part of the event log.
#include <QObject>
#include <QPointer>
#include <QStringList>

#include <functional>
#include <memory>

class QLabel;
class QPushButton;
class QToolButton;
class QWidget;

namespace app::api {
class ApiServer;
}
namespace dev {
class Instrument;
}
namespace dev::jobs {
class PatternRunner;
class RecipeRunner;
class ScanRunner;
}
namespace dev {
class TuningRunner;
}
namespace ui {
class CalibrationScreen;
}
namespace dev::tele {
class TelemetryHub;
}

namespace app {

class ApiPanel;
class ApiControlStrip;
class GatedInstrument;
class InstrumentSession;

struct ApiOptions {
    QString socketPath;           ///< empty: no API (tests, screenshots)
    quint16 webSocketPort = 0;    ///< 0: no WebSocket
    QString tokenFile;            ///< the WebSocket's token (default beside the socket)
    QStringList allowedOrigins;   ///< browser Origins the WebSocket accepts
};

class ApiWiring : public QObject {
    Q_OBJECT
public:
    ApiWiring(InstrumentSession* const sessions[2], dev::tele::TelemetryHub* hub, const ApiOptions& options, QWidget* window);
    ~ApiWiring() override;

    /// What the operator's screens hold for instrument `index`: gated while a script has control.
    dev::Instrument* screenInstrument(int index) const;
    /// The screens' runners: a script cannot take control while one of them runs a job.
    void watchRunners(dev::jobs::RecipeRunner* plates, dev::jobs::ScanRunner* scan, dev::jobs::PatternRunner* const patterns[2], dev::TuningRunner* tuning,
                      ui::CalibrationScreen* calibration);
    /// How the window asks "take control back?"; empty: never asks (tests).
    void setAsk(std::function<bool(const QString& question)> ask) { m_ask = std::move(ask); }

    app::api::ApiServer* server() const { return m_server.get(); }
    /// "" when listening (or no API was asked for), else why not, for a banner.
    QString startError() const { return m_startError; }
    ApiControlStrip* strip() const { return m_strip; }
    ApiPanel* panel() const { return m_panel; }
    QToolButton* statusButton() const { return m_statusButton; }

signals:
    /// For the event log: who, what.
    void note(const QString& client, const QString& text, bool problem);
    /// For a banner: a script's job is now the operator's.
    void handedOver(const QString& text);
    void showPanelRequested();

private:
    QString blockedBy() const;
    void askTakeBack();

    std::unique_ptr<app::api::ApiServer> m_server;
    QPointer<GatedInstrument> m_gated[2];
    ApiControlStrip* m_strip = nullptr;
    ApiPanel* m_panel = nullptr;
    QToolButton* m_statusButton = nullptr;
    QString m_startError;
    std::function<bool(const QString&)> m_ask;
    std::function<QString()> m_operatorBusy;
    bool m_asking = false;
};

} // namespace app
