#pragma once
// The long-move question of every screen (Jog, Patterns, Scan; widgets/common/confirmation.h)
// with "Don't ask again this session": an operator who crosses the deck all afternoon is not
// asked each time, and the waiver ends with the program — it is never written to the
// settings. Destructive questions (Abort, Disconnect during a run, homing a plunger that
// holds liquid, discarding edits) never come here and never offer it.
#include <QObject>
#include <QString>

#include <functional>

class QWidget;

namespace app {

class LongMoveQuestion : public QObject {
    Q_OBJECT
public:
    /// `answer` (tests): answers instead of the dialog, with no waiver; empty: the dialog asks.
    explicit LongMoveQuestion(QWidget* window, std::function<bool(const QString&)> answer = {});

    /// True: go ahead. Asks unless the operator waived the question earlier this session.
    bool ask(const QString& question);
    bool waived() const { return m_waived; }

private:
    QWidget* m_window;
    std::function<bool(const QString&)> m_answer;
    bool m_waived = false;
};

} // namespace app
