#include "api_panel.h"

#include "app/api/api_server.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace app {

namespace {
QString since(const QDateTime& t) { return t.toString(QStringLiteral("HH:mm:ss")); }
} // namespace

// ---- the strip ------------------------------------------------------------------------

ApiControlStrip::ApiControlStrip(app::api::ApiServer* server, QWidget* parent) : QFrame(parent), m_server(server)
{
    setObjectName(QStringLiteral("apiControlStrip"));
    setStyleSheet(QStringLiteral("#apiControlStrip { background:#fff3cd; border:1px solid #d4a72c; border-radius:4px; }"));
    auto* h = new QHBoxLayout(this);
    h->setContentsMargins(8, 3, 8, 3);
    m_label = new QLabel(this);
    m_label->setTextFormat(Qt::PlainText);
    // Wrapped over the height the connection bars give the row: one line was cut at "Your m…"
    // at 1366 px. The button stays whatever the client's name.
    m_label->setWordWrap(true);
    m_label->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_takeBack = new QPushButton(this);
    m_takeBack->setObjectName(QStringLiteral("apiTakeBack"));
    h->addWidget(m_label, 1);
    h->addWidget(m_takeBack);
    connect(m_takeBack, &QPushButton::clicked, server, &app::api::ApiServer::takeBack);
    connect(&server->lease(), &app::api::ControlLease::changed, this, &ApiControlStrip::refresh);
    retranslateUi();
}

QString ApiControlStrip::text() const { return m_label->text(); }

void ApiControlStrip::retranslateUi()
{
    m_takeBack->setText(tr("Take back"));
    m_takeBack->setToolTip(tr("End the script's control now: its next call is refused, its jogs stop; jobs it started go on as yours"));
    refresh();
}

void ApiControlStrip::refresh()
{
    const auto& h = m_server->lease().holder();
    // A call of benchpilot-cli --attach takes control for its own length only: not worth a strip.
    const bool show = h && !h->forOneCall;
    if (show) {
        m_label->setText(tr("%1 has had control of the bench since %2. Your motion controls ask before they act.")
                             .arg(h->clientName, since(h->since)));
        m_label->setToolTip(m_label->text());
    }
    setVisible(show);
}

void ApiControlStrip::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QFrame::changeEvent(event);
}

// ---- the status bar button ------------------------------------------------------------

ApiStatusButton::ApiStatusButton(app::api::ApiServer* server, QWidget* parent) : QToolButton(parent), m_server(server)
{
    setObjectName(QStringLiteral("apiStatus"));
    setAutoRaise(true);
    connect(server, &app::api::ApiServer::clientsChanged, this, &ApiStatusButton::retranslateUi);
    retranslateUi();
}

void ApiStatusButton::retranslateUi()
{
    const int n = m_server->clients().size();
    setText(tr("API: %n client(s)", nullptr, n));
    QString tip = tr("Scripting API on %1").arg(m_server->socketPath());
    if (!m_server->webSocketUrl().isEmpty())
        tip += QLatin1Char('\n') + tr("WebSocket: %1").arg(m_server->webSocketUrl());
    for (const auto& c : m_server->clients())
        tip += QLatin1Char('\n') + tr("%1 (%2), since %3").arg(c.name, c.transport, since(c.since));
    tip += QLatin1Char('\n') + tr("Click for the API panel");
    setToolTip(tip);
}

void ApiStatusButton::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QToolButton::changeEvent(event);
}

// ---- the panel ------------------------------------------------------------------------

ApiPanel::ApiPanel(app::api::ApiServer* server, QWidget* parent) : QWidget(parent), m_server(server)
{
    auto* v = new QVBoxLayout(this);
    v->setContentsMargins(4, 4, 4, 4);
    m_where = new QLabel(this);
    m_where->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_where->setWordWrap(true);
    auto* controlRow = new QHBoxLayout;
    m_control = new QLabel(this);
    m_control->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_takeBack = new QPushButton(this);
    controlRow->addWidget(m_control, 1);
    controlRow->addWidget(m_takeBack);
    m_clientsTitle = new QLabel(this);
    m_clients = new QTableWidget(0, 4, this);
    m_jobsTitle = new QLabel(this);
    m_jobs = new QTableWidget(0, 5, this);
    for (QTableWidget* t : {m_clients, m_jobs}) {
        t->verticalHeader()->hide();
        t->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
        t->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
        t->horizontalHeader()->setStretchLastSection(false);
        t->setWordWrap(false);
        t->setEditTriggers(QAbstractItemView::NoEditTriggers);
        t->setSelectionBehavior(QAbstractItemView::SelectRows);
        t->setSelectionMode(QAbstractItemView::SingleSelection);
        t->setMinimumHeight(60);
    }
    m_abort = new QPushButton(this);
    auto* jobsRow = new QHBoxLayout;
    jobsRow->addWidget(m_jobsTitle, 1);
    jobsRow->addWidget(m_abort);
    v->addWidget(m_where);
    v->addLayout(controlRow);
    v->addWidget(m_clientsTitle);
    v->addWidget(m_clients, 1);
    v->addLayout(jobsRow);
    v->addWidget(m_jobs, 1);
    connect(m_takeBack, &QPushButton::clicked, server, &app::api::ApiServer::takeBack);
    connect(m_abort, &QPushButton::clicked, this, &ApiPanel::abortSelected);
    connect(m_jobs, &QTableWidget::itemSelectionChanged, this, &ApiPanel::refresh);
    connect(server, &app::api::ApiServer::clientsChanged, this, &ApiPanel::refresh);
    connect(&server->jobs(), &app::api::JobBoard::changed, this, &ApiPanel::refresh);
    connect(&server->lease(), &app::api::ControlLease::changed, this, &ApiPanel::refresh);
    retranslateUi();
}

