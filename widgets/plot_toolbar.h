#pragma once
// The Plots screen's row of controls: window and rate choosers, pause, auto-scale,
// cursors, XY, plots added and removed, record and export. It only lays them out;
// the screen connects them and keeps them in step with its state.
#include <QWidget>

class QComboBox;
class QMenu;
class QPushButton;

namespace ui {

class PlotToolbar : public QWidget {
    Q_OBJECT
public:
    /// rateHz preselected in the rate chooser; rawCsvLimit is quoted in the CSV tooltip.
    PlotToolbar(int rateHz, qint64 rawCsvLimit, QWidget* parent = nullptr);

    QComboBox* const window;   ///< item data: seconds
    QComboBox* const rate;     ///< item data: Hz
    QPushButton* const pause;  ///< checkable
    QPushButton* const autoY;  ///< checkable, on at start
    QPushButton* const cursors;
    QPushButton* const xy;     ///< checkable, on at start
    QPushButton* const addPlot;
    QPushButton* const removePlot;
    QPushButton* const record; ///< checkable
    QPushButton* const exportCsv;
    QPushButton* const exportPng;
    QPushButton* const exportPdf;
    /// Export of the recorded history (every instrument's positions and following
    /// errors, shown or not); its menu's actions carry the span in seconds (0: all).
    QPushButton* const exportHistory;
    QMenu* const historySpans;
};

} // namespace ui
