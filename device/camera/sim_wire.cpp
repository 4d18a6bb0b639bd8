#include "device/camera/sim_wire.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

#include <cmath>
#include <cstring>

namespace dev::camera {

namespace {

namespace m = motion::msg;

QJsonObject wireHeader(const char* type)
{
    return QJsonObject{{QStringLiteral("schema"), QLatin1String(kSimWireSchema)},
                       {QStringLiteral("version"), kSimWireVersion},
                       {QStringLiteral("type"), QLatin1String(type)}};
}

std::string line(const QJsonObject& o) { return QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString() + '\n'; }

QJsonObject geometryJson(const CameraGeometry& g)
{
    return QJsonObject{{QStringLiteral("width_px"), g.sensorWidthPx},   {QStringLiteral("height_px"), g.sensorHeightPx},
                       {QStringLiteral("pixel_um"), g.pixelUm},         {QStringLiteral("rotation_deg"), g.rotationDeg},
                       {QStringLiteral("image_y"), g.imageYAlongMinusY ? QStringLiteral("-y") : QStringLiteral("+y")}};
}

const char* formatName(PixelFormat f)
{
    switch (f) {
    case PixelFormat::Grey8: return "grey8";
    case PixelFormat::Grey16: return "grey16";
    case PixelFormat::Rgb8: return "rgb8";
    }
    return "grey8";
}

/// Reads the checked fields of one header; the first field at fault is kept.
class WireFields {
public:
    WireFields(const QJsonObject& o, std::string prefix = {}) : m_o(o), m_prefix(std::move(prefix)) {}

