// What is typed into a number is what the screen keeps: the walk finds every numeric
// entry on every screen of the main window, for both simulated instruments (entry
// fields, spin boxes, line edits with a number validator, editable combos' line edits),
// types "-5", "1e9" and "abc" into each and leaves the field. Each must either keep the
// text as typed and mark it invalid with a reason, or hold exactly the number typed —
// never a silently different number ("-5" turned into 5, "1e9" into 19, "abc" dropped).
#include "gui_window.h"

#include "widgets/common/number_field.h"

#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QDoubleValidator>
#include <QFocusEvent>
#include <QIntValidator>
#include <QLineEdit>
#include <QLocale>
#include <QScrollArea>
#include <QSpinBox>
#include <QTest>

#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>

namespace {

/// A widget a person types a number into, found by what it is, not by its name.
bool numericEntry(QWidget* w)
{
    if (qobject_cast<ui::NumberField*>(w) || qobject_cast<QAbstractSpinBox*>(w))
        return true;
    auto* e = qobject_cast<QLineEdit*>(w);
    if (!e || qobject_cast<QAbstractSpinBox*>(e->parent()))
        return false;  // a spin box's own line edit: the spin box is walked
    const QValidator* v = e->validator();
    return qobject_cast<const QDoubleValidator*>(v) || qobject_cast<const QIntValidator*>(v);
}

QString describe(QWidget* w, const QString& screen)
{
    QString path;
    for (QObject* o = w; o && o->objectName() != QStringLiteral("screenScroll_%1").arg(screen); o = o->parent())
        if (!o->objectName().isEmpty() && !o->objectName().startsWith(QLatin1String("qt_"))) {
            path = o->objectName();
            break;
        }
    return QStringLiteral("%1: %2 %3").arg(screen, QString::fromLatin1(w->metaObject()->className()),
                                           path.isEmpty() ? QStringLiteral("(unnamed)") : path);
}

void leave(QWidget* w)
{
    // What leaving the field does: a spin box interprets and fixes up, a validated line
    // edit fixes up, a NumberField keeps the text.
    QFocusEvent out(QEvent::FocusOut, Qt::TabFocusReason);
    QApplication::sendEvent(w, &out);
}

std::optional<double> parsed(const QString& typed)
{
    bool ok = false;
    const double v = QLocale::c().toDouble(typed, &ok);
    return ok && std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

/// Types `typed` into `w` and says what went wrong, or empty.
QString typeInto(QWidget* w, const QString& typed)
{
    const std::optional<double> number = parsed(typed);
    if (auto* s = qobject_cast<QAbstractSpinBox*>(w)) {
        s->selectAll();
        QTest::keyClicks(s, typed);
        leave(s);
        double value = std::nan("");
        if (auto* d = qobject_cast<QDoubleSpinBox*>(s))
            value = d->value();
        else if (auto* i = qobject_cast<QSpinBox*>(s))
            value = i->value();
        if (number && value == *number)
            return {};
        return QStringLiteral("“%1” became “%2” (%3) with nothing said").arg(typed, s->text()).arg(value);
    }
    auto* e = qobject_cast<QLineEdit*>(w);
    e->selectAll();
    e->del();
    QTest::keyClicks(e, typed);
    leave(e);
    const bool kept = e->text() == typed;
    if (auto* f = qobject_cast<ui::NumberField*>(e)) {
        if (kept && !f->isValid() && !f->problem().isEmpty() && f->toolTip().contains(f->problem()))
            return {};
        if (kept && f->isValid() && number && f->value() && *f->value() == *number)
            return {};
        if (!kept)
            return QStringLiteral("“%1” became “%2”").arg(typed, e->text());
        return f->isValid() ? QStringLiteral("“%1” is taken as %2").arg(typed).arg(f->value().value_or(std::nan("")))
                            : QStringLiteral("“%1” is marked invalid without a reason shown").arg(typed);
    }
    if (kept && e->property("invalid").toBool() && !e->toolTip().isEmpty())
        return {};
    if (kept && number && e->hasAcceptableInput())
        return {};
    return QStringLiteral("“%1” became “%2” with nothing said").arg(typed, e->text());
}

} // namespace

TEST(TrustNumbers, EveryNumberTypedOnEveryScreenIsKeptOrRefusedWithItsReason)
{
    auto w = guitest::openReadyWindow(QSize(1366, 768));
    ASSERT_TRUE(w);
    const QStringList typedTexts{QStringLiteral("-5"), QStringLiteral("1e9"), QStringLiteral("abc")};
    std::set<QWidget*> walked;
    std::map<QString, int> perScreen;
    QStringList failures, notReached;
    for (int instrument = 0; instrument < 2; ++instrument) {
        w->showInstrument(instrument);
        for (const QString& screen : w->screenNames()) {
            ASSERT_TRUE(w->showScreen(screen));
            auto* page = w->findChild<QScrollArea*>(QStringLiteral("screenScroll_%1").arg(screen));
            ASSERT_NE(page, nullptr) << screen.toStdString();
            // Screens that pick their instrument with a combo of their own.
            for (auto* c : page->findChildren<QComboBox*>())
                if (c->objectName().endsWith(QLatin1String("Instrument")) && c->count() > instrument)
                    c->setCurrentIndex(instrument);
            guitest::pump(30);
            for (QWidget* input : page->findChildren<QWidget*>()) {
                if (!numericEntry(input))
                    continue;
                if (!input->isEnabled())
                    input->setEnabled(true);  // a field greyed until a box is ticked is typed into later
                if (!input->isEnabled()) {
                    notReached << describe(input, screen);
                    continue;
                }
                ++perScreen[screen];
                walked.insert(input);
                auto* asLine = qobject_cast<QLineEdit*>(input);
                const QString before = asLine ? asLine->text() : qobject_cast<QAbstractSpinBox*>(input)->text();
                for (const QString& typed : typedTexts)
                    if (const QString why = typeInto(input, typed); !why.isEmpty())
                        failures << QStringLiteral("%1: %2").arg(describe(input, screen), why);
                if (asLine)
                    asLine->setText(before);
            }
        }
    }
    for (const auto& [screen, count] : perScreen)
        std::printf("%s: %d numeric entries walked\n", qPrintable(screen), count);
    for (const QString& n : notReached)
        std::printf("not reached (its panel is greyed): %s\n", qPrintable(n));
    failures.removeDuplicates();
    EXPECT_TRUE(failures.isEmpty()) << failures.size() << " silently changed:\n" << failures.join(QLatin1Char('\n')).toStdString();
    // The walk finds inputs by what they are: it must find the screens' forms.
    for (const char* screen : {"jog", "profiles", "tuning", "scan", "calibration", "joystick", "patterns"})
        EXPECT_GT(perScreen[QString::fromLatin1(screen)], 0) << "no numeric entry found on " << screen;
    EXPECT_GE(walked.size(), 60u);
}

// The walk's judge, on the widgets it exists to catch: a spin box turns "-5" into 5 and
// "1e9" into 19 and drops "abc"; a line edit with a number validator drops "abc".
TEST(TrustNumbers, TheWalkCatchesWidgetsThatChangeWhatWasTyped)
{
    QDoubleSpinBox spin;
    spin.setRange(0, 100);
    EXPECT_FALSE(typeInto(&spin, QStringLiteral("-5")).isEmpty()) << spin.text().toStdString();
    EXPECT_FALSE(typeInto(&spin, QStringLiteral("1e9")).isEmpty()) << spin.text().toStdString();
    EXPECT_FALSE(typeInto(&spin, QStringLiteral("abc")).isEmpty()) << spin.text().toStdString();
    QLineEdit validated;
    validated.setValidator(new QDoubleValidator(0, 100, 3, &validated));
    EXPECT_TRUE(numericEntry(&validated));
    EXPECT_FALSE(typeInto(&validated, QStringLiteral("abc")).isEmpty()) << validated.text().toStdString();
    // And passes one that keeps the text and says why.
    ui::NumberField field;
    field.setRange(0, 100);
    for (const char* typed : {"-5", "1e9", "abc", "42"})
        EXPECT_TRUE(typeInto(&field, QString::fromLatin1(typed)).isEmpty()) << typed;
}