void ApiPanel::retranslateUi()
{
    m_takeBack->setText(tr("Take back"));
    m_clientsTitle->setText(tr("Clients connected"));
    m_jobsTitle->setText(tr("Jobs started by scripts"));
    m_abort->setText(tr("Abort job"));
    m_clients->setHorizontalHeaderLabels({tr("Client"), tr("Transport"), tr("Since"), tr("Calls running")});
    m_jobs->setHorizontalHeaderLabels({tr("Job"), tr("Instrument"), tr("Owner"), tr("State"), tr("Progress")});
    refresh();
}

void ApiPanel::refresh()
{
    QString where = tr("Socket: %1 (this user only)").arg(m_server->socketPath());
    if (!m_server->webSocketUrl().isEmpty())
        where += QLatin1Char('\n') + tr("WebSocket: %1 (127.0.0.1 only, token required)").arg(m_server->webSocketUrl());
    m_where->setText(where);
    const auto& h = m_server->lease().holder();
    m_control->setText(h ? tr("Control: %1, since %2").arg(h->clientName, since(h->since)) : tr("Control: the operator (you)"));
    m_control->setToolTip(m_control->text());
    m_takeBack->setEnabled(h.has_value());
    m_takeBack->setToolTip(h ? tr("End the script's control now") : tr("No script has control"));

    const auto clients = m_server->clients();
    m_clients->setRowCount(clients.size());
    for (int r = 0; r < clients.size(); ++r) {
        const auto& c = clients[r];
        const QStringList cells{c.holdsLease ? tr("%1 (in control)").arg(c.name) : c.name, c.transport, since(c.since), QString::number(c.calls)};
        for (int col = 0; col < cells.size(); ++col) {
            auto* item = new QTableWidgetItem(cells[col]);
            item->setToolTip(cells[col]);
            m_clients->setItem(r, col, item);
        }
    }
    const QString selected = m_jobs->currentRow() >= 0 && m_jobs->item(m_jobs->currentRow(), 0)
        ? m_jobs->item(m_jobs->currentRow(), 0)->data(Qt::UserRole).toString()
        : QString();
    QVector<const app::api::Job*> shown;
    for (const auto& j : m_server->jobs().all())
        if (j.fromApi)
            shown.push_back(&j);
    const QSignalBlocker block(m_jobs);
    m_jobs->setRowCount(shown.size());
    bool canAbort = false;
    for (int r = 0; r < shown.size(); ++r) {
        const app::api::Job& j = *shown[r];
        QStringList progress;
        for (auto it = j.progress.begin(); it != j.progress.end(); ++it)
            if (it.value().isDouble() || it.value().isString())
                progress << QStringLiteral("%1 %2").arg(it.key(), it.value().isDouble() ? QString::number(it.value().toDouble(), 'g', 5) : it.value().toString());
        const QString owner = j.handedOver ? tr("you (started by %1)").arg(j.startedBy) : j.owner;
        const QStringList cells{j.kind, j.instrument, owner, j.state, progress.join(QStringLiteral(", "))};
        for (int col = 0; col < cells.size(); ++col) {
            auto* item = new QTableWidgetItem(cells[col]);
            item->setToolTip(cells[col]);
            if (col == 0)
                item->setData(Qt::UserRole, j.id);
            m_jobs->setItem(r, col, item);
        }
        if (j.id == selected) {
            m_jobs->selectRow(r);
            canAbort = j.state == QLatin1String("running");
        }
    }
    m_abort->setEnabled(canAbort);
    m_abort->setToolTip(canAbort ? tr("Interrupt the selected job as Ctrl+C would (a recipe run raises its tip and can resume)")
                                 : tr("Select a running job to abort it"));
}

void ApiPanel::abortSelected()
{
    const int row = m_jobs->currentRow();
    if (row < 0 || !m_jobs->item(row, 0))
        return;
    m_server->interruptJob(m_jobs->item(row, 0)->data(Qt::UserRole).toString());
}

void ApiPanel::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(event);
}

} // namespace app
