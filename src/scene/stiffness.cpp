#include "scene/stiffness.h"

#include "scene/rube_limits.h"

#include <algorithm>
#include <array>
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

// The largest frequency and damping ratio the reader accepts.
constexpr float kMostFrequency = static_cast<float>(kFrequency.max);
constexpr float kMostDampingRatio = static_cast<float>(kDampingRatio.max);

// How many floats on each side of a computed inverse are tried.
constexpr int kSteps = 8;

// The floats within kSteps of `guess` (clamped to [0, most]) that lie in [0, most], nearest first.
std::array<float, 2 * kSteps + 1> Nearby(float guess, float most, int& count)
{
    std::array<float, 2 * kSteps + 1> found{};
    count = 0;
    const float middle = std::clamp(guess, 0.0f, most);
    found[count++] = middle;
    float below = middle;
    float above = middle;
    for (int step = 0; step < kSteps; ++step)
    {
        below = std::nextafter(below, -INFINITY);
        above = std::nextafter(above, INFINITY);
        if (below >= 0.0f)
        {
            found[count++] = below;
        }
        if (above <= most)
        {
            found[count++] = above;
        }
    }
    return found;
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
    // The nearest pair that converts back exactly: the stiffness depends on the frequency alone (several
    // frequencies may give it), the damping on both. Both stay within the ranges the reader accepts.
    const float frequencyGuess = omega / (2.0f * b2_pi);
    const float ratioGuess = damping / (2.0f * massOrInertia * omega);
    int frequencies = 0;
    const auto frequencyCandidates = Nearby(frequencyGuess, kMostFrequency, frequencies);
    int ratios = 0;
    const auto ratioCandidates = Nearby(ratioGuess, kMostDampingRatio, ratios);
    spring.frequency = frequencyCandidates[0];
    spring.dampingRatio = ratioCandidates[0];
    for (int i = 0; i < frequencies; ++i)
    {
        float k = 0.0f;
        float d = 0.0f;
        convert(frequencyCandidates[i], 0.0f, k, d);
        if (k != stiffness)
        {
            continue;
        }
        for (int j = 0; j < ratios; ++j)
        {
            convert(frequencyCandidates[i], ratioCandidates[j], k, d);
            if (d == damping)
            {
                spring.frequency = frequencyCandidates[i];
                spring.dampingRatio = ratioCandidates[j];
                return spring;
            }
        }
    }
    return spring;
}

} // namespace cfx::scene_detail
