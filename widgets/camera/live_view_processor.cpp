#include "widgets/camera/live_view_processor.h"

#include "device/camera/focus_measure.h"

#include <memory>

namespace ui {

LiveViewProcessor::LiveViewProcessor(QObject* parent) : QObject(parent)
{
    m_pool.setMaxThreadCount(1);  // frames are taken one at a time: two at once would only finish out of order
    m_pool.setExpiryTimeout(-1);
}

LiveViewProcessor::~LiveViewProcessor() { m_pool.waitForDone(); }

void LiveViewProcessor::submit(const dev::camera::Frame& frame)
{
    ++m_submitted;
    if (!m_busy) {
        start(frame);
        return;
    }
    if (m_waiting)
        ++m_dropped;
    m_waiting = frame;
}

void LiveViewProcessor::start(dev::camera::Frame frame)
{
    m_busy = true;
    auto owned = std::make_shared<const dev::camera::Frame>(std::move(frame));
    const bool autoContrast = m_autoContrast;
    const QSize target = m_target;
    m_pool.start([this, owned, autoContrast, target] {
        ProcessedFrame result = process(*owned, autoContrast, target);
        // Back on the GUI thread; dropped unseen if this object is gone by then.
        QMetaObject::invokeMethod(this, [this, result] { finish(result); }, Qt::QueuedConnection);
    });
}

void LiveViewProcessor::finish(const ProcessedFrame& result)
{
    m_busy = false;
    ++m_processed;
    if (m_waiting) {
        dev::camera::Frame next = std::move(*m_waiting);
        m_waiting.reset();
        start(std::move(next));
    }
    emit ready(result);
}

ProcessedFrame LiveViewProcessor::process(const dev::camera::Frame& frame, bool autoContrast, const QSize& target)
{
    ProcessedFrame out;
    out.frameSize = QSize(frame.width, frame.height);
    out.pixelUm = frame.pixelUm;
    out.sequence = frame.sequence;
    out.colour = frame.format == dev::camera::PixelFormat::Rgb8;
    out.bitDepth = frame.format == dev::camera::PixelFormat::Grey16 ? frame.bitDepth : 8;
    const int bpp = dev::camera::bytesPerPixel(frame.format);
    if (frame.isEmpty() || frame.pixels.size() < std::size_t(frame.width) * std::size_t(frame.height) * std::size_t(bpp))
        return out;  // a short buffer is not read past its end
    const QImage shown = dev::camera::toDisplayImage(frame, autoContrast, &out.stretch);
    if (shown.isNull())
        return out;
    out.focus = dev::camera::focusMeasure(frame);
    if (target.isValid() && !target.isEmpty() && (shown.width() > target.width() || shown.height() > target.height()))
        out.image = shown.scaled(target, Qt::KeepAspectRatio, Qt::SmoothTransformation);
    else
        out.image = shown;
    return out;
}

} // namespace ui
