#pragma once
// A one-line label for text that may be longer than the room it gets (an
// instrument's identity, a file's name): cut with "…" rather than clipped
// mid-letter, with the whole text in the tooltip, and never asking the window
// to be wider than the screen (a 1366 × 768 laptop must show every control).
#include <QLabel>

namespace ui {

class ElidedLabel : public QLabel {
    Q_OBJECT
public:
    explicit ElidedLabel(QWidget* parent = nullptr);

    /// The whole text; what shows is this, elided to the label's width.
    void setFullText(const QString& text);
    QString fullText() const { return m_full; }
    /// True while the text shown is cut short.
    bool isElided() const { return text() != m_full; }

    QSize minimumSizeHint() const override;
    QSize sizeHint() const override;

protected:
    void resizeEvent(QResizeEvent* event) override;

private:
    void elide();

    QString m_full;
};

} // namespace ui
