#include "device/backends/protocol_probe.h"

#include "device/backends/grbl/grbl_protocol.h"

namespace dev {

namespace {

bool grblActsOn(std::uint8_t b) { return dev::grbl::rt::isRealtime(b) || b == '\n' || b == '\r'; }

} // namespace

QByteArray ProtocolProbe::safeHello(std::uint16_t* seqOut)
{
    const dev::proto::Bytes payload = dev::proto::encode(dev::proto::HelloRequest{dev::proto::HelloReadsExtensions});
    // Sequence numbers far from the ones a client starts with (1, 2, …), so a device's
    // retransmission cache never mistakes the client's first HELLO for this one.
    for (std::uint32_t seq = 0x2000; seq < 0x10000; ++seq) {
        std::vector<std::uint8_t> wire;
        dev::proto::encodeFrame(static_cast<std::uint8_t>(dev::proto::MsgType::Hello), static_cast<std::uint16_t>(seq), payload.data(),
                           payload.size(), wire);
        bool clean = true;
        for (const std::uint8_t b : wire)
            clean = clean && !grblActsOn(b);
        if (!clean)
            continue;
        if (seqOut)
            *seqOut = static_cast<std::uint16_t>(seq);
        return QByteArray(reinterpret_cast<const char*>(wire.data()), static_cast<qsizetype>(wire.size()));
    }
    return {};  // never: most sequence numbers give a clean frame (tested)
}

ProtocolProbe::ProtocolProbe(Transport* transport, QObject* parent) : QObject(parent), m_transport(transport)
{
    qRegisterMetaType<dev::ProbeResult>();
    m_timer.setInterval(20);
    connect(&m_timer, &QTimer::timeout, this, &ProtocolProbe::tick);
}

ProtocolProbe::~ProtocolProbe()
{
    for (const auto& c : m_connections)
        disconnect(c);
}

void ProtocolProbe::start()
{
    if (m_started)
        return;
    m_started = true;
    if (!m_transport) {
        ProbeResult r;
        r.error = motion::msg::make("link.no_connection_chosen");
        QTimer::singleShot(0, this, [this, r] { finish(r); });
        return;
    }
    m_connections << connect(m_transport, &Transport::bytesReceived, this, &ProtocolProbe::onBytes);
    m_connections << connect(m_transport, &Transport::failed, this, [this](const motion::msg::Message& why) {
        ProbeResult r;
        r.error = why;
        finish(r);
    });
    m_connections << connect(m_transport, &Transport::lost, this, [this](const motion::msg::Message& why) {
        ProbeResult r;
        r.error = why;
        finish(r);
    });
    if (m_transport->isOpen()) {
        QTimer::singleShot(0, this, &ProtocolProbe::begin);
    } else {
        m_connections << connect(m_transport, &Transport::opened, this, &ProtocolProbe::begin);
        m_transport->open();
    }
}

void ProtocolProbe::begin()
{
    if (m_done || !m_transport)
        return;
    m_clock.start();
    m_lastQueryMs = 0;
    m_transport->write(QByteArray(1, static_cast<char>(dev::grbl::rt::kStatusQuery)));
    m_timer.start();
}

void ProtocolProbe::tick()
{
    if (m_done || !m_transport)
        return;
    const qint64 now = m_clock.elapsed();
    if (now >= (m_heardFrames ? kNoisyTotalMs : kTotalMs)) {
        ProbeResult r;
        const motion::msg::Arg link = motion::msg::verbatim("link", m_transport->describe().toStdString());
        const motion::msg::Arg seconds = motion::msg::real("seconds", (m_heardFrames ? kNoisyTotalMs : kTotalMs) / 1000.0, motion::msg::Unit::S);
        r.error = m_bytes == 0 ? motion::msg::make("grbl.probe.no_answer", {link, seconds})
                               : motion::msg::make("grbl.probe.unreadable",
                                           {link, motion::msg::integer("bytes", static_cast<long long>(m_bytes)), seconds});
        m_transport->close();
        finish(r);
        return;
    }
    if (now >= kGrblFirstMs && (m_lastHelloMs < 0 || now - m_lastHelloMs >= (m_heardFrames ? kNoisyRepeatMs : kRepeatMs))) {
        m_lastHelloMs = now;
        m_transport->write(safeHello(&m_helloSeq));
    }
    if (now - m_lastQueryMs >= kRepeatMs) {
        m_lastQueryMs = now;
        m_transport->write(QByteArray(1, static_cast<char>(dev::grbl::rt::kStatusQuery)));
    }
}

void ProtocolProbe::onBytes(const QByteArray& bytes)
{
    if (m_done)
        return;
    m_bytes += static_cast<quint64>(bytes.size());
    std::vector<dev::grbl::LineReader::Line> lines;
    m_lines.feed(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), lines);
    for (const auto& l : lines) {
        const dev::grbl::Line c = dev::grbl::classifyLine(l.text);
        using K = dev::grbl::LineKind;
        if (c.kind == K::Banner || c.kind == K::Status || c.kind == K::Ok || c.kind == K::Error || c.kind == K::Alarm
            || c.kind == K::Message) {
            ProbeResult r;
            r.protocol = ProbeResult::Protocol::Grbl;
            if (const auto b = dev::grbl::parseBanner(l.text))
                r.found = motion::msg::make("grbl.probe.found_grbl", {motion::msg::verbatim("firmware", b->firmware == dev::grbl::Firmware::GrblHal ? "grblHAL" : "Grbl"),
                                                              motion::msg::verbatim("version", b->version)});
            else
                r.found = motion::msg::make("grbl.probe.found_grbl_unnamed");
            for (const auto& other : lines)
                r.grblBanner = r.grblBanner || dev::grbl::parseBanner(other.text).has_value();
            finish(r);
            return;
        }
    }
    std::vector<dev::proto::Frame> frames;
    m_frames.feed(reinterpret_cast<const std::uint8_t*>(bytes.constData()), static_cast<std::size_t>(bytes.size()), frames);
    // A damaged frame is one with a bad CRC or broken COBS between two delimiters: at 1 % of
    // bytes damaged most HELLO replies arrive so (a dropped or doubled byte breaks the COBS).
    m_heardFrames = m_heardFrames || !frames.empty() || m_frames.stats().crcErrors > 0 || m_frames.stats().malformed > 0;
    for (const auto& f : frames) {
        if (f.type != dev::proto::replyTypeOf(dev::proto::MsgType::Hello) || f.seq != m_helloSeq)
            continue;
        const auto h = dev::proto::decodeHelloReply(f.payload);
        if (!h)
            continue;
        ProbeResult r;
        r.protocol = ProbeResult::Protocol::BenchPilot;
        r.kindKnown = true;
        r.kind = h->kind;
        r.found = motion::msg::make("grbl.probe.found_benchpilot", {motion::msg::integer("version", h->protocolVersion, motion::msg::Unit::None),
                                                             motion::msg::term("instrument", h->kind == dev::proto::DeviceKind::Stage ? "instrument.stage"
                                                                                                                         : "instrument.analyzer")});
        finish(r);
        return;
    }
}

void ProtocolProbe::finish(ProbeResult r)
{
    if (m_done)
        return;
    m_done = true;
    m_timer.stop();
    for (const auto& c : m_connections)
        disconnect(c);
    m_connections.clear();
    m_result = std::move(r);
    emit finished(m_result);
}

} // namespace dev
