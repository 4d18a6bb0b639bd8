#pragma once
// Tick labels that tell the ticks apart at every range. QCustomPlot's default labels
// carry six significant digits: a position near 10 mm plotted over a few micrometres read
// "10, 10, 10". These give each label the decimals its tick step needs, and no more.
class QCPAxis;

namespace ui {

/// Gives `axis` a ticker whose labels differ wherever its ticks do.
void useDistinctTickLabels(QCPAxis* axis);

} // namespace ui
