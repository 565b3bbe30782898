// contactfx_harness: a hash of what a run produced, to check determinism against stored values.
//
// Box2D's and Jolt's tests keep hashes of reference runs and compare every build against them; this is the
// same for contactfx: FNV-1a (64 bits) over every event in the order it was reported, then over the live
// particles at the end, bit for bit. Fixture and body addresses are left out (they change from run to run);
// all else an event carries is in. The same scene, config, seed, rate and drive give the same hash with any
// number of threads, on any machine with the same floating-point behaviour (x86-64 SSE2, no -ffast-math).
#pragma once

#include "contactfx/events.h"
#include "contactfx/particle_system.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace cfx
{

class StateHash
{
public:
    /// Any bytes, in order.
    void Add(const void* data, std::size_t size);
    /// Every field of the event except the fixture addresses.
    void Add(const EffectEvent& event);
    void Add(std::span<const EffectEvent> events);
    /// The live particles in pool order: their count, then each one's position, velocity, life and type.
    void Add(const ParticleView& particles);

    std::uint64_t Value() const { return m_value; }
    /// Value() as 16 lower-case hexadecimal digits.
    std::string Hex() const;

private:
    std::uint64_t m_value = 0xcbf29ce484222325ULL;
};

} // namespace cfx
