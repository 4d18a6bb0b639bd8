#pragma once
// Defining an accuracy test on the Calibration screen: an ISO 230-2 axis test
// (axis, targets as a grid with ISO's irregular spacing or a list, cycles, one or both
// directions, overrun, feed, dwell, the settle rule, tolerances), seed 000's linked XY
// line, or an ISO 230-4 circle. Edits emit changed(); test() gives the definition and
// problems() what motion/metrology's validators say of it (without the instrument's
// limits: the run checks those).
#include "device/files/accuracy/accuracy_test_file.h"

#include <QWidget>

#include <utility>
#include <vector>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QStackedWidget;

namespace ui {

class NumberField;

class AccuracyTestForm : public QWidget {
    Q_OBJECT
public:
    enum class Kind { Axis = 0, XyLine = 1, Circle = 2 };

    explicit AccuracyTestForm(QWidget* parent = nullptr);

    Kind kind() const;
    dev::files::accuracy::AccuracyTest test() const;
    void setTest(const dev::files::accuracy::AccuracyTest& test);
    /// Axis letters the instrument has (the axis combo offers these).
    void setAxes(const QStringList& letters);
    motion::msg::Problems problems() const;
    /// The first typed number that is not valid ("Feed (mm/s) must be at least 0.01, not -5"),
    /// empty when every shown field holds a number: the run waits for it.
    QString entryProblem() const;
    /// Read-only while a run uses the definition.
    void setEditable(bool editable);

signals:
    void changed();

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslateUi();
    void fill(const dev::files::accuracy::AccuracyTest& test);
    QWidget* buildAxisPage();
    QWidget* buildXyPage();
    QWidget* buildCirclePage();
    NumberField* number(const char* name, double min, double max, double value, int decimals);
    NumberField* whole(const char* name, int min, int max, int value);

    QComboBox* m_kind;
    QStackedWidget* m_pages;
    // Axis test.
    QComboBox* m_axis;
    QComboBox* m_targetMode;    ///< grid or list
    NumberField *m_start, *m_end;
    NumberField* m_count;
    QCheckBox* m_irregular;
    QLineEdit* m_list;
    NumberField* m_cycles;
    QCheckBox* m_bidirectional;
    NumberField *m_overrun, *m_feed, *m_dwell, *m_settleTol, *m_settleWindow, *m_settleTimeout;
    NumberField *m_tolA, *m_tolR;
    // XY line.
    NumberField *m_fromX, *m_fromY, *m_toX, *m_toY, *m_xyFeed;
    NumberField *m_xyCount, *m_xyCycles;
    // Circle.
    NumberField *m_cx, *m_cy, *m_radius, *m_circleFeed, *m_lead, *m_tolG;
    NumberField* m_samples;
    QComboBox* m_directions;
    std::string m_name;
    /// Form labels and their source texts (QT_TR_NOOP), re-worded by retranslateUi().
    std::vector<std::pair<QLabel*, const char*>> m_worded;
};

} // namespace ui
