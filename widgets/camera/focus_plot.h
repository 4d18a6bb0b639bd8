#pragma once
// The focus figure's recent history as a small line: a person turning the focus knob
// sees it climb to a peak and fall past it, and stops at the top.
#include <QVector>
#include <QWidget>

namespace ui {

class FocusPlot : public QWidget {
    Q_OBJECT
public:
    static constexpr int kHistory = 150;  ///< frames kept; older ones fall off the left

    explicit FocusPlot(QWidget* parent = nullptr);
    void add(double focus);
    void clear();
    const QVector<double>& history() const { return m_values; }
    QSize sizeHint() const override { return {240, 32}; }

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    QVector<double> m_values;
};

} // namespace ui
