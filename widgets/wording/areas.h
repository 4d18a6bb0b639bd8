#pragma once
// One function per area, each answering the ids under its prefix (a null QString
// for an id it does not know). wording.cpp dispatches on the prefix; an area adds
// its file and one line to the table there, nothing else.
#include "motion/message.h"

#include <QString>

namespace ui::words::areas {

// Sentences: the id starts with one of the area's prefixes.
QString capability(const motion::msg::Message& m);  ///< "capability."
QString accuracy(const motion::msg::Message& m);    ///< "accuracy.", "compensation."
QString device(const motion::msg::Message& m);      ///< "request.", "link.", "device.", "telemetry."
QString deviceEvent(const motion::msg::Message& m); ///< "device.why." (event_words.cpp)
QString refusal(const motion::msg::Message& m);     ///< "device.refused" (refusal_words.cpp)
QString file(const motion::msg::Message& m);        ///< "file."
QString grbl(const motion::msg::Message& m);        ///< "grbl."
QString pattern(const motion::msg::Message& m);     ///< "pattern."
QString plate(const motion::msg::Message& m);       ///< "plate."
QString profile(const motion::msg::Message& m);     ///< "profile."
QString recipe(const motion::msg::Message& m);      ///< "recipe."
QString scan(const motion::msg::Message& m);        ///< "scan."
QString camera(const motion::msg::Message& m);      ///< "camera."
QString tuning(const motion::msg::Message& m);      ///< "tuning."
QString gauge(const motion::msg::Message& m);       ///< "gauge." (accuracy_bench_words.cpp)

// What an area's table does not word yet, in a context of its own whose Chinese is
// pending (tests/build/translations.cmake): the area's function falls back to these.
QString accuracyBench(const motion::msg::Message& m);      ///< "accuracy." runs, imports, readings
QString compensationBench(const motion::msg::Message& m);  ///< "compensation." on the device
QString accuracyBenchTerm(const std::string& id);  ///< "accuracy.source_kind.", "compensation.request."
QString grblBackend(const motion::msg::Message& m);        ///< "grbl." of the GRBL client
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

} // namespace ui::words::areas
