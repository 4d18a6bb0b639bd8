#pragma once
// Numbers in the tuners' messages: four significant digits ("Kp = 2.551").
#include <cstdio>
#include <string>

namespace motion::control {

inline std::string shortNumber(double v)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

} // namespace motion::control
