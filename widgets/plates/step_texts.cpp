#include "widgets/plates/step_texts.h"

#include "widgets/wording/wording.h"

#include <QCoreApplication>

namespace ui {

namespace {
/// The translation context of these texts (lupdate reads tr() calls in it).
struct StepTexts {
    Q_DECLARE_TR_FUNCTIONS(StepTexts)
};
QString number(double v) { return QString::number(v, 'g', 10); }
} // namespace

QString stepTypeTitle(motion::plates::StepType type)
{
    using motion::plates::StepType;
    switch (type) {
    case StepType::Aspirate: return StepTexts::tr("Aspirate");
    case StepType::Dispense: return StepTexts::tr("Dispense");
    case StepType::Mix: return StepTexts::tr("Mix");
    case StepType::Wash: return StepTexts::tr("Wash");
    case StepType::AirGap: return StepTexts::tr("Air gap");
    case StepType::Wait: return StepTexts::tr("Wait");
    case StepType::TouchOff: return StepTexts::tr("Touch off");
    }
    return QString::fromLatin1(motion::plates::stepTypeName(type));
}

QString opTitle(const motion::plates::PlanOp& op)
{
    using motion::plates::StepType;
    const QString where = !op.station.empty() ? StepTexts::tr("station %1").arg(QString::fromStdString(op.station))
                                              : QString::fromStdString(op.plate) + QLatin1Char(' ') + QString::fromStdString(op.well);
    const QString v = number(op.volumeUl);
    switch (op.type) {
    case StepType::Aspirate: return StepTexts::tr("Aspirate %1 µL from %2").arg(v, where);
    case StepType::Dispense: return StepTexts::tr("Dispense %1 µL into %2").arg(v, where);
    case StepType::Mix: return StepTexts::tr("Mix %1 µL in %2").arg(v, where);
    case StepType::Wash: return StepTexts::tr("Wash %1 µL at %2").arg(v, where);
    case StepType::AirGap: return StepTexts::tr("Air gap %1 µL").arg(v);
    case StepType::Wait: return StepTexts::tr("Wait %1 s").arg(number(op.moves.empty() ? 0 : op.moves.front().seconds));
    case StepType::TouchOff: return StepTexts::tr("Touch off in %1").arg(where);
    }
    return ui::words::text(op.label());
}

} // namespace ui
