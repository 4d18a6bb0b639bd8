#include "app/gui/long_move_question.h"

#include <QCheckBox>
#include <QMessageBox>
#include <QWidget>

namespace app {

LongMoveQuestion::LongMoveQuestion(QWidget* window, std::function<bool(const QString&)> answer)
    : QObject(window), m_window(window), m_answer(std::move(answer))
{
}

bool LongMoveQuestion::ask(const QString& question)
{
    if (m_waived)
        return true;
    if (m_answer)
        return m_answer(question);
    QMessageBox box(QMessageBox::Question, tr("Confirm move"), question, QMessageBox::Yes | QMessageBox::Cancel, m_window);
    box.setDefaultButton(QMessageBox::Cancel);
    auto* waive = new QCheckBox(tr("Don't ask again this session"), &box);
    waive->setToolTip(tr("Long moves go ahead without this question until BenchPilot is closed. "
                         "Aborting, disconnecting during a run and homing with liquid still ask."));
    box.setCheckBox(waive);
    const bool yes = box.exec() == QMessageBox::Yes;
    // A waiver with Cancel would mean "never move far": not what anyone ticks it for.
    m_waived = yes && waive->isChecked();
    return yes;
}

} // namespace app
