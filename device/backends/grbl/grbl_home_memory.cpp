#include "device/backends/grbl/grbl_home_memory.h"

#include "device/files/text_file.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

#include <algorithm>
#include <cmath>

namespace dev {

namespace {

/// Positions beyond this are no machine's: an entry holding one is damaged.
constexpr double kHomeMaxAbsMm = 1e6;

QJsonArray homeNumbers(const std::vector<double>& v)
{
    QJsonArray a;
    for (const double x : v)
        a.append(x);
    return a;
}

std::optional<std::vector<double>> homeNumbersFrom(const QJsonValue& v)
{
    if (!v.isArray())
        return std::nullopt;
    std::vector<double> out;
    for (const QJsonValue& x : v.toArray()) {
        if (!x.isDouble() || !std::isfinite(x.toDouble()) || std::fabs(x.toDouble()) > kHomeMaxAbsMm)
            return std::nullopt;
        out.push_back(x.toDouble());
    }
    if (out.empty() || out.size() > 6)
        return std::nullopt;
    return out;
}

} // namespace

QString GrblHomeMemory::defaultPath()
{
    return QDir(QDir(QStandardPaths::writableLocation(QStandardPaths::GenericDataLocation)).filePath(QStringLiteral("BenchPilot")))
        .filePath(QStringLiteral("grbl-homes.json"));
}

std::string GrblHomeMemory::serialize(const std::vector<GrblHome>& homes)
{
    QJsonArray list;
    for (const GrblHome& h : homes) {
        QJsonObject o;
        o.insert(QStringLiteral("controller"), QString::fromStdString(h.controller));
        o.insert(QStringLiteral("axes"), QString::fromStdString(h.axes));
        o.insert(QStringLiteral("g54_mm"), homeNumbers(h.g54Mm));
        o.insert(QStringLiteral("machine_mm"), homeNumbers(h.machineMm));
        list.append(o);
    }
    QJsonObject root;
    root.insert(QStringLiteral("schema"), QString::fromLatin1(kSchema));
    root.insert(QStringLiteral("version"), kVersion);
    root.insert(QStringLiteral("controllers"), list);
    return QJsonDocument(root).toJson(QJsonDocument::Indented).toStdString();
}

std::vector<GrblHome> GrblHomeMemory::parse(const std::string& text)
{
    std::vector<GrblHome> out;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text));
    const QJsonObject root = doc.object();
    if (root.value(QStringLiteral("schema")).toString() != QLatin1String(kSchema) || root.value(QStringLiteral("version")).toInt(-1) != kVersion)
        return out;
    for (const QJsonValue& v : root.value(QStringLiteral("controllers")).toArray()) {
        const QJsonObject o = v.toObject();
        GrblHome h;
        h.controller = o.value(QStringLiteral("controller")).toString().toStdString();
        h.axes = o.value(QStringLiteral("axes")).toString().toStdString();
        const auto g54 = homeNumbersFrom(o.value(QStringLiteral("g54_mm")));
        const auto machine = homeNumbersFrom(o.value(QStringLiteral("machine_mm")));
        const bool lettersOk = !h.axes.empty() && h.axes.size() <= 6
                               && std::all_of(h.axes.begin(), h.axes.end(), [](char c) { return std::string("XYZABC").find(c) != std::string::npos; });
        if (h.controller.empty() || !lettersOk || !g54 || !machine || g54->size() != machine->size())
            continue;  // a damaged entry: as if never remembered
        h.g54Mm = *g54;
        h.machineMm = *machine;
        out.push_back(std::move(h));
        if (out.size() >= kMaxControllers)
            break;
    }
    return out;
}

std::vector<GrblHome> GrblHomeMemory::readAll() const
{
    if (m_path.isEmpty() || !QFileInfo::exists(m_path))
        return {};
    std::string text;
    QString error;
    if (!dev::files::readText(m_path, &text, &error, 1024 * 1024))
        return {};
    return parse(text);
}

bool GrblHomeMemory::writeAll(const std::vector<GrblHome>& homes) const
{
    if (m_path.isEmpty())
        return false;
    QDir().mkpath(QFileInfo(m_path).absolutePath());
    QString error;
    return dev::files::writeAtomically(m_path, serialize(homes), &error);
}

std::optional<GrblHome> GrblHomeMemory::recall(const std::string& controller) const
{
    for (GrblHome& h : readAll())
        if (h.controller == controller)
            return std::move(h);
    return std::nullopt;
}

bool GrblHomeMemory::remember(const GrblHome& home) const
{
    std::vector<GrblHome> homes = readAll();
    homes.erase(std::remove_if(homes.begin(), homes.end(), [&](const GrblHome& h) { return h.controller == home.controller; }), homes.end());
    homes.push_back(home);  // the newest last
    if (homes.size() > kMaxControllers)
        homes.erase(homes.begin(), homes.begin() + static_cast<std::ptrdiff_t>(homes.size() - kMaxControllers));
    return writeAll(homes);
}

bool GrblHomeMemory::forget(const std::string& controller) const
{
    std::vector<GrblHome> homes = readAll();
    const auto before = homes.size();
    homes.erase(std::remove_if(homes.begin(), homes.end(), [&](const GrblHome& h) { return h.controller == controller; }), homes.end());
    return homes.size() == before || writeAll(homes);
}

} // namespace dev
