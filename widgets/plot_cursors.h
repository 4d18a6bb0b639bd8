#pragma once
// Two time cursors (A and B) across every plot of a stack, dragged with the
// mouse, and their readout: the time of each, Δt, and for every channel the
// sample nearest each cursor and Δy = y(B) − y(A). Values are the stored
// samples themselves, never the decimated points drawn on screen.
#include "widgets/plot_source.h"

#include <QObject>
#include <QTableWidget>

#include <optional>

class QCPItemStraightLine;
class QCPItemText;

namespace ui {

class PlotStack;

struct CursorReading {
    int panel = 0;
    dev::tele::ChannelKey key;
    QString name, unit;
    std::optional<dev::tele::Sample> a, b;  ///< nearest stored sample to each cursor (device time)
    std::optional<double> deltaY() const
    {
        if (!a || !b)
            return std::nullopt;
        return double(b->value) - double(a->value);
    }
};

class PlotCursors : public QObject {
    Q_OBJECT
public:
    explicit PlotCursors(PlotStack* stack);
    ~PlotCursors() override;

    /// Shows the cursors; the first time at one and two thirds of the visible range.
    void setVisible(bool on);
    bool isVisible() const { return m_visible; }
    /// Cursor positions on the stack's time axis (s, relative to the anchors).
    void setPositions(double xA, double xB);
    double position(int which) const { return m_x[which == 1 ? 1 : 0]; }
    double deltaT() const { return m_x[1] - m_x[0]; }
    QVector<CursorReading> readings() const;

signals:
    void changed();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void rebuild();
    void place();
    int cursorNear(const QPoint& pos) const;

    PlotStack* m_stack;
    bool m_visible = false;
    bool m_placed = false;
    double m_x[2] = {0, 0};
    int m_drag = -1;
    QList<QCPItemStraightLine*> m_lines[2];
    QCPItemText* m_labels[2] = {nullptr, nullptr};
};

/// The cursors' table: one row for time, one per channel.
class CursorReadout : public QTableWidget {
    Q_OBJECT
public:
    explicit CursorReadout(PlotCursors* cursors, QWidget* parent = nullptr);
    void refresh();

private:
    PlotCursors* m_cursors;
};

} // namespace ui
