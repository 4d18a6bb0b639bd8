#pragma once
// The scan plan typed in: region (two corners, centre and size, or a polygon's
// corners), camera field (from the sensor or given directly), overlap, order and
// start corner, approach, timing, compensation and export naming. Edits emit
// planChanged; the screen draws and checks the plan.
#include "motion/plans/scan/scan_plan.h"

#include <QWidget>

#include <string>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLabel;
class QLineEdit;
class QStackedWidget;

namespace ui {

class NumberField;

class ScanPlanForm : public QWidget {
    Q_OBJECT
public:
    explicit ScanPlanForm(QWidget* parent = nullptr);

    motion::scan::ScanPlan plan() const;
    void setPlan(const motion::scan::ScanPlan& plan);
    /// The polygon text ("x, y; x, y; …") does not read: why, else empty.
    QString polygonError() const { return m_polygonError; }
    /// The first typed number shown that is not valid, with its reason; empty when all are.
    /// plan() gives NaN for such a field: nothing is planned, saved or run from it.
    QString entryProblem() const;

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
    NumberField* number(const QString& name, double min, double max, double value, int decimals, const QString& suffix,
                        const QString& tip);
    void changed();
    void updateCameraInfo();

    bool m_loading = false;
    /// The camera profile the plan names: kept through the form so saving keeps the link.
    std::string m_cameraProfile;
    mutable QString m_polygonError;  ///< set by plan()
    QLineEdit* m_name;
    // Region
    QComboBox* m_regionKind;
    QStackedWidget* m_regionPages;
    NumberField *m_x0, *m_y0, *m_x1, *m_y1;
    NumberField *m_cx, *m_cy, *m_w, *m_h;
    QLineEdit* m_vertices;
    // Camera
    QComboBox* m_fovFrom;
    QStackedWidget* m_cameraPages;
    NumberField *m_sensorW, *m_sensorH;
    NumberField *m_sensorPixel, *m_magnification;
    NumberField *m_fieldW, *m_fieldH, *m_samplePixel;
    NumberField* m_rotation;
    QComboBox* m_imageY;
    QLabel* m_cameraInfo;
    // Grid
    NumberField *m_overlapX, *m_overlapY;
    QComboBox *m_order, *m_start;
    QCheckBox* m_unidirectional;
    NumberField* m_overtravel;
    // Run
    NumberField *m_speed, *m_settle, *m_exposure, *m_tolerance, *m_settleTimeout;
    QCheckBox* m_compensate;
    // Export
    QLineEdit *m_pattern, *m_mmStage;
    NumberField* m_firstIndex;
};

} // namespace ui
