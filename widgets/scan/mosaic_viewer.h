#pragma once
// The mosaic viewer on the Scan screen's Mosaic tab: the stitched mosaic (its pyramidal
// OME-TIFF, read a region at a time) with zoom (wheel, + and −, F fits), pan (drag,
// arrow keys), the tiles' outlines (T) and the quality overlay (Q) toggled, the stage's
// field of view where the stage is, a scale bar, and the stage position under the
// cursor. A double-click moves the stage so that the point is under the objective
// (docs/stitching.md, "The mosaic viewer"): refused with why when the stage is not
// connected, not homed, a scan runs, or the point lies outside its soft limits; asked
// first (through Confirm, which app/ answers) when it is farther than one camera field.
#include "device/client/instrument.h"
#include "imaging/stitch.h"
#include "motion/plans/scan/scan_plan.h"
#include "widgets/scan/mosaic_stage_frame.h"

#include <QPointF>
#include <QWidget>

#include <functional>
#include <optional>

class QAction;
class QLabel;
class QToolButton;

namespace ui {

class MosaicCanvas;

class MosaicViewer : public QWidget {
    Q_OBJECT
public:
    /// Asked before a move farther than one field; true = go.
    using Confirm = std::function<bool(const QString& question)>;

    explicit MosaicViewer(QWidget* parent = nullptr);

    void setStage(dev::Instrument* stage);
    void setConfirm(Confirm confirm) { m_confirm = std::move(confirm); }
    /// While a scan runs the stage is the scan's: double-clicks are refused.
    void setScanRunning(bool running) { m_scanRunning = running; }

    /// Shows the mosaic at `mosaicPath`, which `result` describes and `camera` took;
    /// false with a problem signal when the file cannot be read.
    bool showStitch(const imaging::StitchResult& result, const motion::scan::Camera& camera, const QString& mosaicPath);
    void clear();
    bool hasMosaic() const;

    MosaicCanvas* canvas() const { return m_canvas; }
    const MosaicStageFrame& frame() const;
    /// The double-click's action: moves the stage to put `mosaicPx` under the objective.
    /// False (with why, as a problem) when refused or not confirmed.
    bool goTo(const QPointF& mosaicPx);
    /// "X 12.345  Y 6.789 mm …" under the cursor, and the level shown, as on screen.
    QString statusText() const;

signals:
    /// Open (O): show the mosaic already stitched in the output folder.
    void openRequested();
    void problem(const QString& message);
    void notice(const QString& message);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void updateStatus();
    void updateStage();

    MosaicCanvas* m_canvas;
    QAction *m_open, *m_fit, *m_zoomIn, *m_zoomOut, *m_tiles, *m_quality;
    QToolButton *m_openButton, *m_fitButton, *m_inButton, *m_outButton, *m_tilesButton, *m_qualityButton;
    QLabel* m_status;
    dev::Instrument* m_stage = nullptr;
    Confirm m_confirm;
    bool m_scanRunning = false;
    std::optional<QPointF> m_cursor;
    QString m_file;
};

} // namespace ui
