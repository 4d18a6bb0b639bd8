#pragma once
// Constants every part of the motion library uses, defined once (std::numbers
// is C++20; a copy per file collides in a unity build).

namespace motion {

inline constexpr double kPi = 3.14159265358979323846;

} // namespace motion
