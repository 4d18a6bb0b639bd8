#include "event_journal.h"

#include "device/client/instrument.h"
#include "widgets/wording/wording.h"

#include <QCoreApplication>

namespace app::api {

QJsonObject JournalEntry::toJson() const
{
    QJsonObject o{{QStringLiteral("seq"), static_cast<qint64>(seq)},
                  {QStringLiteral("time"), hostTime.toString(Qt::ISODateWithMs)},
                  {QStringLiteral("source"), source},
                  {QStringLiteral("kind"), kind},
                  {QStringLiteral("text"), text},
                  {QStringLiteral("problem"), problem}};
    if (deviceTimeUs)
        o.insert(QStringLiteral("device_time_us"), static_cast<qint64>(deviceTimeUs));
    if (!client.isEmpty())
        o.insert(QStringLiteral("client"), client);
    return o;
}

QString eventKindKey(dev::proto::EventKind kind)
{
    QString k = QString::fromLatin1(dev::proto::eventKindName(kind)).toLower();
    k.replace(QLatin1Char(' '), QLatin1Char('_'));
    k.replace(QLatin1Char('-'), QString());
    return k;
}

EventJournal::EventJournal(QObject* parent) : QObject(parent) {}

void EventJournal::watch(const QString& source, dev::Instrument* instrument)
{
    connect(instrument, &dev::Instrument::eventReceived, this, [this, source, instrument](const dev::DeviceEvent& e) {
        using K = dev::proto::EventKind;
        JournalEntry j;
        j.hostTime = e.hostTime.isValid() ? e.hostTime : QDateTime::currentDateTime();
        j.deviceTimeUs = e.deviceTimeUs;
        j.source = source;
        j.kind = eventKindKey(e.kind);
        const auto& axes = instrument->identity().axes;
        const QString axis = e.axis >= 0 && e.axis < axes.size() ? QString(axes[e.axis].letter) : QString();
        j.text = axis.isEmpty() ? e.text : QStringLiteral("%1: %2").arg(axis, e.text);
        j.problem = e.kind == K::LimitHit || e.kind == K::Fault || e.kind == K::EStop || e.kind == K::LostSteps
            || e.kind == K::JogExpired || e.kind == K::PathAborted;
        add(j);
    });
    connect(instrument, &dev::Instrument::stateChanged, this, [this, source](dev::LinkState st) {
        JournalEntry j;
        j.hostTime = QDateTime::currentDateTime();
        j.source = source;
        j.kind = QStringLiteral("link");
        j.text = QString::fromLatin1(dev::linkStateKey(st));
        j.problem = st == dev::LinkState::Lost;
        add(j);
    });
    connect(instrument, &dev::Instrument::requestFailed, this, [this, source](const dev::RequestError& e) {
        JournalEntry j;
        j.hostTime = QDateTime::currentDateTime();
        j.source = source;
        j.kind = QStringLiteral("refused");
        j.text = ui::words::englishText(e.message);  // the API speaks English whatever the screens do
        j.problem = true;
        add(j);
    });
}

void EventJournal::add(JournalEntry entry)
{
    entry.seq = m_nextSeq++;
    if (!entry.hostTime.isValid())
        entry.hostTime = QDateTime::currentDateTime();
    m_entries.push_back(entry);
    while (m_entries.size() > static_cast<std::size_t>(kCapacity))
        m_entries.pop_front();
    emit added(m_entries.back());
}

} // namespace app::api
