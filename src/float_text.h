// contactfx internal: a float as messages show it.
#pragma once

#include <charconv>
#include <cmath>
#include <string>

namespace cfx::detail
{

/// The shortest text that reads back as the same float ("0.001", "3e+09"), "NaN" for not-a-number.
inline std::string FloatText(float value)
{
    if (std::isnan(value))
    {
        return "NaN";
    }
    char buffer[64];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

} // namespace cfx::detail
