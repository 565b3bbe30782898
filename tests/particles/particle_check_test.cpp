// The particle check's pass-through count (particles/particle_check.h): a particle that went through a
// moving body, seen from the body, is counted; one the body carried, pushed ahead or slid around a corner
// of, or that flew past it, is not. The check is fed particles' paths by hand, so each case is exact.
#include "particles/particle_check.h"

#include <box2d/box2d.h>
#include <gtest/gtest.h>
#include <optional>
#include <string>
#include <vector>

namespace cfx::test
{
namespace
{

constexpr float kCheckDt = 1.0f / 30.0f;
constexpr float kCheckRadius = 0.01f;

// One particle's step, as the particle system leaves it for the check: start, where a push began (the start
// when nothing pushed it), end.
struct CheckedPath
{
    b2Vec2 start, via, end;
    bool placedAfter = false; ///< spawned after the bodies moved (their motion not swept against it)
    /// A moving body pushed it from `via`; unset, pushed when `via` is not the start.
    std::optional<bool> pushed = std::nullopt;
    float fraction = 1.0f; ///< where along start -> via the push began
};

// Runs the check over one particle per path against `world` and returns how many passed through.
std::uint64_t PassedThroughCount(const b2World& world, const std::vector<CheckedPath>& paths)
{
    const auto n = static_cast<std::uint32_t>(paths.size());
    std::vector<float> x(n), y(n), vx(n), vy(n), life(n, 1.0f), clearance(n), sx(n), sy(n), px(n), py(n),
        fraction(n);
    std::vector<std::uint16_t> type(n, 0);
    std::vector<std::uint8_t> flags(n, 0);
    for (std::uint32_t i = 0; i < n; ++i)
    {
        x[i] = paths[i].end.x;
        y[i] = paths[i].end.y;
        sx[i] = paths[i].start.x;
        sy[i] = paths[i].start.y;
        fraction[i] = paths[i].fraction;
        px[i] = paths[i].via.x;
        py[i] = paths[i].via.y;
        const bool pushed = paths[i].pushed.value_or(paths[i].via.x != paths[i].start.x ||
                                                     paths[i].via.y != paths[i].start.y);
        flags[i] = static_cast<std::uint8_t>((paths[i].placedAfter ? particles::kPlacedAfterFlag : 0) |
                                             (pushed ? particles::kPushedFlag : 0));
    }
    particles::PoolArrays pool{x.data(),         y.data(),     vx.data(), vy.data(), life.data(), type.data(),
                               clearance.data(), nullptr,      sx.data(), sy.data(), px.data(),   py.data(),
                               fraction.data(),  flags.data(), n,         0};
    particles::TypeStep step{};
    step.side = particles::ParticleSide{kCheckRadius, 0.0f, 0.0f, 0.0f, 0x0001, 0xFFFF};
    step.sweeps = true;
    particles::CheckCounts counts;
    particles::CheckParticles(world, pool, &step, n, nullptr, kCheckDt, counts);
    EXPECT_EQ(counts.inside, 0u);
    return counts.passedThrough;
}

// A kinematic body of one fixture at the origin, moved by one world step at these velocities (which also
// puts its fixture in the broad phase where it went).
b2Body* MovedKinematicBody(b2World& world, const b2Shape& shape, b2Vec2 velocity, float angularVelocity)
{
    b2BodyDef def;
    def.type = b2_kinematicBody;
    b2Body* body = world.CreateBody(&def);
    body->CreateFixture(&shape, 1.0f);
    body->SetLinearVelocity(velocity);
    body->SetAngularVelocity(angularVelocity);
    world.Step(kCheckDt, 8, 3);
    return body;
}

} // namespace

TEST(ParticleCheck, CountsAParticleThatWentThroughAMovingBodyAndNoOther)
{
    b2World world(b2Vec2(0.0f, 0.0f));
    // A plank 4 x 0.2 m rising at 12 m/s: 0.4 m in the step, from -0.1 .. 0.1 to 0.3 .. 0.5.
    b2PolygonShape plankShape;
    plankShape.SetAsBox(2.0f, 0.1f);
    b2Body* plank = MovedKinematicBody(world, plankShape, b2Vec2(0.0f, 12.0f), 0.0f);
    const b2Vec2 centre = plank->GetPosition();
    ASSERT_NEAR(centre.y, 0.4f, 1e-4f);
    const float top = centre.y + 0.1f, bottom = centre.y - 0.1f, rise = 0.4f;

    // Resting 1 cm over the plank's old top: the plank rose into it.
    const b2Vec2 resting(0.0f, top - rise + 0.011f);
    // Spawned between where the plank was and where it is, after it rose, and left there: the plank never
    // passed it; had it been there before, the plank went through it.
    const b2Vec2 spawned(0.0f, bottom - 0.1f);
    EXPECT_EQ(PassedThroughCount(world, {{spawned, spawned, spawned + b2Vec2(0.0f, -0.01f), true}}), 0u);
    EXPECT_EQ(PassedThroughCount(world, {{spawned, spawned, spawned + b2Vec2(0.0f, -0.01f), false}}), 1u);
    // Put through: left under the plank's new bottom (a push the wrong way), whether the check is told it
    // was pushed from where it rested or not.
    EXPECT_EQ(PassedThroughCount(world, {{resting, resting, b2Vec2(0.0f, bottom - 0.011f)}}), 1u);
    EXPECT_EQ(PassedThroughCount(world, {{resting, resting, b2Vec2(0.0f, bottom - 0.011f), false, true}}),
              1u);
    // Carried: on its new top.
    EXPECT_EQ(PassedThroughCount(world, {{resting, resting, b2Vec2(0.0f, top + 0.011f)}}), 0u);
    // Pushed by another body through it: flew to under the plank, then a push took it over it.
    EXPECT_EQ(PassedThroughCount(world, {{b2Vec2(1.0f, bottom - 0.5f), b2Vec2(1.0f, bottom - 0.05f),
                                          b2Vec2(1.0f, top + 0.02f)}}),
              1u);
    // Under it all along, flying up through where it was and now is: through it.
    EXPECT_EQ(PassedThroughCount(world, {{b2Vec2(1.0f, bottom - 0.5f), b2Vec2(1.0f, bottom - 0.5f),
                                          b2Vec2(1.0f, top + 0.02f)}}),
              1u);
    // Flew past its end, beside it all along.
    EXPECT_EQ(PassedThroughCount(world, {{b2Vec2(2.1f, -0.5f), b2Vec2(2.1f, -0.5f), b2Vec2(2.1f, 0.5f)}}),
              0u);
    // Slid around its corner: came onto its top near the end, pushed out past its end face.
    EXPECT_EQ(
        PassedThroughCount(world, {{b2Vec2(1.98f, top - rise + 0.011f), b2Vec2(1.98f, top - rise + 0.011f),
                                    b2Vec2(2.0f + 0.011f, top - 0.02f)}}),
        0u);
    // Went through and came out of the far side, deeper than its radius: counted once per particle.
    EXPECT_EQ(PassedThroughCount(world, {{resting, resting, b2Vec2(0.0f, bottom - 0.011f)},
                                         {b2Vec2(-1.0f, 1.0f), b2Vec2(-1.0f, 1.0f), b2Vec2(-1.0f, 1.2f)},
                                         {resting, resting, b2Vec2(0.5f, bottom - 0.02f)}}),
              2u);
}

TEST(ParticleCheck, CountsAParticleThatWentThroughASpinningWheel)
{
    b2World world(b2Vec2(0.0f, 0.0f));
    b2CircleShape rim;
    rim.m_radius = 0.4f;
    b2Body* wheel = MovedKinematicBody(world, rim, b2Vec2(0.0f, 0.0f), 60.0f); // 2 rad in the step
    // Riding the rim: flew off along its tangent (24.7 m/s), and the wheel put it back on the same point of
    // the rim, turned with it.
    const b2Vec2 onRim(0.411f, 0.0f);
    const b2Rot turned(wheel->GetAngle());
    const b2Vec2 flown = onRim + kCheckDt * b2Vec2(0.0f, 60.0f * 0.411f);
    EXPECT_EQ(PassedThroughCount(world, {{onRim, flown, b2Mul(turned, onRim)}}), 0u);
    // Flew from one side to the other, through the middle, while the wheel turned 2 rad.
    EXPECT_EQ(PassedThroughCount(world, {{onRim, onRim, -onRim}}), 1u);
    // Flew past it: its path 0.02 m from the rim.
    EXPECT_EQ(PassedThroughCount(world, {{b2Vec2(-1.0f, 0.43f), b2Vec2(-1.0f, 0.43f), b2Vec2(1.0f, 0.43f)}}),
              0u);
}

// A particle at rest has no flight: its path starts where the push began. A wheel rolling into it put it on
// its rim; the chord from its start to its end cuts through the wheel, but the wheel came onto it and
// carried it (the check once took such a push for a flight: 11 to 21 counted in 3 s of a trial's wheels).
TEST(ParticleCheck, APushOfAParticleAtRestIsNoPassThrough)
{
    b2World world(b2Vec2(0.0f, 0.0f));
    b2CircleShape rim;
    rim.m_radius = 0.4f;
    // From the origin to (0.4, 0), turning 2 rad.
    b2Body* wheel = MovedKinematicBody(world, rim, b2Vec2(12.0f, 0.0f), 60.0f);
    ASSERT_NEAR(wheel->GetPosition().x, 0.4f, 1e-4f);
    const b2Vec2 resting(0.45f, 0.0f); // 4 cm in front of the rim, which rolled over it
    const b2Vec2 onTop = wheel->GetPosition() + b2Vec2(0.0f, 0.411f);
    EXPECT_EQ(PassedThroughCount(world, {{resting, resting, onTop, false, true}}), 0u);
    // As a flight (not pushed), the same path goes through the wheel.
    EXPECT_EQ(PassedThroughCount(world, {{resting, resting, onTop, false, false}}), 1u);
}

// A push that began where the flight met the body (a fraction of the way): the flight beyond that never
// happened, so it cannot show where the particle came onto the body. A spark in the gap under a box
// sliding over it, touching its bottom from the start and held there, would have flown up into the box's
// trailing face; seen from there it left by the leading face, through the box (a trial's false count).
TEST(ParticleCheck, APushFromWhereTheFlightMetTheBodyIsJudgedFromThere)
{
    b2World world(b2Vec2(0.0f, 0.0f));
    b2PolygonShape boxShape;
    boxShape.SetAsBox(0.2f, 0.2f);
    MovedKinematicBody(world, boxShape, b2Vec2(12.0f, 0.0f), 0.0f); // 0.4 m to the right
    // Under its bottom near its right end; the flight would have ended past that corner; held, it is now
    // beyond the box's left end.
    const b2Vec2 start(0.195f, -0.207f);
    const b2Vec2 flight = start + b2Vec2(0.437f, 0.031f);
    const b2Vec2 end = start + b2Vec2(-0.02f, 0.0f);
    EXPECT_EQ(PassedThroughCount(world, {{start, flight, end, false, true, 0.0f}}), 0u);
    // Taken as pushed from the flight's end, it came onto the face the box leads with.
    EXPECT_EQ(PassedThroughCount(world, {{start, flight, end, false, true, 1.0f}}), 1u);
}

} // namespace cfx::test
