#pragma once
// One numeric entry for every field a person types a number into where a
// wrong number matters (gains, recipe depths, slots): the text is kept exactly
// as typed or as a file gave it — no validator drops a "-" or clamps 700 to
// 100 — and a text that is not a valid number for the field is shown as
// invalid with the reason (tooltip and problem()), and value() is nullopt
// until it is fixed. Whoever sends the value disables its action while invalid.
//
// value(), isValid() and problem() always read the text as it is now, so a slot
// connected to textEdited (emitted before textChanged) sees the key just typed.
// A number still being typed ("-", "1e", an emptied field) is incomplete, not
// wrong: it is not marked invalid until the operator leaves the field, presses
// Enter or the owner calls finishEntry(); value() is nullopt meanwhile.
#include <QLineEdit>

class QLabel;

#include <optional>

namespace ui {

class NumberField : public QLineEdit {
    Q_OBJECT
public:
    explicit NumberField(QWidget* parent = nullptr);

    /// Limits the value must lie within (inclusive); unset: no limit on that side.
    void setRange(std::optional<double> minimum, std::optional<double> maximum);
    /// Only whole numbers are valid.
    void setInteger(bool integer);
    /// An empty field is valid, with no value (a target not typed yet); by default it is not.
    void setEmptyAllowed(bool allowed);
    /// Digits after the point when setValue() writes a number (significant digits with 'g').
    void setDisplay(char format, int precision);
    /// What the field is for, in the reason ("Kp", "depth"); empty: "the value".
    void setFieldName(const QString& name);
    QString fieldName() const { return m_name; }
    /// Text appended to the tooltip while the entry is valid (what the field means).
    void setHelp(const QString& help);
    /// A unit shown at the field's right end (" mm", " µm"), outside the text: what is
    /// typed stays the number alone. Empty: none.
    void setUnit(const QString& unit);
    QString unit() const;

    /// Writes `v` as text, even outside the range (a file's value is shown as it is, marked invalid).
    void setValue(double v);
    std::optional<double> value() const;
    /// The value, or `fallback` while the entry is invalid (for previews; an action that
    /// sends the value is disabled instead).
    double valueOr(double fallback) const { return value().value_or(fallback); }
    bool isValid() const { return problem().isEmpty(); }
    /// Why the entry is invalid, for people; empty while valid.
    QString problem() const;
    /// The operator is typing and the text is the start of a number ("-", "1e", ""):
    /// not valid yet, and not shown as an error yet.
    bool isIncomplete() const;
    /// The operator is done with the field (an owner's Apply): an incomplete entry is an error from now on.
    void finishEntry();

    /// The first invalid field shown under `root` (in creation order), as its reason
    /// preceded by the field's name where the reason does not name it; empty if none.
    static QString firstProblemUnder(const QWidget* root);

signals:
    /// After every change of the text (typed or set), and when an entry is finished:
    /// valid or not. value(), problem() and isIncomplete() are current when it comes.
    void entryChanged(bool valid);

protected:
    void resizeEvent(QResizeEvent* event) override;
    void changeEvent(QEvent* event) override;
    void focusOutEvent(QFocusEvent* event) override;

private:
    struct Reading {
        std::optional<double> value;
        QString problem;
        bool partial = false;  ///< the start of a number, not a number yet
    };
    Reading read() const;
    void check();
    /// The name the reason gives: setFieldName's, else the text of the label that is
    /// this field's buddy (a form row's label), else "the value".
    QString shownName() const;
    void placeUnit();
    QString limit(double v) const;

    std::optional<double> m_min, m_max;
    bool m_integer = false;
    bool m_emptyAllowed = false;
    char m_format = 'g';
    int m_precision = 6;
    QString m_name;
    QLabel* m_unit = nullptr;
    bool m_typing = false;       ///< the text came from the operator's keys and the entry is not finished
    bool m_editPending = false;  ///< textEdited seen, its textChanged not yet
};

} // namespace ui
