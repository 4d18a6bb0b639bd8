#include "device/link/loopback.h"

#include <QCoreApplication>

#include <algorithm>

namespace dev {

class LoopbackEnd final : public Transport {
public:
    LoopbackEnd(LoopbackPair* pair, int side) : Transport(pair), m_pair(pair), m_side(side) {}
    void open() override
    {
        QTimer::singleShot(0, this, [this] {
            if (m_pair->m_unplugged) {
                emit failed(motion::msg::make("link.cable_unplugged"));
                return;
            }
            m_open = true;
            emit opened();
            m_pair->peerOpenedBy(m_side);
        });
    }
    void close() override { m_open = false; }
    bool isOpen() const override { return m_open; }
    void write(const QByteArray& bytes) override
    {
        if (m_open && !m_pair->m_unplugged)
            m_pair->transmit(m_side, bytes, true);
    }
    QString describe() const override
    {
        // Not a Q_OBJECT: its own tr() would look in Transport's context, not the one
        // lupdate files these under.
        return m_pair->m_baud > 0 ? QCoreApplication::translate("dev::LoopbackEnd", "loopback @ %1 baud").arg(m_pair->m_baud)
                                  : QCoreApplication::translate("dev::LoopbackEnd", "loopback");
    }
    void sayPeerOpened()
    {
        if (m_open)
            emit peerOpened();
    }
    void deliver(const QByteArray& bytes)
    {
        if (m_open)
            emit bytesReceived(bytes);
    }
    void drop(const motion::msg::Message& why)
    {
        if (!m_open)
            return;
        m_open = false;
        emit lost(why);
    }

private:
    LoopbackPair* m_pair;
    int m_side;
    bool m_open = false;
};

LoopbackPair::LoopbackPair(qint32 baud, QObject* parent) : QObject(parent), m_baud(baud)
{
    m_ends[0] = new LoopbackEnd(this, 0);
    m_ends[1] = new LoopbackEnd(this, 1);
    m_clock.start();
    m_timer.setSingleShot(true);
    m_timer.setTimerType(Qt::PreciseTimer);
    connect(&m_timer, &QTimer::timeout, this, &LoopbackPair::deliverDue);
}

LoopbackPair::~LoopbackPair() = default;

Transport* LoopbackPair::end(Side side) { return m_ends[side]; }

void LoopbackPair::peerOpenedBy(int side) { static_cast<LoopbackEnd*>(m_ends[1 - side])->sayPeerOpened(); }

void LoopbackPair::unplug()
{
    m_unplugged = true;
    m_pending.clear();
    for (auto* e : m_ends)
        static_cast<LoopbackEnd*>(e)->drop(motion::msg::make("link.cable_pulled"));
}

void LoopbackPair::hang(int ms)
{
    m_hungUntilNs = std::max(m_hungUntilNs, m_clock.nsecsElapsed() + qint64(ms) * 1000000);
}

void LoopbackPair::transmit(int from, const QByteArray& input, bool applyFaults)
{
    if (applyFaults && hung())
        return;
    std::int64_t extra = 0;
    const QByteArray bytes = applyFaults ? m_lines[from].spoil(input, &extra) : input;
    if (bytes.isEmpty())
        return;
    m_carried[from] += bytes.size();
    const qint64 now = m_clock.nsecsElapsed();
    const int to = 1 - from;
    if (m_baud <= 0) {
        const qint64 due = std::max(now + extra, m_lastDueNs[from]);
        m_lastDueNs[from] = due;
        m_pending.push_back({due, to, bytes});
    } else {
        // Pace in small pieces so a long burst trickles in as it would off a UART.
        const auto byteNs = static_cast<qint64>(10e9 / (static_cast<double>(m_baud) * m_timeScale));
        qint64 t = std::max(now, m_lineFreeNs[from]);
        for (int i = 0; i < bytes.size(); i += 32) {
            const QByteArray piece = bytes.mid(i, 32);
            t += byteNs * piece.size();
            const qint64 due = std::max(t + extra, m_lastDueNs[from]);
            m_lastDueNs[from] = due;
            m_pending.push_back({due, to, piece});
        }
        m_lineFreeNs[from] = t;
    }
    std::stable_sort(m_pending.begin(), m_pending.end(), [](const Pending& a, const Pending& b) { return a.dueNs < b.dueNs; });
    schedule();
}

void LoopbackPair::schedule()
{
    if (m_pending.empty())
        return;
    const qint64 waitNs = m_pending.front().dueNs - m_clock.nsecsElapsed();
    const int ms = waitNs <= 0 ? 0 : static_cast<int>((waitNs + 999999) / 1000000);
    if (!m_timer.isActive() || m_timer.remainingTime() > ms)
        m_timer.start(ms);
}

void LoopbackPair::deliverDue()
{
    const qint64 now = m_clock.nsecsElapsed();
    QByteArray out[2];
    while (!m_pending.empty() && m_pending.front().dueNs <= now) {
        out[m_pending.front().to] += m_pending.front().bytes;
        m_pending.pop_front();
    }
    for (int side = 0; side < 2; ++side)
        if (!out[side].isEmpty())
            static_cast<LoopbackEnd*>(m_ends[side])->deliver(out[side]);
    schedule();
}

} // namespace dev
