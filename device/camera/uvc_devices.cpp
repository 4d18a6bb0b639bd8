#include "device/camera/uvc_devices.h"

#include "device/camera/video_frame_convert.h"

#include <QMediaDevices>
#include <QRegularExpression>

#include <algorithm>

namespace dev::camera {

UvcName parseUvcName(const QString& text)
{
    UvcName out;
    out.camera = text.trimmed();
    static const QRegularExpression kSize(QStringLiteral("^(.*)@\\s*(\\d{1,5})\\s*[xX×]\\s*(\\d{1,5})\\s*$"));
    const auto m = kSize.match(out.camera);
    if (m.hasMatch()) {
        out.camera = m.captured(1).trimmed();
        out.size = QSize(m.captured(2).toInt(), m.captured(3).toInt());
    }
    return out;
}

std::vector<UvcDevice> listUvcCameras()
{
    std::vector<UvcDevice> out;
    const auto found = QMediaDevices::videoInputs();
    for (const QCameraDevice& d : found) {
        UvcDevice u;
        u.name = d.description();
        u.id = QString::fromUtf8(d.id());
        u.isDefault = d.isDefault();
        for (const QCameraFormat& f : d.videoFormats())
            u.formats.push_back({f.resolution(), f.pixelFormat(), f.minFrameRate(), f.maxFrameRate(), isAcceptedVideoFormat(f.pixelFormat())});
        out.push_back(std::move(u));
    }
    return out;
}

motion::msg::Checked<QCameraDevice> findUvcCamera(const QString& name, const QList<QCameraDevice>& found)
{
    using Result = motion::msg::Checked<QCameraDevice>;
    const std::string asked = name.isEmpty() ? std::string("uvc") : ("uvc:" + name.toStdString());
    if (found.isEmpty())
        return Result::fail(motion::msg::make("camera.uvc.none_found", {motion::msg::verbatim("source", asked)}));
    if (name.isEmpty()) {
        for (const QCameraDevice& d : found)
            if (d.isDefault())
                return Result::ok(d);
        return Result::ok(found.front());
    }
    for (const QCameraDevice& d : found)
        if (d.description().compare(name, Qt::CaseInsensitive) == 0 || QString::fromUtf8(d.id()) == name)
            return Result::ok(d);
    QStringList names;
    for (const QCameraDevice& d : found)
        names << QStringLiteral("%1 (%2)").arg(d.description(), QString::fromUtf8(d.id()));
    return Result::fail(motion::msg::make("camera.uvc.not_found", {motion::msg::verbatim("source", asked),
                                                                   motion::msg::verbatim("found", names.join(QStringLiteral(", ")).toStdString())}));
}

QCameraFormat chooseUvcFormat(const QCameraDevice& device, std::optional<QSize> size)
{
    QCameraFormat best;
    auto area = [](const QSize& s) { return static_cast<qint64>(s.width()) * s.height(); };
    auto better = [&](const QCameraFormat& a, const QCameraFormat& b) {
        if (b.isNull())
            return true;
        if (area(a.resolution()) != area(b.resolution()))
            return area(a.resolution()) > area(b.resolution());
        const bool aJpeg = a.pixelFormat() == QVideoFrameFormat::Format_Jpeg, bJpeg = b.pixelFormat() == QVideoFrameFormat::Format_Jpeg;
        if (aJpeg != bJpeg)
            return !aJpeg;
        return a.maxFrameRate() > b.maxFrameRate();
    };
    for (const QCameraFormat& f : device.videoFormats()) {
        if (!isAcceptedVideoFormat(f.pixelFormat()) || (size && f.resolution() != *size))
            continue;
        if (better(f, best))
            best = f;
    }
    return best;
}

std::string uvcSizesText(const QCameraDevice& device)
{
    auto key = [](const QSize& s) { return std::make_pair(-static_cast<qint64>(s.width()) * s.height(), s.width()); };
    std::vector<QSize> sizes;
    for (const QCameraFormat& f : device.videoFormats())
        if (isAcceptedVideoFormat(f.pixelFormat()) && std::find(sizes.begin(), sizes.end(), f.resolution()) == sizes.end())
            sizes.push_back(f.resolution());
    std::sort(sizes.begin(), sizes.end(), [&](const QSize& a, const QSize& b) { return key(a) < key(b); });
    QStringList parts;
    for (const QSize& s : sizes)
        parts << QStringLiteral("%1×%2").arg(s.width()).arg(s.height());
    return parts.join(QStringLiteral(", ")).toStdString();
}

} // namespace dev::camera
