// contactfx_harness: the run hash (see state_hash.h).
#include "harness/state_hash.h"

#include <cstdio>

namespace cfx
{

void StateHash::Add(const void* data, std::size_t size)
{
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
    {
        m_value = (m_value ^ bytes[i]) * 0x100000001b3ULL;
    }
}

void StateHash::Add(const EffectEvent& event)
{
    const auto type = static_cast<std::uint8_t>(event.type);
    const auto end = static_cast<std::uint8_t>(event.end);
    Add(&type, sizeof type);
    Add(&end, sizeof end);
    Add(&event.rule.index, sizeof event.rule.index);
    Add(&event.materialA.index, sizeof event.materialA.index);
    Add(&event.materialB.index, sizeof event.materialB.index);
    Add(&event.id, sizeof event.id);
    Add(&event.step, sizeof event.step);
    const float values[] = {event.point.x,   event.point.y,         event.normal.x,      event.normal.y,
                            event.intensity, event.tangentialSpeed, event.normalImpulse, event.approachSpeed};
    Add(values, sizeof values);
    if (event.type == EffectEventType::particleHits)
    {
        // Not the body: its address differs from run to run.
        Add(&event.particleType.index, sizeof event.particleType.index);
        Add(&event.count, sizeof event.count);
    }
}

void StateHash::Add(std::span<const EffectEvent> events)
{
    for (const EffectEvent& event : events)
    {
        Add(event);
    }
}

void StateHash::Add(const ParticleView& particles)
{
    Add(&particles.count, sizeof particles.count);
    for (std::uint32_t i = 0; i < particles.count; ++i)
    {
        const std::uint32_t slot = particles.Slot(i);
        const float values[] = {particles.positionX[slot], particles.positionY[slot],
                                particles.velocityX[slot], particles.velocityY[slot], particles.life[slot]};
        Add(values, sizeof values);
        Add(&particles.type[slot], sizeof particles.type[slot]);
    }
}

std::string StateHash::Hex() const
{
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(m_value));
    return text;
}

} // namespace cfx
