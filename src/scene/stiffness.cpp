#include "scene/stiffness.h"

#include <cmath>

namespace cfx::scene_detail
{

namespace
{

// The effective mass (inertia) b2LinearStiffness (b2AngularStiffness) uses.
float Combine(float a, float b)
{
    if (a > 0.0f && b > 0.0f)
    {
        return a * b / (a + b);
    }
    return a > 0.0f ? a : b;
}

// How many floats on each side of the computed inverse are tried.
constexpr int kSteps = 8;

// Of the floats within kSteps of `guess` (nearest first), one for which `matches` holds; `guess` if none.
template <typename Matches> float Nearby(float guess, Matches matches)
{
    if (matches(guess))
    {
        return guess;
    }
    float below = guess;
    float above = guess;
    for (int step = 0; step < kSteps; ++step)
    {
        below = std::nextafter(below, -INFINITY);
        above = std::nextafter(above, INFINITY);
        if (below >= 0.0f && matches(below))
        {
            return below;
        }
        if (matches(above))
        {
            return above;
        }
    }
    return guess;
}

} // namespace

Spring SpringFromStiffness(float stiffness, float damping, const b2Body& bodyA, const b2Body& bodyB,
                           bool angular)
{
    const float massOrInertia =
        angular ? Combine(bodyA.GetInertia(), bodyB.GetInertia()) : Combine(bodyA.GetMass(), bodyB.GetMass());
    Spring spring;
    if (!(stiffness > 0.0f) || !(massOrInertia > 0.0f))
    {
        return spring;
    }
    const float omega = std::sqrt(stiffness / massOrInertia);
    const auto convert = [&](float frequency, float dampingRatio, float& k, float& d)
    {
        if (angular)
        {
            b2AngularStiffness(k, d, frequency, dampingRatio, &bodyA, &bodyB);
        }
        else
        {
            b2LinearStiffness(k, d, frequency, dampingRatio, &bodyA, &bodyB);
        }
    };
    // The stiffness depends on the frequency alone, the damping on both.
    spring.frequency = Nearby(omega / (2.0f * b2_pi),
                              [&](float frequency)
                              {
                                  float k = 0.0f;
                                  float d = 0.0f;
                                  convert(frequency, 0.0f, k, d);
                                  return k == stiffness;
                              });
    spring.dampingRatio = Nearby(damping / (2.0f * massOrInertia * omega),
                                 [&](float dampingRatio)
                                 {
                                     float k = 0.0f;
                                     float d = 0.0f;
                                     convert(spring.frequency, dampingRatio, k, d);
                                     return d == damping;
                                 });
    return spring;
}

} // namespace cfx::scene_detail
