#pragma once
#include <QFrame>
#include <QTimer>

class QLabel;

namespace ui {

/// Non-modal message strip at the top of a window: errors stay until dismissed
/// or replaced, notes fade after a while. Never blocks the operator.
class MessageBanner : public QFrame {
    Q_OBJECT
public:
    enum class Level { Info, Warning, Error };
    explicit MessageBanner(QWidget* parent = nullptr);
    void show(Level level, const QString& text);
    QString text() const;
    Level level() const { return m_level; }

private:
    QLabel* m_label;
    QTimer m_hide;
    Level m_level = Level::Info;
};

} // namespace ui
