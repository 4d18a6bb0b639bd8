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

std::vector<UvcFormat> uvcFormatsOf(const QCameraDevice& device)
{
    std::vector<UvcFormat> out;
    for (const QCameraFormat& f : device.videoFormats())
        out.push_back({f.resolution(), f.pixelFormat(), f.minFrameRate(), f.maxFrameRate(), isAcceptedVideoFormat(f.pixelFormat())});
    return out;
}

std::vector<UvcDevice> listUvcCameras()
{
    std::vector<UvcDevice> out;
    const auto found = QMediaDevices::videoInputs();
    for (const QCameraDevice& d : found)
        out.push_back({d.description(), QString::fromUtf8(d.id()), d.isDefault(), uvcFormatsOf(d)});
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

int chooseUvcFormat(const std::vector<UvcFormat>& formats, std::optional<QSize> size)
{
    auto area = [](const QSize& s) { return static_cast<qint64>(s.width()) * s.height(); };
    auto better = [&](const UvcFormat& a, const UvcFormat& b) {
        if (area(a.size) != area(b.size))
            return area(a.size) > area(b.size);
        const bool aJpeg = a.pixelFormat == QVideoFrameFormat::Format_Jpeg, bJpeg = b.pixelFormat == QVideoFrameFormat::Format_Jpeg;
        if (aJpeg != bJpeg)
            return !aJpeg;
        return a.maxFps > b.maxFps;
    };
    int best = -1;
    for (int i = 0; i < static_cast<int>(formats.size()); ++i) {
        const UvcFormat& f = formats[static_cast<std::size_t>(i)];
        if (!isAcceptedVideoFormat(f.pixelFormat) || (size && f.size != *size))
            continue;
        if (best < 0 || better(f, formats[static_cast<std::size_t>(best)]))
            best = i;
    }
    return best;
}

QCameraFormat chooseUvcFormat(const QCameraDevice& device, std::optional<QSize> size)
{
    const int i = chooseUvcFormat(uvcFormatsOf(device), size);
    return i < 0 ? QCameraFormat() : device.videoFormats().at(i);
}

std::string uvcSizesText(const std::vector<UvcFormat>& formats)
{
    std::vector<QSize> sizes;
    for (const UvcFormat& f : formats)
        if (isAcceptedVideoFormat(f.pixelFormat) && std::find(sizes.begin(), sizes.end(), f.size) == sizes.end())
            sizes.push_back(f.size);
    auto area = [](const QSize& s) { return static_cast<qint64>(s.width()) * s.height(); };
    std::stable_sort(sizes.begin(), sizes.end(), [&](const QSize& a, const QSize& b) { return area(a) > area(b); });
    QStringList parts;
    for (const QSize& s : sizes)
        parts << QStringLiteral("%1×%2").arg(s.width()).arg(s.height());
    return parts.join(QStringLiteral(", ")).toStdString();
}

std::string uvcSizesText(const QCameraDevice& device) { return uvcSizesText(uvcFormatsOf(device)); }

} // namespace dev::camera
