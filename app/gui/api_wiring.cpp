#include "api_wiring.h"

#include "api_panel.h"
#include "gated_instrument.h"
#include "instrument_session.h"
#include "app/api/api_server.h"
#include "device/jobs/pattern_runner.h"
#include "device/link/simulated_link.h"
#include "device/jobs/recipe_runner.h"
#include "device/jobs/scan_runner.h"
#include "device/jobs/tuning/tuning_runner.h"
#include "widgets/calibration/calibration_screen.h"

#include <QFileInfo>
#include <QPointer>

namespace app {

ApiWiring::ApiWiring(InstrumentSession* const sessions[2], dev::tele::TelemetryHub* hub, const ApiOptions& options, QWidget* window)
    : QObject(window)
{
    // Each lives as long as its session's proxy (the screens hold them the same way).
    for (int i = 0; i < 2; ++i)
        m_gated[i] = new GatedInstrument(sessions[i]->instrument(), [this] { return blockedBy(); }, [this] { askTakeBack(); }, sessions[i]);
    if (options.socketPath.isEmpty())
        return;
    QVector<app::api::ServedInstrument> served{{QStringLiteral("analyzer"), sessions[0]->instrument(), 0, {}},
                                          {QStringLiteral("stage"), sessions[1]->instrument(), 1, {}}};
    for (int i = 0; i < 2; ++i) {
        QPointer<InstrumentSession> session(sessions[i]);
        served[i].simulator = [session]() -> QObject* { return session ? qobject_cast<dev::SimulatedLink*>(session->link()) : nullptr; };
    }
    m_server = std::make_unique<app::api::ApiServer>(served, hub);
    QString error;
    if (!m_server->listen(options.socketPath, &error)) {
        m_startError = tr("Scripting API not started: %1").arg(error);
        m_server.reset();
        return;
    }
    if (options.webSocketPort) {
        const QString token = options.tokenFile.isEmpty() ? QFileInfo(options.socketPath).absolutePath() + QStringLiteral("/api.token")
                                                          : options.tokenFile;
        if (!m_server->listenWebSocket(options.webSocketPort, token, options.allowedOrigins, &error))
            m_startError = tr("Scripting API WebSocket not started: %1").arg(error);
    }
    m_server->setOperatorBusy([this] { return m_operatorBusy ? m_operatorBusy() : QString(); });
    m_strip = new ApiControlStrip(m_server.get(), window);
    m_panel = new ApiPanel(m_server.get());
    m_statusButton = new ApiStatusButton(m_server.get(), window);
    connect(m_statusButton, &QToolButton::clicked, this, &ApiWiring::showPanelRequested);
    connect(m_server.get(), &app::api::ApiServer::activity, this, &ApiWiring::note);
    connect(m_server.get(), &app::api::ApiServer::jobHandedOver, this, [this](const QString&, const QString& text) { emit handedOver(text); });
}

ApiWiring::~ApiWiring()
{
    // The server's calls end before the sessions they use (the window destroys those after).
    m_server.reset();
}

dev::Instrument* ApiWiring::screenInstrument(int index) const { return m_gated[index]; }

QString ApiWiring::blockedBy() const
{
    // Any holder, a script's or an attached benchpilot-cli's for its one call.
    if (!m_server || !m_server->lease().holder())
        return {};
    return m_server->lease().holder()->clientName;
}

void ApiWiring::askTakeBack()
{
    if (!m_server || !m_ask || m_asking)
        return;
    const auto& h = m_server->lease().holder();
    if (!h)
        return;
    m_asking = true;
    const bool take = m_ask(tr("%1 has had control of the bench since %2.\n\nTake control back? The script's next call is "
                               "refused and its jogs stop; a job it started goes on as yours. Then do again what you meant to do.")
                                .arg(h->clientName, h->since.toString(QStringLiteral("HH:mm:ss"))));
    m_asking = false;
    if (take)
        m_server->takeBack();
}

void ApiWiring::watchRunners(dev::jobs::RecipeRunner* plates, dev::jobs::ScanRunner* scan, dev::jobs::PatternRunner* const patterns[2],
                             dev::TuningRunner* tuning, ui::CalibrationScreen* calibration)
{
    if (!m_server)
        return;
    QPointer<dev::jobs::RecipeRunner> p(plates);
    QPointer<dev::jobs::ScanRunner> s(scan);
    QPointer<dev::jobs::PatternRunner> pa(patterns[0]), ps(patterns[1]);
    QPointer<dev::TuningRunner> t(tuning);
    QPointer<ui::CalibrationScreen> c(calibration);
    m_operatorBusy = [p, s, pa, ps, t, c]() -> QString {
        using R = dev::jobs::RunState;
        if (p && (p->state() == R::Running || p->state() == R::Pausing || p->state() == R::Paused || p->state() == R::Aborting))
            return tr("a recipe on the Plates screen");
        if (s && (s->isActive() || s->state() == dev::jobs::ScanRunner::State::Paused))
            return tr("a scan on the Scan screen");
        if ((pa && pa->busy()) || (ps && ps->busy()))
            return tr("a pattern on the Patterns screen");
        if (t && t->busy())
            return tr("a test on the Tuning screen");
        if (c && c->busy())  // a paused accuracy run too: a script's move would spoil its readings
            return tr("a test on the Calibration screen");
        return {};
    };
    app::api::watchRecipeRunner(m_server->jobs(), plates, QStringLiteral("analyzer"), QStringLiteral("plates screen"));
    app::api::watchScanRunner(m_server->jobs(), scan, QStringLiteral("stage"), QStringLiteral("scan screen"));
    app::api::watchPatternRunner(m_server->jobs(), patterns[0], QStringLiteral("analyzer"), QStringLiteral("patterns screen"));
    app::api::watchPatternRunner(m_server->jobs(), patterns[1], QStringLiteral("stage"), QStringLiteral("patterns screen"));
    if (!calibration)
        return;
    auto instrumentKey = [](int index) { return index == 0 ? QStringLiteral("analyzer") : QStringLiteral("stage"); };
    connect(calibration, &ui::CalibrationScreen::accuracyRunStarting, this, [this, instrumentKey](dev::jobs::AccuracyRunner* r, int index) {
        app::api::watchAccuracyRunner(m_server->jobs(), r, instrumentKey(index), QStringLiteral("calibration screen"));
    });
    connect(calibration, &ui::CalibrationScreen::circleRunStarting, this, [this, instrumentKey](dev::jobs::CircleRunner* r, int index) {
        app::api::watchCircleRunner(m_server->jobs(), r, instrumentKey(index), QStringLiteral("calibration screen"));
    });
}

} // namespace app
