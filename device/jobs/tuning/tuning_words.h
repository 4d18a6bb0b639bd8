#pragma once
// The words motion/ keeps as plain keys, because it has no Qt: how a run ended
// and how a trial's oscillation went. Result files and JSON output keep the
// keys; whatever a person reads goes through these, so it is translated.
#include "motion/control/experiment.h"

#include <QString>

#include <string>

namespace dev {

/// How a test run ended ("settled", "max excursion crossed", …), for people.
QString endReasonText(motion::control::EndReason reason);

/// An outcome as a tuning result stores it: a trial's ("decays", "sustained",
/// "grows", "no oscillation", "hit the envelope") or a verification's (an end
/// reason's name). Anything else, from a newer file, shows as it is.
QString outcomeText(const std::string& outcome);

} // namespace dev
