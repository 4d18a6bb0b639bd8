#include "device/jobs/tuning/tuning_words.h"

#include <QCoreApplication>

namespace dev {
namespace {

constexpr const char* kContext = "dev::TuningWords";

// The keys motion/ hands out, listed so that lupdate finds them; they are
// translated by key at run time (motion::control::endReasonName and the outcomes
// TuningRunner stores).
[[maybe_unused]] const char* const kWords[] = {
    QT_TRANSLATE_NOOP("dev::TuningWords", "running"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "settled"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "completed"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "max excursion crossed"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "max following error crossed"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "max duration reached"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "stopped"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "E-stop"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "host went silent"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "fault"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "unknown"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "decays"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "sustained"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "grows"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "no oscillation"),
    QT_TRANSLATE_NOOP("dev::TuningWords", "hit the envelope"),
};

} // namespace

QString endReasonText(motion::control::EndReason reason)
{
    return QCoreApplication::translate(kContext, motion::control::endReasonName(reason));
}

QString outcomeText(const std::string& outcome)
{
    // A word not in the list above finds no translation and comes back as it is.
    return QCoreApplication::translate(kContext, outcome.c_str());
}

} // namespace dev
