#pragma once
// The accuracy bench's report (docs/accuracy.md): one PDF per test with its set-up, the
// figures table with pass/fail, the ISO-style plot (mean ± 2s per direction against
// the target, reversal visible), the deviations of every reading, the compensation
// fit with its order table and residuals when there is one, and the before/after
// comparison when a compensated run follows an uncompensated one. The circular test's
// report has its figures and the polar plot with the error magnified.
//
// Qt Gui only (QPdfWriter, QPainter), like the wording layer is Qt Core only, so the
// CLI writes the same PDF as the GUI. It needs a QGuiApplication (the CLI makes an
// offscreen one); canRender() says whether there is one.
#include "device/files/accuracy/accuracy_result_file.h"
#include "motion/metrology/compensation/polynomial_fit.h"
#include "motion/metrology/contour/circular_test.h"
#include "motion/metrology/grid/grid_map.h"
#include "motion/metrology/grid/grid_map_test.h"
#include "motion/metrology/linear/axis_test.h"

#include <QString>

#include <optional>
#include <vector>

namespace ui::report {

struct AxisReportInput {
    QString title;                                   ///< "Positioning accuracy, stage X"
    QString instrument;                              ///< model, family
    motion::msg::Message source;                             ///< where the readings came from (accuracy.source.*)
    std::optional<motion::metrology::AxisTest> test; ///< the set-up, when known
    dev::files::accuracy::AccuracyResult result;
    std::vector<motion::metrology::Reading> readings;
    std::optional<dev::files::accuracy::AccuracyResult> before;  ///< the same test without compensation
    std::optional<motion::metrology::FitTable> fit;       ///< the compensation fitted to these readings
    QString created;                                 ///< date and time, as the reader's locale writes them
};

struct CircleReportInput {
    QString title;
    QString instrument;
    motion::metrology::CircularTest test;
    motion::metrology::CircularEvaluation evaluation;
    QString created;
};

/// A grid map's report: the set-up, the figures of the decomposition (beside those of the
/// map before compensation when there is one), and the map (before and after side by
/// side): the error vectors magnified over a colour map of their length.
struct GridReportInput {
    QString title;
    QString instrument;
    motion::msg::Message source;                               ///< accuracy.source.camera_plate
    std::optional<motion::metrology::GridMapTest> test;
    motion::metrology::GridMapResult result;
    std::optional<motion::metrology::GridMapResult> before;    ///< the same grid without compensation
    QString created;
};

/// A QGuiApplication exists (QPainter needs one for its fonts).
bool canRender();
/// Written all or nothing (a temporary file renamed at the end).
bool writeAxisReport(const QString& pdfPath, const AxisReportInput& in, QString* error);
bool writeCircleReport(const QString& pdfPath, const CircleReportInput& in, QString* error);
bool writeGridReport(const QString& pdfPath, const GridReportInput& in, QString* error);

} // namespace ui::report
