#pragma once
// The scripting API in the window (docs/api.md):
//  - ApiControlStrip: while a script holds control, a strip on every screen says which
//    client and since when, with Take back (hidden otherwise);
//  - ApiStatusButton: "API: 2 clients" in the status bar; the socket path in its tooltip;
//    opens the panel;
//  - ApiPanel: the socket (and WebSocket), the clients connected, the jobs scripts
//    started (with Abort), in a dock beside the event log.
#include <QFrame>
#include <QToolButton>
#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace app::api {
class ApiServer;
}

namespace app {

class ApiControlStrip : public QFrame {
    Q_OBJECT
public:
    ApiControlStrip(app::api::ApiServer* server, QWidget* parent = nullptr);
    QPushButton* takeBackButton() const { return m_takeBack; }
    QString text() const;

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void refresh();

    app::api::ApiServer* m_server;
    QLabel* m_label;
    QPushButton* m_takeBack;
};

class ApiStatusButton : public QToolButton {
    Q_OBJECT
public:
    ApiStatusButton(app::api::ApiServer* server, QWidget* parent = nullptr);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();

    app::api::ApiServer* m_server;
};

class ApiPanel : public QWidget {
    Q_OBJECT
public:
    ApiPanel(app::api::ApiServer* server, QWidget* parent = nullptr);
    QTableWidget* clientsTable() const { return m_clients; }
    QTableWidget* jobsTable() const { return m_jobs; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void refresh();
    void abortSelected();

    app::api::ApiServer* m_server;
    QLabel* m_where;
    QLabel* m_control;
    QPushButton* m_takeBack;
    QLabel* m_clientsTitle;
    QTableWidget* m_clients;
    QLabel* m_jobsTitle;
    QTableWidget* m_jobs;
    QPushButton* m_abort;
};

} // namespace app
