#pragma once
// gtest prints a motion::msg::Message in a failure as its debugString; tests read a nested
// message (a refusal's cause) with nested().
#include "motion/message.h"

#include <memory>
#include <ostream>
#include <variant>

namespace motion::msg {
inline std::ostream& operator<<(std::ostream& os, const Message& m) { return os << debugString(m); }

/// The message in argument `name` of `m`, or an empty message when there is none
/// (so a chain of nested() calls in a test fails on the id, never crashes).
inline Message nested(const Message& m, const std::string& name)
{
    if (const Arg* a = m.arg(name))
        if (const auto* inner = std::get_if<std::shared_ptr<const Message>>(&a->value); inner && *inner)
            return **inner;
    return {};
}
} // namespace motion::msg
