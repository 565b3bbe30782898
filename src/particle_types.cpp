#include "contactfx/particle_types.h"

#include <algorithm>

namespace cfx
{

ParticleLook LookAt(const ParticleTypeDef& type, float life)
{
    float t = std::clamp(life, 0.0f, 1.0f); // 1 at birth, 0 at death
    auto mix = [t](float atDeath, float atBirth) { return atDeath + (atBirth - atDeath) * t; };
    ParticleLook look;
    look.color.r = mix(type.colorEnd.r, type.colorStart.r);
    look.color.g = mix(type.colorEnd.g, type.colorStart.g);
    look.color.b = mix(type.colorEnd.b, type.colorStart.b);
    look.color.a = mix(type.colorEnd.a, type.colorStart.a) * t;
    look.size = mix(type.sizeEnd, type.sizeStart);
    return look;
}

} // namespace cfx
