#pragma once
// A camera for the GUI tests: opens at once (answering on the event loop, as the
// interface asks), sends the frames a test pushes as live frames, and answers a capture
// with the frame set for it. Frames of a known make: a texture blurred as asked, and a
// 16-bit ramp whose percentiles are known.
#include "device/camera/camera.h"

#include <QMetaObject>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace guitest {

class FakeCamera : public dev::camera::Camera {
public:
    explicit FakeCamera(QString source = QStringLiteral("sim"), QObject* parent = nullptr) : Camera(parent), m_source(std::move(source)) {}
    QString source() const override { return m_source; }
    dev::camera::Capabilities capabilities() const override { return {true, true, false, false}; }
    void open() override
    {
        QMetaObject::invokeMethod(this, [this] {
            m_open = true;
            emit opened();
        }, Qt::QueuedConnection);
    }
    void close() override
    {
        m_open = false;
        emit closed();
    }
    bool isOpen() const override { return m_open; }
    void startLive() override { m_live = true; }
    void stopLive() override { m_live = false; }
    void setExposureMs(double ms) override { m_exposureMs = ms; }
    double exposureMs() const override { return m_exposureMs; }
    void capture(const dev::camera::CaptureRequest& request) override
    {
        lastRequest = request;
        QMetaObject::invokeMethod(this, [this, id = request.id] { emit captured(id, captureFrame); }, Qt::QueuedConnection);
    }
    void push(const dev::camera::Frame& frame) { emit liveFrame(frame); }
    bool live() const { return m_live; }

    dev::camera::Frame captureFrame;
    dev::camera::CaptureRequest lastRequest;

private:
    QString m_source;
    bool m_open = false;
    bool m_live = false;
    double m_exposureMs = 10;
};

/// A grey 16-bit texture (squares of several sizes), box-blurred `blurPx` times over.
inline dev::camera::Frame texture(int width, int height, int blurPx, std::uint64_t sequence = 1)
{
    std::vector<double> v(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            v[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                ((x / 4 + y / 4) % 2) * 0.5 + ((x / 13 + y / 7) % 2) * 0.3 + ((x / 37) % 2) * 0.2;
    for (int pass = 0; pass < blurPx; ++pass) {
        std::vector<double> out(v.size());
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                double sum = 0;
                int n = 0;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int xx = x + dx, yy = y + dy;
                        if (xx >= 0 && yy >= 0 && xx < width && yy < height) {
                            sum += v[std::size_t(yy) * std::size_t(width) + std::size_t(xx)];
                            ++n;
                        }
                    }
                out[std::size_t(y) * std::size_t(width) + std::size_t(x)] = sum / n;
            }
        v.swap(out);
    }
    dev::camera::Frame f;
    f.width = width;
    f.height = height;
    f.format = dev::camera::PixelFormat::Grey16;
    f.bitDepth = 16;
    f.sequence = sequence;
    f.pixels.resize(v.size() * 2);
    for (std::size_t i = 0; i < v.size(); ++i) {
        const auto level = std::uint16_t(std::lround(2000 + v[i] * 30000));
        std::memcpy(&f.pixels[2 * i], &level, 2);
    }
    return f;
}

/// A 16-bit frame whose pixel i (row-major) has level `offset + i`.
inline dev::camera::Frame ramp16(int width, int height, int offset)
{
    dev::camera::Frame f;
    f.width = width;
    f.height = height;
    f.format = dev::camera::PixelFormat::Grey16;
    f.bitDepth = 16;
    f.pixels.resize(std::size_t(width) * std::size_t(height) * 2);
    for (int i = 0; i < width * height; ++i) {
        const auto level = std::uint16_t(offset + i);
        std::memcpy(&f.pixels[2 * std::size_t(i)], &level, 2);
    }
    return f;
}

} // namespace guitest
