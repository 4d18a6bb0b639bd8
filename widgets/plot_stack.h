#pragma once
// Stacked plots on one shared time axis, in one QCustomPlot (so one replot
// draws them all and one savePng/savePdf exports them all).
//
// Time: x is seconds relative to an anchor per instrument (device time =
// anchor + x). Live views anchor at each instrument's newest sample, so both
// instruments' "now" sits at x = 0 although their device clocks differ; a
// paused view keeps its anchors. The stack draws only when redraw() is called:
// the owner decides when (a coalescing timer, never per packet).
//
// Mouse: drag pans time and values; the wheel zooms time, Ctrl+wheel zooms the
// values of the plot under the pointer. A user change of the time range emits
// userMovedTime() (the screen pauses), of a value range userMovedValues().
#include "widgets/plot_source.h"

#include <qcustomplot.h>

#include <QList>

namespace ui {

class PlotPanel;

class PlotStack : public QCustomPlot {
    Q_OBJECT
public:
    explicit PlotStack(const PlotDataSource* source, QWidget* parent = nullptr);
    ~PlotStack() override;

    const PlotDataSource* source() const { return m_source; }

    int panelCount() const { return m_panels.size(); }
    PlotPanel* panel(int index) const { return m_panels.value(index); }
    /// Index of the panel under a widget position, or −1.
    int panelAt(const QPoint& pos) const;
    PlotPanel* addPanel();
    /// The last panel is never removed: a stack always has one plot.
    bool removePanel(int index);

    /// Name and unit come from the source.
    bool addChannel(int panel, const dev::tele::ChannelKey& key);
    bool removeChannel(int panel, const dev::tele::ChannelKey& key);
    /// Every channel of every panel, each once.
    QVector<dev::tele::ChannelKey> allChannels() const;

    /// Device time (s) at x = 0 for instrument 0 (analyzer) and 1 (stage); NaN hides its channels.
    void setAnchors(double analyzerS, double stageS);
    double anchorS(int instrument) const { return m_anchorS[instrument == 1 ? 1 : 0]; }
    /// Sets the shared time range without emitting userMovedTime().
    void setTimeRange(double x0S, double x1S);
    QCPRange timeRange() const;
    void setAutoScaleValues(bool on) { m_autoScale = on; }
    bool autoScaleValues() const { return m_autoScale; }

    /// Pixel columns of the plotting area (the decimation width).
    int columns() const;
    /// Re-reads every channel for the present range and size and replots now.
    void redraw();
    void setTimeTitle(const QString& title);
    /// The time axis's title is kept as a string property, not a member: the run-time
    /// rewording (retranslator.h) rewords a widget's string properties, so a panel
    /// labelled after a language switch gets the title in the new language.
    static constexpr const char* kTimeTitleProperty = "bpTimeTitle";
    void setHighlightedPanel(int index);

signals:
    void userMovedTime();
    void userMovedValues();
    void panelClicked(int index);
    /// After panels or channels changed (cursors re-attach, pickers refresh).
    void layoutChanged();
    /// After every redraw() (readouts refresh).
    void redrawn();

protected:
    void wheelEvent(QWheelEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;

private:
    void relabel();
    void watchRanges(PlotPanel* p);

    const PlotDataSource* m_source;
    QCPMarginGroup* m_margins;
    QList<PlotPanel*> m_panels;
    double m_anchorS[2];
    bool m_autoScale = true;
    int m_programmatic = 0;  ///< > 0 while the stack itself sets ranges
    /// The plotting area may have changed size (resize, plots or channels added or
    /// removed): lay out before asking the stores for columns. Otherwise the last
    /// frame's width is used; a margin that grows with a tick label is at most a few
    /// columns off for one frame.
    bool m_layoutDirty = true;
    int m_highlighted = -1;
};

} // namespace ui
