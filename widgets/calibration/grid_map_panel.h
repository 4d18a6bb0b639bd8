#pragma once
// The Calibration screen's grid map: the stage mapped by the GUI's camera on a grid plate
// (docs/accuracy.md, "The grid map run by the camera"), as `benchpilot-cli grid-map run`
// does it: nodes every pitch from the dot under the camera, each dot found to a fraction
// of a pixel. The map is drawn as the report draws it (the error vectors magnified over
// a colour map of their length) with its figures beside it; a 2D table fitted from it is
// uploaded and enabled on the stage with one button, and the next map, run with the
// table enabled, stands beside the first: before and after, on one colour scale. A map
// read both ways is their mean; its reversal at each node is one choice away (the
// arrows show the errors or the reversals) and its figures join the table.
#include "device/client/instrument.h"
#include "device/jobs/accuracy/grid_map_runner.h"
#include "motion/metrology/grid/grid_map.h"
#include "widgets/report/grid_map_painter.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

class QCheckBox;
class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace dev::camera {
class DotReadingSource;
}

namespace ui {

class NumberField;

class CameraSession;

/// The maps, drawn side by side on one scale.
class GridMapView : public QWidget {
    Q_OBJECT
public:
    using QWidget::QWidget;
    void setMaps(const std::optional<motion::metrology::GridMapResult>& before, const std::optional<motion::metrology::GridMapResult>& after);
    void setVectors(ui::report::GridVectors kind);
    ui::report::GridVectors vectors() const { return m_kind; }
    QSize sizeHint() const override { return {520, 300}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::optional<motion::metrology::GridMapResult> m_before, m_after;
    ui::report::GridVectors m_kind = ui::report::GridVectors::Error;
};

class GridMapPanel : public QWidget {
    Q_OBJECT
public:
    explicit GridMapPanel(QWidget* parent = nullptr);
    ~GridMapPanel() override;

    void setInstrument(dev::Instrument* instrument);
    void setCameraSession(CameraSession* session) { m_camera = session; }
    /// Where the runs go: a new "grid-map", "grid-map-2", … under this folder.
    void setFolderSource(std::function<QString()> folder) { m_folder = std::move(folder); }
    void setGrid(double pitchMm, int columns, int rows);
    /// Read every node both ways (forward from −X −Y, then in reverse order from +X +Y).
    void setBidirectional(bool both);
    /// What the map's arrows show; Reversal only when a map shown was read both ways.
    void showVectors(ui::report::GridVectors kind);
    GridMapView* view() const { return m_view; }
    /// Maps the stage from the dot under the camera; false (with a problem) when it cannot start.
    bool run();
    void abort();
    /// Fits a 2D table to the first map, uploads it and enables it; the next map is the "after".
    bool compensate();
    /// Disables the table on the stage; the next map starts a new "before".
    void disableTable();

    dev::jobs::GridMapRunner* runner() const { return m_runner.get(); }
    const std::optional<motion::metrology::GridMapResult>& before() const { return m_before; }
    const std::optional<motion::metrology::GridMapResult>& after() const { return m_after; }
    bool tableEnabled() const { return m_tableEnabled; }
    QString stateText() const;

signals:
    void problem(const QString& message);
    void notice(const QString& message);

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void onFinished();
    void showMaps();
    void updateUi();

    QPointer<dev::Instrument> m_instrument;
    CameraSession* m_camera = nullptr;
    std::function<QString()> m_folder;
    std::unique_ptr<dev::camera::DotReadingSource> m_source;
    std::unique_ptr<dev::jobs::GridMapRunner> m_runner;
    std::optional<motion::metrology::GridMapResult> m_before, m_after;
    /// The before map's grid with its start: the after map reads these same nodes,
    /// wherever the stage stands when it is asked for.
    std::optional<motion::metrology::GridMapTest> m_beforeTest;
    motion::metrology::GridMapTest m_runningTest;
    bool m_tableEnabled = false;
    bool m_busyCompensating = false;

    QLabel* m_pitchLabel = nullptr;
    QLabel* m_nodesLabel = nullptr;
    QLabel* m_showLabel = nullptr;
    QCheckBox* m_bidirectional = nullptr;
    QComboBox* m_show = nullptr;
    NumberField* m_pitch = nullptr;
    NumberField* m_columns = nullptr;
    NumberField* m_rows = nullptr;
    QPushButton* m_run = nullptr;
    QPushButton* m_abort = nullptr;
    QPushButton* m_compensate = nullptr;
    QPushButton* m_disable = nullptr;
    QLabel* m_state = nullptr;
    QLabel* m_cannotKnow = nullptr;
    QTableWidget* m_figures = nullptr;
    GridMapView* m_view = nullptr;
};

} // namespace ui
