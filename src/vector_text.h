// contactfx internal: how the API's errors show a vector they refuse.
#pragma once

#include "float_text.h"

#include <box2d/b2_math.h>
#include <string>

namespace cfx::detail
{

/// "(x, y)", each number as FloatText writes it ("NaN", "inf", "1e+30").
inline std::string VectorText(b2Vec2 value)
{
    return "(" + FloatText(value.x) + ", " + FloatText(value.y) + ")";
}

} // namespace cfx::detail
