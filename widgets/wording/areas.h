#pragma once
// One function per area, each answering the ids under its prefix (a null QString
// for an id it does not know). wording.cpp dispatches on the prefix; an area adds
// its file and one line to the table there, nothing else.
#include "motion/message.h"

#include <QString>

namespace words::areas {

// Sentences: the id starts with the area's prefix.
QString capability(const msg::Message& m);  ///< "capability."
QString grblText(const msg::Message& m);    ///< "grbl." (the GRBL backend, docs/grbl.md)

// The accuracy bench (accuracy_words.cpp).
QString accuracy(const msg::Message& m);      ///< "accuracy."
QString compensation(const msg::Message& m);  ///< "compensation."
QString fileProblem(const msg::Message& m);   ///< "file."
QString gauge(const msg::Message& m);         ///< "gauge."

// Terms: a null QString for a term id the area does not know.
QString capabilityTerm(const std::string& id);  ///< "instrument.", "capability.because."
QString grblTerm(const std::string& id);        ///< "capability.because.grbl_*", "capability.because.no_*_in_profile", "grbl.status."
QString accuracyTerm(const std::string& id);    ///< "direction.", "rotation."

} // namespace words::areas
