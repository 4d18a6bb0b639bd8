#pragma once
// A plate drawn to scale: its footprint, row letters and column numbers, each
// well in its true size and place, coloured by what the recipe does there
// (planned, done, current, error). Click a well or drag across wells to select
// them (Ctrl adds to the selection); hovering names the well with its plate and
// machine coordinates and the recipe's volume for it.
#include "motion/plans/plates/labware.h"
#include "motion/plans/plates/transform.h"

#include <QMap>
#include <QWidget>

#include <optional>
#include <set>

namespace ui {

class PlateMap : public QWidget {
    Q_OBJECT
public:
    enum class WellState { Unused, Planned, Done, Current, Error };

    explicit PlateMap(QWidget* parent = nullptr);

    /// The plate to draw (copied); an empty labware draws nothing.
    void setLabware(const motion::plates::Labware& labware, const QString& title);
    const motion::plates::Labware& labware() const { return m_labware; }
    /// The line under the plate ("assay in slot 1: 96-well plate, 360 µL").
    void setTitle(const QString& title);
    QString title() const { return m_title; }
    /// Plate frame → machine XY, for the hover text.
    void setTransform(const motion::plates::PlateTransform& t, bool calibrated);
    /// States and the recipe's volumes per well (µL: + dispensed, − aspirated).
    void setWellStates(const QMap<QString, WellState>& states);
    void setVolumes(const QMap<QString, double>& volumesUl);

    const std::set<motion::plates::WellId>& selection() const { return m_selection; }
    void setSelection(const std::set<motion::plates::WellId>& wells);
    void clearSelection() { setSelection({}); }

    /// Where a well's centre is drawn (widget pixels), for tests and tooltips.
    QPointF wellCenter(const motion::plates::WellId& w) const;
    std::optional<motion::plates::WellId> wellAt(const QPointF& pos) const;
    /// "B3 · plate (23.38, 20.24) mm · machine (31.38, 28.24) mm · 10 µL dispensed"
    QString describeWell(const motion::plates::WellId& w) const;
    /// The text of the well under the mouse ("" when none).
    QString hoverText() const { return m_hoverText; }

    QSize minimumSizeHint() const override { return {320, 220}; }
    QSize sizeHint() const override { return {640, 440}; }

    static QColor colorOf(WellState s);

signals:
    void selectionChanged();
    void hovered(const QString& text);

protected:
    void paintEvent(QPaintEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;

private:
    /// Plate mm → widget pixels: scale and offset, recomputed from the size.
    double scale() const;
    QPointF origin() const;
    QPointF toWidget(double xMm, double yMm) const;
    QPointF toPlate(const QPointF& p) const;
    void selectDragged();  ///< the drag's rectangle, with the wells held by Ctrl
    std::set<motion::plates::WellId> wellsIn(const QRectF& widgetRect) const;
    void setHover(const QString& text);

    motion::plates::Labware m_labware;
    QString m_title;
    motion::plates::PlateTransform m_transform;
    bool m_calibrated = false;
    QMap<QString, WellState> m_states;
    QMap<QString, double> m_volumes;
    std::set<motion::plates::WellId> m_selection;
    std::set<motion::plates::WellId> m_dragBase;  ///< what was selected when a Ctrl-drag began
    std::optional<QPointF> m_pressAt;
    QPointF m_dragTo;
    bool m_dragging = false;
    QString m_hoverText;
};

} // namespace ui
