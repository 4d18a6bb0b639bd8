#include "widgets/common/number_field.h"

#include <QEvent>
#include <QLabel>
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

void NumberField::setEmptyAllowed(bool allowed)
{
    m_emptyAllowed = allowed;
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

// The help is kept as a string property, not a member: the run-time rewording
// (retranslator.h) rewords a widget's string properties, so a language switch finds the
// help in the new language when the tooltip is next shown from it.
static constexpr const char* kHelpProperty = "bpNumberFieldHelp";

void NumberField::setHelp(const QString& help)
{
    setProperty(kHelpProperty, help);
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

void NumberField::setUnit(const QString& unit)
{
    if (unit.isEmpty() && !m_unit)
        return;
    if (!m_unit) {
        m_unit = new QLabel(this);
        m_unit->setObjectName(QStringLiteral("numberFieldUnit"));
        m_unit->setAttribute(Qt::WA_TransparentForMouseEvents);  // a click there still places the cursor
        m_unit->setStyleSheet(QStringLiteral("color: #666; background: transparent;"));
    }
    m_unit->setText(unit);
    placeUnit();
}

QString NumberField::unit() const { return m_unit ? m_unit->text() : QString(); }

void NumberField::placeUnit()
{
    if (!m_unit)
        return;
    const int w = m_unit->text().isEmpty() ? 0 : fontMetrics().horizontalAdvance(m_unit->text()) + 6;
    setTextMargins(0, 0, w, 0);
    m_unit->setGeometry(width() - w - 2, 0, w, height());
    m_unit->setVisible(w > 0);
}

void NumberField::resizeEvent(QResizeEvent* event)
{
    QLineEdit::resizeEvent(event);
    placeUnit();
}

void NumberField::changeEvent(QEvent* event)
{
    QLineEdit::changeEvent(event);
    if (event->type() == QEvent::LanguageChange)
        check();  // the reason in the language now in force
    else if (event->type() == QEvent::FontChange)
        placeUnit();
}

QString NumberField::shownName() const
{
    if (!m_name.isEmpty())
        return m_name;
    if (const QWidget* p = parentWidget())
        for (const QLabel* l : p->findChildren<QLabel*>())
            if (l->buddy() == this && !l->text().isEmpty()) {
                QString t = l->text();
                t.remove(QLatin1Char('&'));
                while (t.endsWith(QLatin1Char(':')) || t.endsWith(QChar(0xFF1A)))
                    t.chop(1);
                return t.trimmed();
            }
    return tr("the value");
}

QString NumberField::firstProblemUnder(const QWidget* root)
{
    for (const NumberField* f : root->findChildren<NumberField*>()) {
        if (f->isValid() || !f->isVisibleTo(root) || !f->isEnabled())
            continue;
        const QString name = f->shownName();
        return f->problem().contains(name) ? f->problem() : tr("%1: %2").arg(name, f->problem());
    }
    return {};
}

QString NumberField::limit(double v) const { return m_integer ? QLocale().toString(static_cast<qlonglong>(std::llround(v))) : QLocale().toString(v, 'g', 6); }

NumberField::Reading NumberField::read() const
{
    const QString name = shownName();
    const QString t = text().trimmed();
    bool ok = false;
    double v = QLocale().toDouble(t, &ok);
    if (!ok)
        v = QLocale::c().toDouble(t, &ok);  // "0.5" typed under a locale with a decimal comma
    Reading r;
    if (t.isEmpty() && m_emptyAllowed)
        return r;  // valid, and no value
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
    setToolTip(shown.isEmpty() ? property(kHelpProperty).toString() : shown);
    setProperty("invalid", !shown.isEmpty());
    emit entryChanged(r.problem.isEmpty());
}

} // namespace ui
