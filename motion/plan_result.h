#pragma once
// Planning outcome in the style of ruckig: a value, or a message that names the field, the axis
// and the value at fault (profile.not_positive {field: "aMaxMmS2", value: -3, axis: 1}). The
// message is only filled on failure, so a successful plan does not touch the heap.

#include "motion/message.h"

#include <optional>
#include <string>
#include <utility>

namespace motion {

template <class T>
struct PlanResult {
    std::optional<T> value;
    msg::Message error;  ///< empty on success (profile.*, tuning.plant.*: docs/wording.md)

    static PlanResult ok(T v) { return PlanResult{std::optional<T>(std::move(v)), {}}; }
    static PlanResult fail(msg::Message message) { return PlanResult{std::nullopt, std::move(message)}; }
    explicit operator bool() const { return value.has_value(); }
    const T& operator*() const { return *value; }
    const T* operator->() const { return &*value; }
};

}  // namespace motion
