#pragma once
// Device events and link messages, newest at the bottom; bounded so a chatty
// device cannot grow it without end (oldest rows go first).
#include "device/client/instrument_types.h"

#include <QWidget>

class QTableWidget;

namespace ui {

class EventLog : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMaxRows = 5000;
    explicit EventLog(QWidget* parent = nullptr);
    void addEvent(const QString& instrument, const dev::DeviceIdentity& id, const dev::DeviceEvent& event);
    void addNote(const QString& instrument, const QString& kind, const QString& text, bool isError = false);
    int rowCount() const;
    QString rowText(int row) const;  ///< "time | instrument | axis | kind | text", for tests and copying

private:
    void append(const QStringList& cells, const QColor& color);
    QTableWidget* m_table;
};

} // namespace ui
