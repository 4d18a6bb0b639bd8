#pragma once
// Export of what the stacked plots show: CSV, PNG, PDF.
//
// CSV: the raw stored samples of every channel inside the visible time range —
// exact device values, not what was drawn. When the range holds more than
// kRawCsvLimitSamples samples in all, the file holds the decimated view instead
// (for each pixel column the minimum row then the maximum row of every channel),
// and its header comment and the result say so. Columns:
//   time_s,instrument,<channel name> [<unit>],…
// time_s is the plot's time axis (s relative to the instrument's anchor, whose
// device time is in a header comment); one row per sample time of one
// instrument, other instruments' cells empty (instrument empty in decimated rows).
// Lines starting with '#' are comments. Written atomically (QSaveFile).
#include <QString>

namespace ui {

class PlotStack;

struct CsvExportResult {
    bool ok = false;
    bool decimated = false;  ///< true: min/max per pixel column, false: raw samples
    qint64 rows = 0;
    QString error;           ///< a sentence, when !ok
};

constexpr qint64 kRawCsvLimitSamples = 2'000'000;

CsvExportResult exportCsv(const PlotStack& stack, const QString& path, qint64 rawLimitSamples = kRawCsvLimitSamples);
/// The stack as drawn now, at its present size (or width × height when given).
bool exportPng(PlotStack& stack, const QString& path, QString* error, int width = 0, int height = 0);
bool exportPdf(PlotStack& stack, const QString& path, QString* error);

} // namespace ui
