#include "widgets/plot_toolbar.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMenu>
#include <QPushButton>

namespace ui {
namespace {
QPushButton* toggle(const QString& text, const QString& tip, QWidget* parent)
{
    auto* b = new QPushButton(text, parent);
    b->setCheckable(true);
    b->setToolTip(tip);
    return b;
}
} // namespace

PlotToolbar::PlotToolbar(int rateHz, qint64 rawCsvLimit, QWidget* parent)
    : QWidget(parent),
      window(new QComboBox(this)),
      rate(new QComboBox(this)),
      pause(toggle(tr("Pause"), tr("Freeze the view; the instruments keep streaming and recording goes on"), this)),
      autoY(toggle(tr("Auto Y"), tr("Fit each plot's value axes to what is visible (dragging or Ctrl+wheel on a plot turns it off)"), this)),
      cursors(toggle(tr("Cursors"), tr("Two time cursors A and B with Δt and Δy; drag them along the time axis"), this)),
      xy(toggle(tr("XY"), tr("Show the stage's XY path, commanded against measured"), this)),
      addPlot(new QPushButton(tr("+ Plot"), this)),
      removePlot(new QPushButton(tr("− Plot"), this)),
      record(toggle(tr("Record…"), tr("Stream every plotted channel to a CSV file until stopped"), this)),
      exportCsv(new QPushButton(tr("CSV…"), this)),
      exportPng(new QPushButton(tr("PNG…"), this)),
      exportPdf(new QPushButton(tr("PDF…"), this)),
      exportHistory(new QPushButton(tr("History…"), this)),
      historySpans(new QMenu(this))
{
    auto* bar = new QHBoxLayout(this);
    bar->setContentsMargins(0, 0, 0, 0);
    bar->addWidget(new QLabel(tr("Window"), this));
    window->setObjectName(QStringLiteral("windowChooser"));
    window->setToolTip(tr("How much history the plots keep and show (1 s to 10 min)"));
    const std::pair<double, QString> windows[] = {
        {1, tr("1 s")},    {2, tr("2 s")},    {5, tr("5 s")},    {10, tr("10 s")},   {30, tr("30 s")},
        {60, tr("1 min")}, {120, tr("2 min")}, {300, tr("5 min")}, {600, tr("10 min")}};
    for (const auto& [s, text] : windows)
        window->addItem(text, s);
    bar->addWidget(window);

    bar->addWidget(new QLabel(tr("Rate"), this));
    rate->setObjectName(QStringLiteral("rateChooser"));
    rate->setToolTip(tr("Sample rate asked of the instruments; the link may carry less (see the status line)"));
    for (int hz : {50, 100, 200, 500, 1000, 2000, 5000, 10000})
        rate->addItem(hz >= 1000 ? tr("%1 kHz").arg(hz / 1000) : tr("%1 Hz").arg(hz), hz);
    rate->setCurrentIndex(std::max(0, rate->findData(rateHz)));
    bar->addWidget(rate);

    pause->setObjectName(QStringLiteral("pauseButton"));
    autoY->setChecked(true);
    xy->setChecked(true);
    addPlot->setToolTip(tr("Add a plot below the others"));
    removePlot->setToolTip(tr("Remove the plot chosen in the channel list"));
    for (QPushButton* b : {pause, autoY, cursors, xy, addPlot, removePlot})
        bar->addWidget(b);
    bar->addStretch(1);

    record->setObjectName(QStringLiteral("recordButton"));
    exportCsv->setToolTip(tr("Export the visible range as CSV: the raw samples (decimated per pixel column above %1 samples)")
                              .arg(rawCsvLimit));
    exportPng->setToolTip(tr("Export the plots as a picture"));
    exportPdf->setToolTip(tr("Export the plots as a vector PDF"));
    bar->addWidget(record);
    bar->addSpacing(8);
    // No "Export" label before the export buttons: their names say it, and the room
    // went to History… (the screen must fit 1366 px).
    for (QPushButton* b : {exportCsv, exportPng, exportPdf})
        bar->addWidget(b);

    exportHistory->setObjectName(QStringLiteral("historyButton"));
    exportHistory->setToolTip(tr("Export the recorded history as CSV: every instrument's positions and following "
                                 "errors since connection, whether plotted or not"));
    const std::pair<double, QString> spans[] = {
        {30, tr("Last 30 s")}, {60, tr("Last 1 min")}, {120, tr("Last 2 min")}, {0, tr("Everything recorded")}};
    for (const auto& [s, text] : spans)
        historySpans->addAction(text)->setData(s);
    exportHistory->setMenu(historySpans);
    bar->addWidget(exportHistory);
}

} // namespace ui
