#pragma once
// The Calibration screen's grid map: the stage mapped by the GUI's camera on a grid plate
// (docs/accuracy.md, "The grid map run by the camera"), as `benchpilot-cli grid-map run`
// does it: nodes every pitch from the dot under the camera, each dot found to a fraction
// of a pixel. The map is drawn as the report draws it (the error vectors magnified over
// a colour map of their length) with its figures beside it; a 2D table fitted from it is
// uploaded and enabled on the stage with one button, and the next map, run with the
// table enabled, stands beside the first: before and after, on one colour scale.
#include "device/client/instrument.h"
#include "device/jobs/accuracy/grid_map_runner.h"
#include "motion/metrology/grid/grid_map.h"

#include <QPointer>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>

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
    QSize sizeHint() const override { return {520, 300}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    std::optional<motion::metrology::GridMapResult> m_before, m_after;
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
    bool m_tableEnabled = false;
    bool m_busyCompensating = false;

    QLabel* m_pitchLabel = nullptr;
    QLabel* m_nodesLabel = nullptr;
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
