#pragma once
// One plot of the stacked plots: an axis rect inside the stack's QCustomPlot with
// its channels, its legend and its units. The time axis is the stack's; each
// panel owns its value axes: the first channel's unit on the left, any other
// unit on the right.
//
// Feeding a channel: the store is asked for the min and max of each pixel
// column of the visible range (ChannelStore::decimate) and QCustomPlot gets at
// most those two points per column, so a frame costs the same whether the
// window holds a thousand samples or six million. When the range holds no more
// samples than two per column, the raw samples are handed over instead.
#include "widgets/plot_source.h"

#include <QColor>
#include <QObject>
#include <QPen>
#include <QVector>

#include <memory>
#include <vector>

class QCustomPlot;
class QCPAxis;
class QCPAxisRect;
class QCPGraph;
class QCPGraphData;
class QCPLegend;
class QCPMarginGroup;

namespace ui {

class PlotPanel : public QObject {
    Q_OBJECT
public:
    struct Line {
        dev::tele::ChannelKey key;
        QString name, unit;
        QCPGraph* graph = nullptr;
    };

    /// Adds a new axis rect to `plot` (the caller places it in the layout).
    PlotPanel(QCustomPlot* plot, QCPMarginGroup* margins, QObject* parent = nullptr);
    /// Removes the panel's graphs; the stack removes the axis rect itself.
    ~PlotPanel() override;

    QCPAxisRect* rect() const { return m_rect; }
    QCPAxis* timeAxis() const;
    QCPAxis* leftAxis() const;
    QCPAxis* rightAxis() const;
    QCPLegend* legend() const { return m_legend; }

    bool addChannel(const dev::tele::ChannelKey& key, const QString& name, const QString& unit);
    /// Names every line again from `source` (after a language switch).
    void rename(const PlotDataSource& source);
    bool removeChannel(const dev::tele::ChannelKey& key);
    bool hasChannel(const dev::tele::ChannelKey& key) const { return indexOf(key) >= 0; }
    QVector<dev::tele::ChannelKey> channels() const;
    const QVector<Line>& lines() const { return m_lines; }
    /// The graph drawing `key`, or nullptr.
    QCPGraph* graph(const dev::tele::ChannelKey& key) const;

    /// Shows the time tick labels and title (only the bottom panel of a stack does).
    void setTimeLabelsVisible(bool visible, const QString& title);
    void setHighlighted(bool on);

    /// Re-reads every channel for the time range [x0S, x1S] (relative to each
    /// instrument's anchor: device time = anchor + x) at `columns` pixel columns.
    void refresh(const PlotDataSource& source, double x0S, double x1S, const double anchorS[2], int columns);
    /// Fits the value axes to what refresh() found in the visible range.
    void autoScaleValues();

    /// Line colour and style of a channel: colour by instrument and axis, dash by kind.
    static QPen penFor(const dev::tele::ChannelKey& key);

private:
    int indexOf(const dev::tele::ChannelKey& key) const;
    void relayoutAxes();
    void feed(Line& line, const dev::tele::ChannelStore& store, double x0S, double x1S, double anchorS, int columns);

    QCustomPlot* m_plot;
    QCPAxisRect* m_rect;
    QCPLegend* m_legend;
    QVector<Line> m_lines;
    /// Value extent of the visible points per line (NaN when none), for auto-scale.
    QVector<std::pair<double, double>> m_extent;
    // Scratch buffers reused every frame so a redraw allocates nothing once warm.
    std::vector<dev::tele::MinMax> m_columns;
    std::unique_ptr<QVector<QCPGraphData>> m_points;
};

} // namespace ui
