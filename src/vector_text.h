// contactfx internal: how the API's errors show a vector they refuse.
#pragma once

#include <box2d/b2_math.h>
#include <sstream>
#include <string>

namespace cfx::detail
{

/// "(x, y)", each number as a stream writes it ("nan", "inf", "1e+30").
inline std::string VectorText(b2Vec2 value)
{
    std::ostringstream text;
    text << "(" << value.x << ", " << value.y << ")";
    return text.str();
}

} // namespace cfx::detail
