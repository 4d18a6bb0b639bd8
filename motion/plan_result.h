#pragma once
// Planning outcome in the style of ruckig: a value, or a message that names the field, the axis
// and the value at fault ("axis 1: aMaxMmS2 = -3 must be finite and > 0"). The message string is
// only filled on failure, so a successful plan does not touch the heap.

#include <optional>
#include <string>
#include <utility>

namespace motion {

template <class T>
struct PlanResult {
    std::optional<T> value;
    std::string error;  ///< empty on success

    static PlanResult ok(T v) { return PlanResult{std::optional<T>(std::move(v)), {}}; }
    static PlanResult fail(std::string message) { return PlanResult{std::nullopt, std::move(message)}; }
    explicit operator bool() const { return value.has_value(); }
    const T& operator*() const { return *value; }
    const T* operator->() const { return &*value; }
};

}  // namespace motion
