// contactfx internal: the one source of randomness.
//
// PCG32 (O'Neill's permuted congruential generator, XSH RR variant): small state, good statistics, and
// the same sequence on every platform and standard library, which std::uniform_real_distribution does not
// promise. Floats are made from the top 24 bits, so they are exact and identical everywhere.
#pragma once

#include <cstdint>

namespace cfx
{

class Random
{
public:
    explicit Random(std::uint64_t seed = 1, std::uint64_t stream = 0x853c49e6748fea9bULL)
        : m_increment((stream << 1u) | 1u)
    {
        NextU32();
        m_state += seed;
        NextU32();
    }

    std::uint32_t NextU32()
    {
        std::uint64_t old = m_state;
        m_state = old * 6364136223846793005ULL + m_increment;
        auto xorShifted = static_cast<std::uint32_t>(((old >> 18u) ^ old) >> 27u);
        auto rotation = static_cast<std::uint32_t>(old >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((~rotation + 1u) & 31u));
    }

    /// Uniform in [0, 1).
    float NextFloat() { return static_cast<float>(NextU32() >> 8) * (1.0f / 16777216.0f); }

    /// Uniform in [low, high).
    float Range(float low, float high) { return low + (high - low) * NextFloat(); }

private:
    std::uint64_t m_state = 0;
    std::uint64_t m_increment;
};

} // namespace cfx
