#include "widgets/event_log.h"

#include "device/client/instrument.h"
#include "widgets/wording/wording.h"

#include <QEvent>
#include <QHeaderView>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace ui {

EventLog::EventLog(QWidget* parent) : QWidget(parent), m_table(new QTableWidget(0, 5, this))
{
    auto* l = new QVBoxLayout(this);
    l->setContentsMargins(0, 0, 0, 0);
    l->addWidget(m_table);
    m_table->horizontalHeader()->setStretchLastSection(true);
    m_table->verticalHeader()->setVisible(false);
    // One line of text a row, with little padding: more of what just happened in the same height.
    m_table->verticalHeader()->setMinimumSectionSize(m_table->fontMetrics().height() + 4);
    m_table->verticalHeader()->setDefaultSectionSize(m_table->fontMetrics().height() + 6);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setColumnWidth(0, 90);
    m_table->setColumnWidth(1, 80);
    m_table->setColumnWidth(2, 40);
    m_table->setColumnWidth(3, 110);
    retranslateUi();
}

void EventLog::changeEvent(QEvent* e)
{
    if (e->type() == QEvent::LanguageChange)
        retranslateUi();
    QWidget::changeEvent(e);
}

void EventLog::retranslateUi()
{
    m_table->setHorizontalHeaderLabels({tr("Time"), tr("Instrument"), tr("Axis"), tr("Event"), tr("Details")});
    for (int row = 0; row < static_cast<int>(m_entries.size()); ++row)
        show(row, m_entries[static_cast<std::size_t>(row)]);
}

int EventLog::rowCount() const { return m_table->rowCount(); }

int EventLog::heightForRows(int rows) const
{
    return m_table->horizontalHeader()->sizeHint().height() + rows * m_table->verticalHeader()->defaultSectionSize()
        + 2 * m_table->frameWidth();
}

QString EventLog::rowText(int row) const
{
    QStringList cells;
    for (int c = 0; c < m_table->columnCount(); ++c)
        cells << (m_table->item(row, c) ? m_table->item(row, c)->text() : QString());
    return cells.join(QStringLiteral(" | "));
}

QStringList EventLog::cellsOf(const Entry& e) const
{
    QString instrument = e.instrumentText;
    if (e.instrument)
        instrument = *e.instrument == dev::proto::DeviceKind::Stage ? tr("Stage") : tr("Analyzer");
    QString kind = e.kindText, details = e.noteText;
    if (e.event) {
        const std::string term = dev::proto::eventKindTerm(*e.event);
        // A kind this build does not know (a newer device): by number, so it can be looked up.
        kind = term == "device.event.unknown" ? tr("event %1").arg(static_cast<int>(*e.event)) : ui::words::term(term);
        // What the backend made of it (a GRBL alarm with its meaning) says more than the
        // device's own words ("ALARM:3"), and is worded in the language of the log.
        const QString said = e.worded || !e.note.empty() ? ui::words::text(e.note) : e.deviceText;
        details = said;
        if (e.position) {
            const QString at = e.segment ? tr("segment %1").arg(static_cast<qint64>(*e.position))
                                         : tr("at %1 %2").arg(QLocale().toString(*e.position, 'f', 3), e.unit);
            details = said.isEmpty() ? at : tr("%1 (%2)", "an event's detail, then where it happened").arg(said, at);
        }
    } else {
        if (!e.kindTerm.empty())
            kind = ui::words::term(e.kindTerm);
        if (!e.note.empty())
            details = ui::words::text(e.note);
    }
    return {QLocale().toString(e.time, QStringLiteral("HH:mm:ss.zzz")), instrument, e.axis, kind, details};
}

void EventLog::show(int row, const Entry& e)
{
    const QStringList cells = cellsOf(e);
    for (int c = 0; c < cells.size(); ++c) {
        QTableWidgetItem* item = m_table->item(row, c);
        if (!item) {
            item = new QTableWidgetItem;
            if (e.color.isValid())
                item->setForeground(e.color);
            m_table->setItem(row, c, item);
        }
        item->setText(cells[c]);
    }
}

