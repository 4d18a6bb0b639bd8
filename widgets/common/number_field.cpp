#include "widgets/common/number_field.h"

#include <QLocale>

#include <cmath>

namespace ui {

NumberField::NumberField(QWidget* parent) : QLineEdit(parent)
{
    connect(this, &QLineEdit::textChanged, this, [this] { check(); });
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

std::optional<double> NumberField::value() const { return m_value; }

QString NumberField::limit(double v) const { return m_integer ? QLocale().toString(static_cast<qlonglong>(std::llround(v))) : QLocale().toString(v, 'g', 6); }

void NumberField::check()
{
    const QString name = m_name.isEmpty() ? tr("the value") : m_name;
    const QString t = text().trimmed();
    bool ok = false;
    double v = QLocale().toDouble(t, &ok);
    if (!ok)
        v = QLocale::c().toDouble(t, &ok);  // "0.5" typed under a locale with a decimal comma
    QString problem;
    if (t.isEmpty())
        problem = tr("%1 is empty: type a number").arg(name);
    else if (!ok || !std::isfinite(v))
        problem = tr("“%1” is not a number").arg(t);
    else if (m_integer && v != std::floor(v))
        problem = tr("%1 must be a whole number").arg(name);
    else if (m_min && v < *m_min)
        problem = *m_min == 0 ? tr("%1 must be 0 or more, not %2").arg(name, t) : tr("%1 must be at least %2, not %3").arg(name, limit(*m_min), t);
    else if (m_max && v > *m_max)
        problem = tr("%1 must be at most %2, not %3").arg(name, limit(*m_max), t);
    m_problem = problem;
    m_value = problem.isEmpty() ? std::optional<double>(v) : std::nullopt;
    setStyleSheet(problem.isEmpty() ? QString() : QStringLiteral("QLineEdit { background: #fdd; border: 1px solid #b00020; }"));
    setToolTip(problem.isEmpty() ? m_help : problem);
    setProperty("invalid", !problem.isEmpty());
    emit entryChanged(problem.isEmpty());
}

} // namespace ui
