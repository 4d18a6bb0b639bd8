#pragma once
// One function per area, each answering the ids under its prefix (a null QString
// for an id it does not know). wording.cpp dispatches on the prefix; an area adds
// its file and one line to the table there, nothing else.
#include "motion/message.h"

#include <QString>

namespace words::areas {

// Sentences: the id starts with one of the area's prefixes.
QString capability(const msg::Message& m);  ///< "capability."
QString accuracy(const msg::Message& m);    ///< "accuracy.", "compensation."
QString device(const msg::Message& m);      ///< "request.", "link.", "device.", "telemetry."
QString deviceEvent(const msg::Message& m); ///< "device.why." (event_words.cpp)
QString refusal(const msg::Message& m);     ///< "device.refused" (refusal_words.cpp)
QString file(const msg::Message& m);        ///< "file."
QString grbl(const msg::Message& m);        ///< "grbl."
QString pattern(const msg::Message& m);     ///< "pattern."
QString plate(const msg::Message& m);       ///< "plate."
QString profile(const msg::Message& m);     ///< "profile."
QString recipe(const msg::Message& m);      ///< "recipe."
QString scan(const msg::Message& m);        ///< "scan."
QString camera(const msg::Message& m);      ///< "camera."
QString tuning(const msg::Message& m);      ///< "tuning."
QString gauge(const msg::Message& m);       ///< "gauge." (accuracy_bench_words.cpp)

// What an area's table does not word yet, in a context of its own whose Chinese is
// pending (tests/build/translations.cmake): the area's function falls back to these.
QString accuracyBench(const msg::Message& m);      ///< "accuracy." runs, imports, readings
QString compensationBench(const msg::Message& m);  ///< "compensation." on the device
QString accuracyBenchTerm(const std::string& id);  ///< "accuracy.source_kind.", "compensation.request."
QString grblBackend(const msg::Message& m);        ///< "grbl." of the GRBL client
QString grblBackendTerm(const std::string& id);    ///< "capability.because.grbl_*", "grbl.status."

// Terms: a null QString for a term id the area does not know.
QString capabilityTerm(const std::string& id);  ///< "instrument.", "capability.because."
QString accuracyTerm(const std::string& id);    ///< "direction.", "rotation."
QString deviceTerm(const std::string& id);      ///< "request.", "device.error.", "device.event.", "path.", "link.state."
QString fileTerm(const std::string& id);        ///< "json.type."
QString grblTerm(const std::string& id);        ///< "grbl.status."
QString patternTerm(const std::string& id);     ///< "segment.", "pattern.state."
QString recipeTerm(const std::string& id);      ///< "recipe.state.", "recipe.move.", "recipe.step."
QString scanTerm(const std::string& id);        ///< "scan.state."
QString tuningTerm(const std::string& id);      ///< "tuning.state.", "tuning.end.", "tuning.outcome.", "tuning.rule."

} // namespace words::areas
