// Names in the files BenchPilot ships (resources/machines/analyzer.deck.json and
// motion/plans/plates/labware.cpp's built-ins): shown in the operator's language.
// Only these exact names are translated, so a name a lab chose is never reworded.
#include "widgets/wording/wording.h"

#include <QCoreApplication>

#include <cstring>

namespace ui::words {
namespace {

// clang-format off
const char* const kShippedNames[] = {
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "back"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "front"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "wash trough"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "waste trough"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "6-well plate, 16.8 mL"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "12-well plate, 6.9 mL"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "24-well plate, 3.4 mL"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "48-well plate, 1.6 mL"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "96-well plate, 360 µL"),
    QT_TRANSLATE_NOOP("ui::words::ShippedNames", "384-well plate, 112 µL"),
};
// clang-format on

} // namespace

QString shippedName(const std::string& name)
{
    for (const char* shipped : kShippedNames)
        if (name == shipped)
            return QCoreApplication::translate("ui::words::ShippedNames", shipped);
    return QString::fromStdString(name);
}

} // namespace ui::words
