#include "device/link/gauge_link.h"

#include "device/link/gauge_dialect.h"

#include <utility>

namespace dev {

GaugeLink::GaugeLink(Transport* transport, QString port, QObject* parent)
    : QObject(parent), m_transport(transport), m_port(std::move(port))
{
    m_timer.setSingleShot(true);
    connect(&m_timer, &QTimer::timeout, this, [this] {
        if (!m_pending)
            return;
        if (!m_line.isEmpty() || m_overlong) {
            // It said something, never ended the line: that is its answer, and not a reading.
            finish(std::nullopt, motion::msg::make("gauge.not_a_reading", {motion::msg::verbatim("port", m_port.toStdString()),
                                                                  motion::msg::verbatim("text", dev::gaugewire::printable(m_line.toStdString()))}));
            return;
        }
        if (m_attemptsLeft > 0) {
            sendRequest();
            return;
        }
        finish(std::nullopt, motion::msg::make("gauge.no_answer", {motion::msg::verbatim("port", m_port.toStdString()),
                                                          motion::msg::real("timeout", m_timeoutMs * 1e-3, motion::msg::Unit::S)}));
    });
    if (!m_transport)
        return;
    m_connections << connect(m_transport, &Transport::bytesReceived, this, &GaugeLink::onBytes);
    m_connections << connect(m_transport, &Transport::opened, this, [this] {
        if (auto done = std::exchange(m_opening, {}))
            done({});
    });
    m_connections << connect(m_transport, &Transport::failed, this, [this](const motion::msg::Message& why) {
        if (auto done = std::exchange(m_opening, {}))
            done(motion::msg::make("gauge.port_failed", {motion::msg::verbatim("port", m_port.toStdString()), motion::msg::nested("detail", why)}));
    });
    m_connections << connect(m_transport, &Transport::lost, this, [this](const motion::msg::Message& why) {
        if (m_pending)
            finish(std::nullopt, motion::msg::make("gauge.link_lost", {motion::msg::verbatim("port", m_port.toStdString()), motion::msg::nested("detail", why)}));
    });
}

GaugeLink::~GaugeLink()
{
    for (const auto& c : m_connections)
        disconnect(c);
}

void GaugeLink::open(OpenDone done)
{
    if (!m_transport) {
        done(motion::msg::make("gauge.no_transport", {motion::msg::verbatim("port", m_port.toStdString())}));
        return;
    }
    if (m_transport->isOpen()) {
        done({});
        return;
    }
    m_opening = std::move(done);
    m_transport->open();
}

void GaugeLink::close()
{
    cancel();
    if (m_transport && m_transport->isOpen())
        m_transport->close();
}

bool GaugeLink::isOpen() const { return m_transport && m_transport->isOpen(); }

void GaugeLink::read(ReadDone done)
{
    if (m_pending) {
        done(std::nullopt, motion::msg::make("gauge.busy", {motion::msg::verbatim("port", m_port.toStdString())}));
        return;
    }
    if (!isOpen()) {
        done(std::nullopt, motion::msg::make("gauge.not_open", {motion::msg::verbatim("port", m_port.toStdString())}));
        return;
    }
    m_pending = std::move(done);
    m_attemptsLeft = m_attempts;
    sendRequest();
}

void GaugeLink::cancel()
{
    m_pending = {};
    m_timer.stop();
}

void GaugeLink::sendRequest()
{
    --m_attemptsLeft;
    // What arrived before this request is stale: an answer to a request that timed
    // out, or a line the gauge sent by itself.
    m_line.clear();
    m_overlong = false;
    m_transport->write(QByteArray(dev::gaugewire::kRequest));
    m_timer.start(m_timeoutMs);
}

void GaugeLink::onBytes(const QByteArray& bytes)
{
    for (char c : bytes) {
        if (c == '\r' || c == '\n') {
            const QByteArray line = std::exchange(m_line, {});
            const bool overlong = std::exchange(m_overlong, false);
            if (!m_pending || (line.isEmpty() && !overlong))
                continue;  // nothing asked, or the LF of a CR LF
            if (overlong) {
                finish(std::nullopt, motion::msg::make("gauge.not_a_reading", {motion::msg::verbatim("port", m_port.toStdString()),
                                                                      motion::msg::verbatim("text", dev::gaugewire::printable(line.toStdString()))}));
                continue;
            }
            const auto a = dev::gaugewire::parseAnswer(std::string_view(line.constData(), static_cast<std::size_t>(line.size())),
                                                  m_port.toStdString());
            finish(a.valueMm, a.problem);
            continue;
        }
        if (static_cast<std::size_t>(m_line.size()) >= dev::gaugewire::kMaxAnswerBytes) {
            m_overlong = true;  // keeps the start for the message, drops the rest up to the line end
            continue;
        }
        m_line.append(c);
    }
}

void GaugeLink::finish(std::optional<double> value, const motion::msg::Message& problem)
{
    m_timer.stop();
    if (auto done = std::exchange(m_pending, {}))
        done(value, problem);
}

} // namespace dev
