#include "contactfx/intensity.h"

#include <algorithm>
#include <cmath>

namespace cfx
{

float MixFriction(FrictionMix mix, float frictionA, float frictionB)
{
    switch (mix)
    {
    case FrictionMix::product:
        return frictionA * frictionB;
    case FrictionMix::sqrt:
        return std::sqrt(frictionA * frictionB);
    case FrictionMix::min:
        return std::min(frictionA, frictionB);
    case FrictionMix::max:
        return std::max(frictionA, frictionB);
    case FrictionMix::mean:
        return 0.5f * (frictionA + frictionB);
    }
    return 0.0f;
}

b2Vec2 TangentialVelocity(const ContactSample& sample)
{
    b2Vec2 relative = sample.velocityA - sample.velocityB;
    return relative - b2Dot(relative, sample.normal) * sample.normal;
}

float RelativeSpeed(SpeedMode mode, const ContactSample& sample)
{
    if (mode == SpeedMode::tangential)
    {
        return TangentialVelocity(sample).Length();
    }
    return (sample.velocityA - sample.velocityB).Length();
}

float ComputeIntensity(const ContactSample& sample, const IntensityModel& model)
{
    float pressure = 1.0f + model.impulseWeight * std::max(sample.normalForce, 0.0f);
    const float friction = sample.contactFriction >= 0.0f
                               ? sample.contactFriction
                               : MixFriction(model.friction, sample.frictionA, sample.frictionB);
    return RelativeSpeed(model.speed, sample) * friction * pressure;
}

} // namespace cfx
