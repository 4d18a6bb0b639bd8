#pragma once
// Device events and link messages, newest at the bottom; bounded so a chatty
// device cannot grow it without end (oldest rows go first). Every entry is kept
// as data (the event, or a note's message) and worded when it is shown, so a
// language switch rewords the whole log, not only the rows that come after it.
#include "device/client/instrument_types.h"
#include "motion/message.h"

#include <QColor>
#include <QTime>
#include <QWidget>

#include <deque>
#include <optional>
#include <string>

class QTableWidget;

namespace ui {

class EventLog : public QWidget {
    Q_OBJECT
public:
    static constexpr int kMaxRows = 5000;
    explicit EventLog(QWidget* parent = nullptr);
    void addEvent(dev::proto::DeviceKind instrument, const dev::DeviceIdentity& id, const dev::DeviceEvent& event);
    /// A note whose kind is a term ("log.kind.link") and whose text is a message:
    /// both worded again when the language changes.
    void addNote(dev::proto::DeviceKind instrument, const std::string& kindTerm, const motion::msg::Message& text, bool isError = false);
    void addNote(const QString& instrument, const std::string& kindTerm, const motion::msg::Message& text, bool isError = false);
    /// A note already in words (shown as it is in every language).
    void addEvent(const QString& instrument, const dev::DeviceIdentity& id, const dev::DeviceEvent& event);
    void addNote(const QString& instrument, const QString& kind, const QString& text, bool isError = false);
    int rowCount() const;
    /// The height that shows the column titles and `rows` rows.
    int heightForRows(int rows) const;
    QString rowText(int row) const;  ///< "time | instrument | axis | kind | text", for tests and copying

protected:
    void changeEvent(QEvent* e) override;

private:
    struct Entry {
        QTime time;
        std::optional<dev::proto::DeviceKind> instrument;  ///< worded; else instrumentText
        QString instrumentText;
        QString axis;
        std::optional<dev::proto::EventKind> event;        ///< a device event …
        QString deviceText;                           ///< … its text, as the device sent it
        std::optional<double> position;               ///< … and where (axis units, or a segment index)
        QString unit;
        bool segment = false;
        std::string kindTerm;                         ///< a note of a worded kind …
        QString kindText;                             ///< … or of a kind already in words
        bool worded = false;                          ///< an event whose detail says all the device said
        motion::msg::Message note;                            ///< a worded note, or an event's structured detail …
        QString noteText;                             ///< … or one already in words
        QColor color;
    };
    void retranslateUi();
    QStringList cellsOf(const Entry& e) const;
    void append(Entry e);
    void show(int row, const Entry& e);
    QTableWidget* m_table;
    std::deque<Entry> m_entries;
};

} // namespace ui