    bool has(const char* key) const { return m_o.contains(QLatin1String(key)); }
    double number(const char* key, double lo, double hi)
    {
        const QJsonValue v = m_o.value(QLatin1String(key));
        const double d = v.toDouble(std::nan(""));
        if (v.isDouble() && std::isfinite(d) && d >= lo && d <= hi)
            return d;
        bad(key);
        return lo;
    }
    std::uint64_t whole(const char* key, double lo, double hi)
    {
        const double d = number(key, lo, hi);
        if (std::floor(d) == d)
            return static_cast<std::uint64_t>(d);
        bad(key);
        return 0;
    }
    int side(const char* key) { return static_cast<int>(whole(key, 1, kSimWireMaxSidePx)); }
    std::string text(const char* key, int maxChars)
    {
        const QJsonValue v = m_o.value(QLatin1String(key));
        if (v.isString() && v.toString().size() <= maxChars)
            return v.toString().toStdString();
        bad(key);
        return {};
    }
    QJsonObject object(const char* key)
    {
        const QJsonValue v = m_o.value(QLatin1String(key));
        if (!v.isObject())
            bad(key);
        return v.toObject();
    }
    CameraGeometry geometry()
    {
        CameraGeometry g;
        g.sensorWidthPx = side("width_px");
        g.sensorHeightPx = side("height_px");
        g.pixelUm = number("pixel_um", 0, kSimWireMaxPixelUm);
        if (m_ok && !(g.pixelUm > 0))
            bad("pixel_um");
        g.rotationDeg = number("rotation_deg", -360, 360);
        const std::string y = text("image_y", 2);
        if (m_ok && y != "-y" && y != "+y")
            bad("image_y");
        g.imageYAlongMinusY = y == "-y";
        return g;
    }
    void bad(const char* key)
    {
        if (m_ok)
            m_field = m_prefix + key;
        m_ok = false;
    }
    bool ok() const { return m_ok; }
    const std::string& field() const { return m_field; }
    /// Carries a nested object's verdict up.
    void take(const WireFields& inner)
    {
        if (m_ok && !inner.ok()) {
            m_ok = false;
            m_field = inner.field();
        }
    }

private:
    QJsonObject m_o;
    std::string m_prefix;
    bool m_ok = true;
    std::string m_field;
};

} // namespace

std::string encodeSimWire(const SimWireHello& h)
{
    QJsonObject o = wireHeader("hello");
    o.insert(QStringLiteral("specimen"), QString::fromStdString(h.specimen));
    o.insert(QStringLiteral("seed"), static_cast<double>(h.seed));
    o.insert(QStringLiteral("camera"), geometryJson(h.geometry));
    return line(o);
}

std::string encodeSimWire(const SimWireCapture& c)
{
    QJsonObject o = wireHeader("capture");
    o.insert(QStringLiteral("id"), static_cast<double>(c.id));
    o.insert(QStringLiteral("exposure_ms"), c.exposureMs);
    if (c.geometry)
        o.insert(QStringLiteral("camera"), geometryJson(*c.geometry));
    return line(o);
}

std::string encodeSimWire(const SimWireFrame& fr)
{
    const Frame& f = fr.frame;
    QJsonObject o = wireHeader("frame");
    o.insert(QStringLiteral("id"), static_cast<double>(fr.id));
    o.insert(QStringLiteral("width_px"), f.width);
    o.insert(QStringLiteral("height_px"), f.height);
    o.insert(QStringLiteral("format"), QLatin1String(formatName(f.format)));
    o.insert(QStringLiteral("bit_depth"), f.bitDepth);
    o.insert(QStringLiteral("exposure_ms"), f.exposureMs);
    o.insert(QStringLiteral("pixel_um"), f.pixelUm);
    o.insert(QStringLiteral("sequence"), static_cast<double>(f.sequence));
    if (f.deviceTimeUs)
        o.insert(QStringLiteral("device_time_us"), static_cast<double>(*f.deviceTimeUs));
    if (fr.trueXMm && fr.trueYMm)
        o.insert(QStringLiteral("true_mm"), QJsonArray{*fr.trueXMm, *fr.trueYMm});
    o.insert(QStringLiteral("bytes"), static_cast<double>(f.pixels.size()));
    std::string out = line(o);
    const std::size_t at = out.size();
    out.resize(at + f.pixels.size());
    if (f.format == PixelFormat::Grey16)
        qToLittleEndian<quint16>(f.pixels.data(), static_cast<qsizetype>(f.pixels.size() / 2), out.data() + at);
    else if (!f.pixels.empty())
        std::memcpy(out.data() + at, f.pixels.data(), f.pixels.size());
    return out;
}

std::string encodeSimWire(const SimWireError& e)
{
    QJsonObject o = wireHeader("error");
    o.insert(QStringLiteral("id"), static_cast<double>(e.id));
    o.insert(QStringLiteral("code"), QString::fromStdString(e.code));
    o.insert(QStringLiteral("detail"), QString::fromStdString(e.detail));
    return line(o);
}

void SimWireReader::feed(const char* data, std::size_t size)
{
    if (broken() || size == 0)
        return;
    m_buf.append(data, size);
}

SimWireReader::Result SimWireReader::breakWith(motion::msg::Message why, motion::msg::Message* error)
{
    m_error = std::move(why);
    m_buf.clear();
    m_pos = 0;
    m_pending.reset();
    *error = m_error;
    return Result::Broken;
}

SimWireReader::Result SimWireReader::next(SimWireMessage* out, motion::msg::Message* error)
{
    if (broken()) {
        *error = m_error;
        return Result::Broken;
    }
    auto compact = [this] {
        // What was read is dropped once it is most of the buffer: each byte is moved at most twice.
        if (m_pos > 0 && m_pos * 2 >= m_buf.size()) {
            m_buf.erase(0, m_pos);
            m_pos = 0;
        }
    };
    if (m_pending) {
        const std::size_t want = m_pendingBytes - m_pending->frame.pixels.size();
        const std::size_t take = std::min(want, m_buf.size() - m_pos);
        m_pending->frame.pixels.insert(m_pending->frame.pixels.end(), m_buf.begin() + static_cast<std::ptrdiff_t>(m_pos),
                                       m_buf.begin() + static_cast<std::ptrdiff_t>(m_pos + take));
        m_pos += take;
        compact();
        if (m_pending->frame.pixels.size() < m_pendingBytes)
            return Result::NeedMore;
        SimWireFrame done = std::move(*m_pending);
        m_pending.reset();
        if (done.frame.format == PixelFormat::Grey16)
            qFromLittleEndian<quint16>(done.frame.pixels.data(), static_cast<qsizetype>(done.frame.pixels.size() / 2), done.frame.pixels.data());
        *out = std::move(done);
        return Result::Message;
    }
    const std::size_t end = m_buf.find('\n', m_pos);
    if (end == std::string::npos) {
        if (m_buf.size() - m_pos >= kSimWireMaxHeaderBytes)
            return breakWith(m::make("camera.wire.header_too_long", {m::integer("max", static_cast<long long>(kSimWireMaxHeaderBytes), m::Unit::Byte)}), error);
        compact();
        return Result::NeedMore;
    }
    if (end + 1 - m_pos > kSimWireMaxHeaderBytes)
        return breakWith(m::make("camera.wire.header_too_long", {m::integer("max", static_cast<long long>(kSimWireMaxHeaderBytes), m::Unit::Byte)}), error);
    const std::string header = m_buf.substr(m_pos, end - m_pos);
    m_pos = end + 1;
    SimWireMessage parsed;
    motion::msg::Message why;
    if (!parseHeader(header, &parsed, &why))
        return breakWith(why, error);
    if (auto* frame = std::get_if<SimWireFrame>(&parsed)) {
        m_pending = std::move(*frame);
        return next(out, error);  // its pixels may be here already
    }
    compact();
    *out = std::move(parsed);
    return Result::Message;
}

bool SimWireReader::parseHeader(const std::string& text, SimWireMessage* out, motion::msg::Message* error)
{
    QJsonParseError pe;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &pe);
    if (pe.error != QJsonParseError::NoError || !doc.isObject()) {
        *error = m::make("camera.wire.not_json", {m::verbatim("detail", pe.error != QJsonParseError::NoError ? pe.errorString().toStdString()
                                                                                                      : std::string("not an object"))});
        return false;
    }
    const QJsonObject o = doc.object();
    WireFields f(o);
    const QJsonValue schema = o.value(QStringLiteral("schema"));
    if (schema.toString() != QLatin1String(kSimWireSchema)) {
        *error = m::make("camera.wire.schema", {m::verbatim("got", schema.isString() ? schema.toString().left(64).toStdString() : std::string("?"))});
        return false;
    }
    const QJsonValue version = o.value(QStringLiteral("version"));
    if (!version.isDouble() || version.toDouble() != kSimWireVersion) {
        *error = m::make("camera.wire.version", {m::verbatim("version", version.isDouble() ? QString::number(version.toDouble()).toStdString() : std::string("?")),
                                                 m::integer("supported", kSimWireVersion, m::Unit::None)});
        return false;
    }
    const std::string type = f.text("type", 16);
    const bool fromServer = m_side == Side::Client;
    if (type == "hello" && fromServer) {
        SimWireHello h;
        h.specimen = f.text("specimen", 64);
        h.seed = f.whole("seed", 0, kSimWireMaxInteger);
        WireFields g(f.object("camera"), "camera.");
        h.geometry = g.geometry();
        f.take(g);
        *out = h;
    } else if (type == "capture" && !fromServer) {
        SimWireCapture c;
        c.id = f.whole("id", 1, kSimWireMaxInteger);
        c.exposureMs = f.number("exposure_ms", 0, kSimWireMaxExposureMs);
        if (f.ok() && !(c.exposureMs > 0))
            f.bad("exposure_ms");
        if (f.has("camera")) {
            WireFields g(f.object("camera"), "camera.");
            c.geometry = g.geometry();
            f.take(g);
        }
        *out = c;
    } else if (type == "frame" && fromServer) {
        SimWireFrame fr;
        fr.id = f.whole("id", 1, kSimWireMaxInteger);
        Frame& fm = fr.frame;
        fm.width = f.side("width_px");
        fm.height = f.side("height_px");
        const std::string format = f.text("format", 8);
        if (format == "grey8")
            fm.format = PixelFormat::Grey8;
        else if (format == "grey16")
            fm.format = PixelFormat::Grey16;
        else if (format == "rgb8")
            fm.format = PixelFormat::Rgb8;
        else
            f.bad("format");
        fm.bitDepth = static_cast<int>(f.whole("bit_depth", 1, fm.format == PixelFormat::Grey16 ? 16 : 8));
        fm.exposureMs = f.number("exposure_ms", 0, kSimWireMaxExposureMs);
        fm.pixelUm = f.number("pixel_um", 0, kSimWireMaxPixelUm);
        fm.sequence = f.whole("sequence", 0, kSimWireMaxInteger);
        if (f.has("device_time_us"))
            fm.deviceTimeUs = f.whole("device_time_us", 0, kSimWireMaxInteger);
        if (f.has("true_mm")) {
            const QJsonArray a = o.value(QStringLiteral("true_mm")).toArray();
            const double x = a.size() == 2 ? a[0].toDouble(std::nan("")) : std::nan("");
            const double y = a.size() == 2 ? a[1].toDouble(std::nan("")) : std::nan("");
            if (!std::isfinite(x) || !std::isfinite(y) || std::fabs(x) > 1e6 || std::fabs(y) > 1e6)
                f.bad("true_mm");
            fr.trueXMm = x;
            fr.trueYMm = y;
        }
        const double bytes = f.number("bytes", 0, kSimWireMaxInteger);
        if (f.ok()) {
            // Each side is bounded, so this product cannot overflow.
            const std::size_t expected = static_cast<std::size_t>(fm.width) * static_cast<std::size_t>(fm.height)
                * static_cast<std::size_t>(bytesPerPixel(fm.format));
            if (bytes != static_cast<double>(expected)) {
                *error = m::make("camera.wire.size", {m::real("bytes", bytes, m::Unit::Byte),
                                                      m::integer("expected", static_cast<long long>(expected), m::Unit::Byte),
                                                      m::integer("width", fm.width, m::Unit::None), m::integer("height", fm.height, m::Unit::None)});
                return false;
            }
            m_pendingBytes = expected;
        }
        *out = std::move(fr);
    } else if (type == "error" && fromServer) {
        SimWireError e;
        e.id = f.whole("id", 0, kSimWireMaxInteger);
        e.code = f.text("code", 64);
        e.detail = f.text("detail", static_cast<int>(kSimWireMaxHeaderBytes));
        *out = e;
    } else if (f.ok()) {
        *error = m::make("camera.wire.unexpected", {m::verbatim("type", type)});
        return false;
    }
    if (!f.ok()) {
        *error = m::make("camera.wire.field", {m::verbatim("field", f.field())});
        return false;
    }
    return true;
}

} // namespace dev::camera
