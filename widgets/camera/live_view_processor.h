#pragma once
// Turns camera frames into pictures for the live view without holding up the GUI
// thread: the contrast stretch, the 8-bit conversion, the focus figure and the scaling
// to the view's size run on a worker thread of this object's own pool.
//
// Threads: the object lives on the GUI thread; submit() and every signal are there.
// At most one frame is being processed at a time and at most one waits: a frame that
// arrives while another waits replaces it (latest wins, counted as dropped), so a
// camera faster than the processing never builds a queue and the picture shown is
// never older than one frame behind.
#include "device/camera/display_image.h"
#include "device/camera/frame.h"

#include <QImage>
#include <QObject>
#include <QSize>
#include <QThreadPool>

#include <cstdint>
#include <optional>

namespace ui {

/// One frame as the live view shows it.
struct ProcessedFrame {
    QImage image;                  ///< 8-bit grey or RGB, scaled to fit the size asked for
    QSize frameSize;               ///< the frame's own size in pixels
    double pixelUm = 0;            ///< the frame's pixel at the sample; 0 when it does not say
    double focus = 0;              ///< dev::camera::focusMeasure of the frame
    dev::camera::DisplayStretch stretch;  ///< the levels shown black and white
    int bitDepth = 8;
    bool colour = false;
    std::uint64_t sequence = 0;
};

class LiveViewProcessor : public QObject {
    Q_OBJECT
public:
    explicit LiveViewProcessor(QObject* parent = nullptr);
    ~LiveViewProcessor() override;  ///< waits for the frame in progress (one frame's work)

    /// Processes `frame` now, or after the one in progress (replacing any that waits).
    void submit(const dev::camera::Frame& frame);
    /// On: the levels are stretched between the darkest and brightest 0.1 % (dev::camera::toDisplayImage);
    /// off: the frame's bit depth maps black to white.
    void setAutoContrast(bool on) { m_autoContrast = on; }
    bool autoContrast() const { return m_autoContrast; }
    /// The picture is scaled to fit this (an empty size: the frame's own size).
    void setTargetSize(const QSize& size) { m_target = size; }

    bool busy() const { return m_busy; }
    std::uint64_t submittedCount() const { return m_submitted; }
    std::uint64_t processedCount() const { return m_processed; }
    std::uint64_t droppedCount() const { return m_dropped; }

    /// The work done on the worker thread, callable anywhere (tests, benchmarks).
    static ProcessedFrame process(const dev::camera::Frame& frame, bool autoContrast, const QSize& target);

signals:
    void ready(const ui::ProcessedFrame& frame);

private:
    void start(dev::camera::Frame frame);
    void finish(const ProcessedFrame& result);

    QThreadPool m_pool;
    bool m_autoContrast = true;
    QSize m_target;
    bool m_busy = false;
    std::optional<dev::camera::Frame> m_waiting;
    std::uint64_t m_submitted = 0, m_processed = 0, m_dropped = 0;
};

} // namespace ui

Q_DECLARE_METATYPE(ui::ProcessedFrame)
