// contactfx benchmarks: the benchmark scenes' own random numbers (SplitMix64: tiny and the same
// everywhere), so that a scene and its seed give the same bits on every machine.
#pragma once

#include <cstdint>

namespace cfx::bench
{

class SplitMix64
{
public:
    explicit SplitMix64(std::uint64_t seed) : m_state(seed) {}

    /// Uniform in [low, high), from the top 24 bits of the next number.
    float Uniform(float low, float high)
    {
        m_state += 0x9e3779b97f4a7c15ULL;
        std::uint64_t z = m_state;
        z = (z ^ (z >> 30u)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27u)) * 0x94d049bb133111ebULL;
        z ^= z >> 31u;
        const float unit = static_cast<float>(z >> 40u) * (1.0f / 16777216.0f);
        return low + (high - low) * unit;
    }

private:
    std::uint64_t m_state;
};

} // namespace cfx::bench
