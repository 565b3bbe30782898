#include "scene/stiffness.h"

#include <cmath>

namespace cfx::scene_detail
{

namespace
{

float Combine(float a, float b)
{
    if (a > 0.0f && b > 0.0f)
    {
        return a * b / (a + b);
    }
    return a > 0.0f ? a : b;
}

} // namespace

float LinearSpringMass(const b2Body& bodyA, const b2Body& bodyB)
{
    return Combine(bodyA.GetMass(), bodyB.GetMass());
}

float AngularSpringInertia(const b2Body& bodyA, const b2Body& bodyB)
{
    return Combine(bodyA.GetInertia(), bodyB.GetInertia());
}

Spring SpringFromStiffness(float stiffness, float damping, float massOrInertia)
{
    Spring spring;
    if (!(stiffness > 0.0f) || !(massOrInertia > 0.0f))
    {
        return spring;
    }
    const float omega = std::sqrt(stiffness / massOrInertia);
    spring.frequency = omega / (2.0f * b2_pi);
    spring.dampingRatio = damping / (2.0f * massOrInertia * omega);
    return spring;
}

} // namespace cfx::scene_detail
