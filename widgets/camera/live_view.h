#pragma once
// The live view: the latest frame scaled to fit, with a crosshair at the centre of
// the field, a scale bar in µm, the stage's position, the levels shown, and the focus
// figure with its recent history, so a person can position and focus by hand.
//
// Threads: a widget of the GUI thread. Frames go to a LiveViewProcessor (its own
// worker thread) and only the picture it returns is painted here; a frame that arrives
// while the previous one is still being processed waits in one slot, replacing any
// frame already waiting there. Paused, or not on screen, frames are not processed at all.
#include "device/camera/frame.h"
#include "widgets/camera/live_view_processor.h"
#include "widgets/camera/scale_bar.h"

#include <QPointF>
#include <QWidget>

#include <optional>

class QCheckBox;
class QHBoxLayout;
class QLabel;
class QPushButton;

namespace ui {

class FocusPlot;
class LiveCanvas;

class LiveView : public QWidget {
    Q_OBJECT
public:
    explicit LiveView(QWidget* parent = nullptr);

    /// Takes a frame to show (connected to a camera's liveFrame, and given snaps).
    void showFrame(const dev::camera::Frame& frame);
    /// Forgets the picture and the focus history (a camera closed or changed).
    void clear(const QString& message = QString());

    void setPaused(bool paused);
    bool isPaused() const { return m_paused; }
    void setAutoContrast(bool on);
    bool autoContrast() const;
    /// The pixel at the sample to use when a frame does not say (the scan plan's camera);
    /// 0 = not known.
    void setFallbackPixelUm(double um);
    /// Where the stage is (mm), or nothing when not known (not homed, not connected).
    void setStagePosition(const std::optional<QPointF>& mm);

    const ProcessedFrame& shown() const { return m_shown; }
    bool hasPicture() const { return !m_shown.image.isNull(); }
    /// What the view says in place of a picture ("" while it shows one).
    QString message() const { return hasPicture() ? QString() : m_message; }
    /// The pixel size the scale bar uses: the frame's, else the fallback; 0 = none.
    double pixelUm() const;
    /// The bar as drawn now (its length in µm and on screen).
    ScaleBar scaleBar() const;
    /// Where the picture is drawn in the canvas, in the canvas' pixels.
    QRectF pictureRect() const;
    std::optional<QPointF> stagePosition() const { return m_stageMm; }
    const QVector<double>& focusHistory() const;
    LiveViewProcessor* processor() const { return m_processor; }
    /// Frames taken while on screen and not paused.
    std::uint64_t framesTaken() const { return m_taken; }
    QString overlayText() const;  ///< the position and frame lines as painted (for tests)
    /// The row above the picture (Pause, Auto contrast, levels): a panel puts its own
    /// controls at its start, so the picture keeps the height.
    QHBoxLayout* bar() const { return m_bar; }

signals:
    void pausedChanged(bool paused);
    void autoContrastChanged(bool on);

protected:
    void changeEvent(QEvent* event) override;

private:
    void onReady(const ProcessedFrame& frame);
    void retranslateUi();
    void updateReadouts();

    LiveViewProcessor* m_processor;
    LiveCanvas* m_canvas;
    FocusPlot* m_focusPlot;
    QHBoxLayout* m_bar;
    QPushButton* m_pause;
    QCheckBox* m_autoContrast;
    QLabel* m_focusLabel;
    QLabel* m_levelsLabel;
    ProcessedFrame m_shown;
    double m_fallbackPixelUm = 0;
    std::optional<QPointF> m_stageMm;
    bool m_paused = false;
    std::uint64_t m_taken = 0;
    QString m_message;

    friend class LiveCanvas;
};

} // namespace ui
