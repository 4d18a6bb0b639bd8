#include "widgets/common/number_field.h"

#include <QLocale>
#include <QRegularExpression>

#include <cmath>

namespace ui {

NumberField::NumberField(QWidget* parent) : QLineEdit(parent)
{
    // QLineEdit emits textEdited before textChanged for a key: the first marks the text
    // as the operator's; a textChanged without it is a text set by the program.
    connect(this, &QLineEdit::textEdited, this, [this] {
        m_typing = true;
        m_editPending = true;
    });
    connect(this, &QLineEdit::textChanged, this, [this] {
        if (!m_editPending)
            m_typing = false;
        m_editPending = false;
        check();
    });
    connect(this, &QLineEdit::editingFinished, this, &NumberField::finishEntry);
    check();
}

void NumberField::setRange(std::optional<double> minimum, std::optional<double> maximum)
{
    m_min = minimum;
    m_max = maximum;
    check();
}

void NumberField::setInteger(bool integer)
{
    m_integer = integer;
    check();
}

void NumberField::setDisplay(char format, int precision)
{
    m_format = format;
    m_precision = precision;
}

void NumberField::setFieldName(const QString& name)
{
    m_name = name;
    check();
}

void NumberField::setHelp(const QString& help)
{
    m_help = help;
    check();
}

void NumberField::setValue(double v)
{
    setText(m_integer ? QLocale().toString(static_cast<qlonglong>(std::llround(v))) : QLocale().toString(v, m_format, m_precision));
}

std::optional<double> NumberField::value() const { return read().value; }

QString NumberField::problem() const { return read().problem; }

bool NumberField::isIncomplete() const { return m_typing && read().partial; }

void NumberField::finishEntry()
{
    if (!m_typing)
        return;
    m_typing = false;
    check();
}

void NumberField::focusOutEvent(QFocusEvent* event)
{
    QLineEdit::focusOutEvent(event);
    finishEntry();  // editingFinished comes only when the text changed since the last one
}

QString NumberField::limit(double v) const { return m_integer ? QLocale().toString(static_cast<qlonglong>(std::llround(v))) : QLocale().toString(v, 'g', 6); }

NumberField::Reading NumberField::read() const
{
    const QString name = m_name.isEmpty() ? tr("the value") : m_name;
    const QString t = text().trimmed();
    bool ok = false;
    double v = QLocale().toDouble(t, &ok);
    if (!ok)
        v = QLocale::c().toDouble(t, &ok);  // "0.5" typed under a locale with a decimal comma
    Reading r;
    if (t.isEmpty())
        r.problem = tr("%1 is empty: type a number").arg(name);
    else if (!ok || !std::isfinite(v))
        r.problem = tr("“%1” is not a number").arg(t);
    else if (m_integer && v != std::floor(v))
        r.problem = tr("%1 must be a whole number").arg(name);
    else if (m_min && v < *m_min)
        r.problem = *m_min == 0 ? tr("%1 must be 0 or more, not %2").arg(name, t) : tr("%1 must be at least %2, not %3").arg(name, limit(*m_min), t);
    else if (m_max && v > *m_max)
        r.problem = tr("%1 must be at most %2, not %3").arg(name, limit(*m_max), t);
    if (r.problem.isEmpty()) {
        r.value = v;
        return r;
    }
    // What a number looks like on its way to being typed: a sign, digits with a point
    // or comma, an exponent still without its digits.
    static const QRegularExpression start(QStringLiteral("^[+\\-\\x{2212}]?[0-9]*([.,][0-9]*)?([eE][+\\-]?)?$"));
    r.partial = !ok && start.match(t).hasMatch();
    return r;
}

void NumberField::check()
{
    const Reading r = read();
    const bool partial = m_typing && r.partial;
    const QString shown = partial ? QString() : r.problem;
    setStyleSheet(shown.isEmpty() ? QString() : QStringLiteral("QLineEdit { background: #fdd; border: 1px solid #b00020; }"));
    setToolTip(shown.isEmpty() ? m_help : shown);
    setProperty("invalid", !shown.isEmpty());
    emit entryChanged(r.problem.isEmpty());
}

} // namespace ui
