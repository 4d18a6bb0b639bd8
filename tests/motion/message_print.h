#pragma once
// gtest prints a msg::Message in a failure as its debugString.
#include "motion/message.h"

#include <ostream>

namespace msg {
inline std::ostream& operator<<(std::ostream& os, const Message& m) { return os << debugString(m); }
} // namespace msg