void EventLog::append(Entry e)
{
    if (m_table->rowCount() >= kMaxRows) {
        m_table->removeRow(0);
        m_entries.pop_front();
    }
    const int row = m_table->rowCount();
    m_table->insertRow(row);
    m_entries.push_back(std::move(e));
    show(row, m_entries.back());
    m_table->scrollToBottom();
}

void EventLog::addEvent(dev::proto::DeviceKind instrument, const dev::DeviceIdentity& id, const dev::DeviceEvent& event)
{
    if (event.kind == dev::proto::EventKind::PathSegmentDone)
        return;  // not logged (below): the entry before it is another event's
    addEvent(QString(), id, event);
    if (!m_entries.empty() && m_entries.back().event && m_entries.back().instrumentText.isEmpty()) {
        m_entries.back().instrument = instrument;
        show(m_table->rowCount() - 1, m_entries.back());
    }
}

void EventLog::addEvent(const QString& instrument, const dev::DeviceIdentity& id, const dev::DeviceEvent& ev)
{
    // A path reports every segment it completes: the Patterns screen shows that as progress;
    // in the log it would bury everything else.
    if (ev.kind == dev::proto::EventKind::PathSegmentDone)
        return;
    Entry e;
    e.time = ev.hostTime.time();
    e.instrumentText = instrument;
    e.axis = ev.axis >= 0 && ev.axis < id.axes.size() ? QString(id.axes[ev.axis].letter) : QString();
    switch (ev.kind) {
    case dev::proto::EventKind::LimitHit:
    case dev::proto::EventKind::Fault:
    case dev::proto::EventKind::EStop:
    case dev::proto::EventKind::LostSteps: e.color = QColor(0xB7, 0x1C, 0x1C); break;
    case dev::proto::EventKind::JogExpired:
    case dev::proto::EventKind::PathUnderrun:
    case dev::proto::EventKind::PathAborted: e.color = QColor(0x9A, 0x67, 0x00); break;
    default: break;
    }
    e.event = ev.kind;
    e.deviceText = ev.text;
    e.note = ev.detail;
    e.worded = ev.worded;
    if (ev.axis >= 0 && ev.axis < id.axes.size()) {
        const double shown = std::round(ev.position * 1000) / 1000;
        e.position = shown == 0 ? 0.0 : shown;
        e.unit = id.axes[ev.axis].unitName();
    } else if (ev.kind >= dev::proto::EventKind::PathStarted && ev.kind <= dev::proto::EventKind::PathAborted) {
        e.position = ev.position;
        e.segment = true;
    }
    append(std::move(e));
}

void EventLog::addNote(dev::proto::DeviceKind instrument, const std::string& kindTerm, const motion::msg::Message& text, bool isError)
{
    Entry e;
    e.time = QTime::currentTime();
    e.instrument = instrument;
    e.kindTerm = kindTerm;
    e.note = text;
    e.color = isError ? QColor(0xB7, 0x1C, 0x1C) : QColor();
    append(std::move(e));
}

void EventLog::addNote(const QString& instrument, const std::string& kindTerm, const motion::msg::Message& text, bool isError)
{
    Entry e;
    e.time = QTime::currentTime();
    e.instrumentText = instrument;
    e.kindTerm = kindTerm;
    e.note = text;
    e.color = isError ? QColor(0xB7, 0x1C, 0x1C) : QColor();
    append(std::move(e));
}

void EventLog::addNote(const QString& instrument, const QString& kind, const QString& text, bool isError)
{
    Entry e;
    e.time = QTime::currentTime();
    e.instrumentText = instrument;
    e.kindText = kind;
    e.noteText = text;
    e.color = isError ? QColor(0xB7, 0x1C, 0x1C) : QColor();
    append(std::move(e));
}

} // namespace ui
