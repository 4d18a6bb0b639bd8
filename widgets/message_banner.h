#pragma once
#include <QFrame>
#include <QList>
#include <QTimer>

#include <functional>

class QLabel;
class QToolButton;

namespace ui {

/// Non-modal message box at the top of a window. It always takes the same
/// two-line height, shown or empty, so a message that comes or goes never moves
/// the controls under the pointer. A longer message is elided; its whole text is
/// the tooltip. Errors stay until dismissed; a message that repeats counts its
/// repeats instead of flashing; news that arrives while an error is unread waits
/// behind it. Warnings and notes step aside by themselves after a while.
class MessageBanner : public QFrame {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };
    explicit MessageBanner(QWidget* parent = nullptr);
    /// `key` names a state the message tells of ("estop"): withdraw(key) takes it back
    /// once that state is over, shown or waiting, so the strip never outlives the fact.
    void show(Level level, const QString& text, const QString& key = {});
    /// A message worded by `wording`, and worded again when the language changes (shown or
    /// waiting), so a switch leaves no line in the old language.
    using Wording = std::function<QString()>;
    void show(Level level, const Wording& wording, const QString& key = {});
    void withdraw(const QString& key);
    /// The message shown now (empty when none).
    QString text() const;
    Level level() const { return m_level; }
    /// True while a message is shown (the strip's space is kept either way).
    bool hasMessage() const { return !m_shown.text.isEmpty(); }
    /// How many times the shown message arrived (1 the first time).
    int repeats() const { return m_shown.count; }
    /// The shown message and those waiting behind it, in the order they will show.
    QStringList texts() const;
    /// Messages waiting behind the shown one.
    int waiting() const { return static_cast<int>(m_waiting.size()); }
    /// The operator read it: the next waiting message, or an empty strip.
    void dismiss();
    /// How long warnings and notes stay.
    static constexpr int kFadeMs = 8000;
    /// At most this many wait; the oldest note or warning goes first.
    static constexpr int kMaxWaiting = 20;
    static constexpr int kLines = 2;

protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    struct Entry {
        Level level = Level::Info;
        QString text;
        int count = 0;
        QString key;
        Wording wording;  ///< none: the text as it came
    };
    void add(Entry e);
    void display(const Entry& e);
    void relabel();

    QLabel* m_label;
    QLabel* m_more;
    QToolButton* m_close;
    QTimer m_fade;
    Level m_level = Level::Info;
    Entry m_shown;
    QList<Entry> m_waiting;
};

} // namespace ui
