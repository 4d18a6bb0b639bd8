#pragma once
// The scan plan typed in: region (two corners, centre and size, or a polygon's
// corners), camera field (from the sensor or given directly), overlap, order and
// start corner, approach, timing, compensation and export naming. Edits emit
// planChanged; the screen draws and checks the plan.
#include "motion/plans/scan/scan_plan.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QSpinBox;
class QStackedWidget;

namespace ui {

class ScanPlanForm : public QWidget {
    Q_OBJECT
public:
    explicit ScanPlanForm(QWidget* parent = nullptr);

    motion::scan::ScanPlan plan() const;
    void setPlan(const motion::scan::ScanPlan& plan);
    /// The polygon text ("x, y; x, y; …") does not read: why, else empty.
    QString polygonError() const { return m_polygonError; }

signals:
    void planChanged();
    /// The region kind changed: the map draws rectangles or polygons.
    void regionKindChanged(motion::scan::RegionKind kind);

private:
    QWidget* regionGroup();
    QWidget* cameraGroup();
    QWidget* gridGroup();
    QWidget* runGroup();
    QWidget* exportGroup();
    QDoubleSpinBox* number(const QString& name, double min, double max, double value, int decimals, const QString& suffix,
                           const QString& tip);
    void changed();
    void updateCameraInfo();

    bool m_loading = false;
    mutable QString m_polygonError;  ///< set by plan()
    QLineEdit* m_name;
    // Region
    QComboBox* m_regionKind;
    QStackedWidget* m_regionPages;
    QDoubleSpinBox *m_x0, *m_y0, *m_x1, *m_y1;
    QDoubleSpinBox *m_cx, *m_cy, *m_w, *m_h;
    QLineEdit* m_vertices;
    // Camera
    QComboBox* m_fovFrom;
    QStackedWidget* m_cameraPages;
    QSpinBox *m_sensorW, *m_sensorH;
    QDoubleSpinBox *m_sensorPixel, *m_magnification;
    QDoubleSpinBox *m_fieldW, *m_fieldH, *m_samplePixel;
    QDoubleSpinBox* m_rotation;
    QComboBox* m_imageY;
    QLabel* m_cameraInfo;
    // Grid
    QDoubleSpinBox *m_overlapX, *m_overlapY;
    QComboBox *m_order, *m_start;
    QCheckBox* m_unidirectional;
    QDoubleSpinBox* m_overtravel;
    // Run
    QDoubleSpinBox *m_speed, *m_settle, *m_exposure, *m_tolerance, *m_settleTimeout;
    QCheckBox* m_compensate;
    // Export
    QLineEdit *m_pattern, *m_mmStage;
    QSpinBox* m_firstIndex;
};

} // namespace ui
