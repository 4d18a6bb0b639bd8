#include "widgets/event_log.h"

#include "device/protocol/messages_tuning.h"

#include <QHeaderView>
#include <cmath>
#include <QTableWidget>
#include <QTime>
#include <QVBoxLayout>

namespace ui {
namespace {
QString kindText(proto::EventKind k)
{
    switch (k) {
    case proto::EventKind::MotionDone: return EventLog::tr("motion done");
    case proto::EventKind::HomeDone: return EventLog::tr("home done");
    case proto::EventKind::LimitHit: return EventLog::tr("limit hit");
    case proto::EventKind::Fault: return EventLog::tr("fault");
    case proto::EventKind::EStop: return EventLog::tr("E-stop");
    case proto::EventKind::JogExpired: return EventLog::tr("jog expired");
    case proto::EventKind::Stopped: return EventLog::tr("stopped");
    case proto::EventKind::LostSteps: return EventLog::tr("lost steps");
    case proto::EventKind::Reset: return EventLog::tr("reset");
    case proto::EventKind::PathStarted: return EventLog::tr("path started");
    case proto::EventKind::PathSegmentDone: return EventLog::tr("path segment done");
    case proto::EventKind::PathUnderrun: return EventLog::tr("path underrun");
    case proto::EventKind::PathDone: return EventLog::tr("path done");
    case proto::EventKind::PathHeld: return EventLog::tr("path held");
    case proto::EventKind::PathAborted: return EventLog::tr("path aborted");
    }
    if (k == proto::kEvTestEnded)
        return EventLog::tr("test ended");
    if (k == proto::kEvTestTripped)
        return EventLog::tr("test tripped");
    if (k == proto::kEvTestAborted)
        return EventLog::tr("test aborted");
    if (k == proto::kEvGainsChanged)
        return EventLog::tr("gains changed");
    // A kind this build does not know (a newer device): by number, so it can be looked up.
    return EventLog::tr("event %1").arg(static_cast<int>(k));
}
} // namespace

EventLog::EventLog(QWidget* parent) : QWidget(parent), m_table(new QTableWidget(0, 5, this))
{
    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(0, 0, 0, 0);
    l->addWidget(m_table);
    m_table->setHorizontalHeaderLabels({tr("Time"), tr("Instrument"), tr("Axis"), tr("Event"), tr("Details")});
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setColumnWidth(0, 90);
    m_table->setColumnWidth(1, 80);
    m_table->setColumnWidth(2, 40);
    m_table->setColumnWidth(3, 110);
}

int EventLog::rowCount() const { return m_table->rowCount(); }

QString EventLog::rowText(int row) const
{
    QStringList cells;
    for (int c = 0; c < m_table->columnCount(); ++c)
        cells << (m_table->item(row, c) ? m_table->item(row, c)->text() : QString());
    return cells.join(QStringLiteral(" | "));
}

void EventLog::append(const QStringList& cells, const QColor& color)
{
    if (m_table->rowCount() >= kMaxRows)
        m_table->removeRow(0);
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    for (int c = 0; c < cells.size(); ++c) {
        auto* item = new QTableWidgetItem(cells[c]);
        if (color.isValid())
            item->setForeground(color);
        m_table->setItem(row, c, item);
    }
    m_table->scrollToBottom();
}

void EventLog::addEvent(const QString& instrument, const dev::DeviceIdentity& id, const dev::DeviceEvent& e)
{
    // A path reports every segment it completes: the Patterns screen shows that as progress;
    // in the log it would bury everything else.
    if (e.kind == proto::EventKind::PathSegmentDone)
        return;
    const QString axis = e.axis >= 0 && e.axis < id.axes.size() ? QString(id.axes[e.axis].letter) : QString();
    QColor color;
    switch (e.kind) {
    case proto::EventKind::LimitHit:
    case proto::EventKind::Fault:
    case proto::EventKind::EStop:
    case proto::EventKind::LostSteps: color = QColor(0xB7, 0x1C, 0x1C); break;
    case proto::EventKind::JogExpired:
    case proto::EventKind::PathUnderrun:
    case proto::EventKind::PathAborted: color = QColor(0x9A, 0x67, 0x00); break;
    default: break;
    }
    QString details = e.text;
    if (e.axis >= 0 && e.axis < id.axes.size())
    {
        const double shown = std::round(e.position * 1000) / 1000;
        const QString at = tr("at %1 %2").arg(shown == 0 ? 0.0 : shown, 0, 'f', 3).arg(id.axes[e.axis].unitName());
        details = e.text.isEmpty() ? at : QStringLiteral("%1 (%2)").arg(e.text, at);
    }
    else if (e.kind >= proto::EventKind::PathStarted && e.kind <= proto::EventKind::PathAborted)
    {
        const QString at = tr("segment %1").arg(static_cast<qint64>(e.position));
        details = e.text.isEmpty() ? at : QStringLiteral("%1 (%2)").arg(e.text, at);
    }
    append({e.hostTime.time().toString(QStringLiteral("HH:mm:ss.zzz")), instrument, axis,
            kindText(e.kind), details},
           color);
}

void EventLog::addNote(const QString& instrument, const QString& kind, const QString& text, bool isError)
{
    append({QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz")), instrument, QString(), kind, text},
           isError ? QColor(0xB7, 0x1C, 0x1C) : QColor());
}

} // namespace ui
