// The step the sound tests drive their scenes and voices with.
#pragma once

namespace cfx::test
{

inline constexpr float kDt = 1.0f / 60.0f; ///< s: 60 Hz

} // namespace cfx::test
