#pragma once
// The form of one recipe step: the fields its type takes (docs/recipes.md), the
// others hidden. Every change is reported as the whole edited step and the
// field that changed, so the editor can make it one undoable command.
#include "motion/plans/recipes/recipe.h"

#include <QWidget>

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLineEdit;

namespace ui {

class NumberField;

class StepForm : public QWidget {
    Q_OBJECT
public:
    explicit StepForm(QWidget* parent = nullptr);

    /// The recipe's plate names and the deck's station ids, for the pickers.
    void setChoices(const QStringList& plates, const QStringList& stations);
    /// Shows `step` (index for the title); index −1 empties and disables the form.
    /// Values out of their field's range are shown as they are, marked invalid.
    void setStep(const motion::plates::Step& step, int index);
    const motion::plates::Step& step() const { return m_step; }

    /// Text for the wells field from a step's specs, and back.
    static QString wellsText(const std::vector<std::string>& specs);
    static std::vector<std::string> wellsFromText(const QString& text);

signals:
    void edited(const motion::plates::Step& step, const QString& field);

private:
    void build();
    void showFieldsOf(motion::plates::StepType t);
    void load();
    void changed(const QString& field);

    motion::plates::Step m_step;
    int m_index = -1;
    bool m_loading = false;
    QFormLayout* m_form;
    QComboBox* m_type;
    QComboBox* m_plate;
    QLineEdit* m_wells;
    QComboBox* m_station;
    // Numbers as the file gave them, never clamped: out of range shows marked invalid
    // until the operator fixes it, and an invalid entry changes nothing: what a file says is never changed silently.
    NumberField* m_volume;
    QCheckBox* m_speedSet;
    NumberField* m_speed;
    NumberField* m_cycles;
    NumberField* m_seconds;
    NumberField* m_offset;
    QWidget* m_volumeRow;
    QWidget* m_secondsRow;
    QWidget* m_offsetRow;
    QComboBox* m_sourcePlate;
    QLineEdit* m_sourceWell;
    QComboBox* m_sourceStation;
    QLineEdit* m_note;
    QWidget* m_speedRow;
    QWidget* m_sourceRow;
};

} // namespace ui
