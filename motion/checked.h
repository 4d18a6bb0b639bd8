#pragma once
// "A value, or the problems why not": what every validator, planner and file reader
// returns (the shape of ruckig's input → output + result). A Checked<T> holds either
// the value, with the warnings that came with it, or a list of problems with at least
// one error. Nothing is allocated on success without warnings, so a planner in a
// loop pays for the check only when it refuses.
//
// Plain C++ (no Qt), like the rest of motion/.
#include "motion/problem.h"

#include <cassert>
#include <optional>
#include <utility>

namespace motion::msg {

template <class T>
class Checked {
public:
    /// The value, with the warnings (only warnings) found on the way.
    static Checked ok(T value, Problems warnings = {})
    {
        assert(!hasErrors(warnings));
        Checked c;
        c.m_value.emplace(std::move(value));
        c.m_problems = std::move(warnings);
        return c;
    }
    /// Refused: `problems` holds at least one error (and may hold warnings beside).
    static Checked refused(Problems problems)
    {
        assert(hasErrors(problems));
        Checked c;
        c.m_problems = std::move(problems);
        return c;
    }
    /// Refused for one reason that names its field in its arguments.
    static Checked fail(Message why, std::string path = {}) { return refused({motion::msg::error(std::move(path), std::move(why))}); }
    /// The value when `problems` holds no error, refused otherwise: a validator's verdict.
    static Checked from(T value, Problems problems)
    {
        return hasErrors(problems) ? refused(std::move(problems)) : ok(std::move(value), std::move(problems));
    }

    bool ok() const { return m_value.has_value(); }
    explicit operator bool() const { return ok(); }
    const T& value() const { return *m_value; }
    T& value() { return *m_value; }
    const T& operator*() const { return *m_value; }
    T& operator*() { return *m_value; }
    const T* operator->() const { return &*m_value; }
    T* operator->() { return &*m_value; }
    /// The value itself, moved out (only when ok()).
    T take() { return std::move(*m_value); }

    /// Errors when refused; warnings either way. Empty when fine.
    const Problems& problems() const { return m_problems; }
    /// The first error's message (empty when ok): for a caller that reports one reason.
    Message error() const
    {
        for (const Problem& p : m_problems)
            if (p.isError())
                return p.message;
        return {};
    }

private:
    Checked() = default;
    std::optional<T> m_value;
    Problems m_problems;
};

} // namespace motion::msg
