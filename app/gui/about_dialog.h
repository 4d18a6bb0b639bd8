#pragma once
// Help → About BenchPilot: the version, the Qt it runs on, the licence and the
// libraries the program is made of with theirs (docs/licences.md has the same
// table). The menu and the box word themselves again when the language changes.
#include <QDialog>
#include <QMenu>

class QLabel;

namespace app {

class AboutDialog : public QDialog {
    Q_OBJECT
public:
    explicit AboutDialog(QWidget* parent = nullptr);
    /// What the box says, as rich text (the tests read it).
    static QString text();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    QLabel* m_text = nullptr;
};

/// The Help menu: About BenchPilot (a box that does not block the window).
class HelpMenu : public QMenu {
    Q_OBJECT
public:
    explicit HelpMenu(QWidget* parent = nullptr);
    QAction* aboutAction() const { return m_about; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    QAction* m_about = nullptr;
};

} // namespace app
