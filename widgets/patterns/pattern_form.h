#pragma once
// The parameters of a pattern in a form: the shape, then only the fields that shape has (each
// shape keeps its own values while another is shown), the feed and, on an instrument whose Z
// follows XY, the height to work at. Problems are listed under the form by field name.
#include "motion/plans/pattern.h"

#include <QHash>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QFormLayout;
class QStackedWidget;

namespace ui {

class NumberField;

class PatternForm : public QWidget {
    Q_OBJECT
public:
    explicit PatternForm(QWidget* parent = nullptr);

    motion::plans::Pattern pattern() const;
    void setPattern(const motion::plans::Pattern& p);
    /// Shows the Z height row (instruments whose Z follows XY).
    void setZAvailable(bool available);
    /// The first typed number shown that is not valid, with its reason; empty when all are.
    /// pattern() gives NaN for such a field, which no plan takes.
    QString entryProblem() const;
    /// The entry of a field ("radius_mm", "feed_mm_s"; points as "center_mm.x"), for tests.
    NumberField* field(const QString& name) const { return m_fields.value(name); }
    QComboBox* shapeBox() const { return m_shape; }

signals:
    void changed();

private:
    NumberField* number(const QString& name, double lo, double hi, int decimals, const QString& suffix,
                        const QString& tip = {});
    QWidget* pointRow(const QString& name, const QString& tip);
    QWidget* page(motion::plans::PatternShape shape);
    void showProblems();

    QComboBox* m_shape;
    QLineEdit* m_name;
    QStackedWidget* m_pages;
    NumberField* m_feed;
    QCheckBox* m_useZ;
    NumberField* m_z;
    QWidget* m_zRow;
    QFormLayout* m_common;
    QHash<QString, NumberField*> m_fields;
    QHash<QString, QComboBox*> m_choices;  ///< "direction.circle", "passes_along"
    QLabel* m_problems;
    bool m_loading = false;
    bool m_zAvailable = true;
};

} // namespace ui
