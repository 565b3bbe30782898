// contactfx: how hard two surfaces rub, as one number.
//
// The tutorial's intensity is |vA - vB| * frictionA * frictionB at the first manifold point. That has
// known weaknesses (its own list): approach along the normal counts as rubbing, the friction mix is not
// Box2D's, the pressure between the surfaces is ignored. An IntensityModel picks each ingredient; the
// tutorial's choice is one setting of it. Pure functions, no state, safe from any thread.
#pragma once

#include <box2d/b2_math.h>
#include <cstdint>

namespace cfx
{

/// Which relative speed counts.
enum class SpeedMode : std::uint8_t
{
    full,       ///< |vA - vB| (the tutorial): approach along the normal counts too
    tangential, ///< only the component along the contact surface: sliding, not approaching
};

/// How the two fixtures' frictions combine into one.
enum class FrictionMix : std::uint8_t
{
    product, ///< fA * fB (the tutorial)
    sqrt,    ///< sqrt(fA * fB), Box2D's b2MixFriction
    min,
    max,
    mean, ///< (fA + fB) / 2
};

/// Which manifold points make samples.
enum class ManifoldPoints : std::uint8_t
{
    first, ///< point 0 only (the tutorial)
    all,   ///< every point of the manifold (up to 2 in Box2D 2.4)
};

/// How one contact sample becomes an intensity:
/// intensity = speed * mix(frictionA, frictionB) * (1 + impulseWeight * normalForce).
struct IntensityModel
{
    SpeedMode speed = SpeedMode::tangential;
    FrictionMix friction = FrictionMix::sqrt;
    ManifoldPoints points = ManifoldPoints::all;
    /// Weight of the pressure between the surfaces, in 1/N (newtons: normal impulse / step time).
    /// 0 ignores pressure (the tutorial). [0, 1000].
    float impulseWeight = 0.0f;

    bool operator==(const IntensityModel&) const = default;
};

/// Everything known about one manifold point after a step.
struct ContactSample
{
    b2Vec2 point{0.0f, 0.0f};     ///< world point, m
    b2Vec2 normal{0.0f, 1.0f};    ///< unit normal from fixture A to fixture B
    b2Vec2 velocityA{0.0f, 0.0f}; ///< velocity of body A at the point, m/s
    b2Vec2 velocityB{0.0f, 0.0f}; ///< velocity of body B at the point, m/s
    float frictionA = 0.0f;       ///< friction coefficient of fixture A, >= 0
    float frictionB = 0.0f;       ///< friction coefficient of fixture B, >= 0
    /// >= 0: the contact's own friction, when it is not Box2D's mix of frictionA and frictionB (the
    /// application set it with b2Contact::SetFriction, an icy patch): used as it is instead of the rule's
    /// mix of frictionA and frictionB. < 0: the contact has Box2D's mix.
    float contactFriction = -1.0f;
    /// N, >= 0: the normal force pressing the sample: PostSolve normal impulse / step time (rate emission
    /// gives each point its body pair's total, see rules.h)
    float normalForce = 0.0f;
};

/// Friction of a pair under a mix. Inputs >= 0.
float MixFriction(FrictionMix mix, float frictionA, float frictionB);

/// Relative speed of the sample under a speed mode, m/s.
float RelativeSpeed(SpeedMode mode, const ContactSample& sample);

/// Tangential relative velocity of A with respect to B at the point, m/s (normal component removed).
b2Vec2 TangentialVelocity(const ContactSample& sample);

/// The intensity of one sample under a model; >= 0 for valid inputs.
float ComputeIntensity(const ContactSample& sample, const IntensityModel& model);

} // namespace cfx
