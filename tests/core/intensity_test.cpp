#include "contactfx/intensity.h"

#include <cmath>
#include <gtest/gtest.h>

namespace cfx
{

namespace
{

ContactSample Sliding(b2Vec2 relative)
{
    ContactSample sample;
    sample.normal = b2Vec2(0.0f, 1.0f);
    sample.velocityA = relative;
    sample.velocityB = b2Vec2(0.0f, 0.0f);
    sample.frictionA = 0.5f;
    sample.frictionB = 0.8f;
    return sample;
}

} // namespace

TEST(Intensity, TutorialModelIsFullSpeedTimesFrictionProduct)
{
    IntensityModel tutorial{SpeedMode::full, FrictionMix::product, ManifoldPoints::first, 0.0f};
    ContactSample sample = Sliding(b2Vec2(3.0f, -4.0f));
    EXPECT_FLOAT_EQ(ComputeIntensity(sample, tutorial), 5.0f * 0.5f * 0.8f);
}

TEST(Intensity, TangentialModeIgnoresApproachAlongTheNormal)
{
    IntensityModel model{SpeedMode::tangential, FrictionMix::product, ManifoldPoints::all, 0.0f};
    ContactSample approaching = Sliding(b2Vec2(0.0f, -7.0f));
    EXPECT_FLOAT_EQ(ComputeIntensity(approaching, model), 0.0f);
    ContactSample both = Sliding(b2Vec2(2.0f, -7.0f));
    EXPECT_FLOAT_EQ(ComputeIntensity(both, model), 2.0f * 0.4f);
    model.speed = SpeedMode::full;
    EXPECT_GT(ComputeIntensity(approaching, model), 2.0f);
}

TEST(Intensity, TangentialModeWorksForAnyNormal)
{
    ContactSample sample = Sliding(b2Vec2(1.0f, 1.0f));
    sample.normal = b2Vec2(std::sqrt(0.5f), std::sqrt(0.5f));
    EXPECT_NEAR(RelativeSpeed(SpeedMode::tangential, sample), 0.0f, 1e-6f);
    sample.velocityA = b2Vec2(1.0f, -1.0f);
    EXPECT_NEAR(RelativeSpeed(SpeedMode::tangential, sample), std::sqrt(2.0f), 1e-6f);
}

TEST(Intensity, FrictionMixes)
{
    EXPECT_FLOAT_EQ(MixFriction(FrictionMix::product, 0.5f, 0.8f), 0.4f);
    EXPECT_FLOAT_EQ(MixFriction(FrictionMix::sqrt, 0.5f, 0.8f), std::sqrt(0.4f));
    EXPECT_FLOAT_EQ(MixFriction(FrictionMix::min, 0.5f, 0.8f), 0.5f);
    EXPECT_FLOAT_EQ(MixFriction(FrictionMix::max, 0.5f, 0.8f), 0.8f);
    EXPECT_FLOAT_EQ(MixFriction(FrictionMix::mean, 0.5f, 0.8f), 0.65f);
}

TEST(Intensity, ImpulseWeightScalesWithNormalForce)
{
    IntensityModel model{SpeedMode::tangential, FrictionMix::min, ManifoldPoints::all, 0.1f};
    ContactSample sample = Sliding(b2Vec2(2.0f, 0.0f));
    sample.normalForce = 0.0f;
    EXPECT_FLOAT_EQ(ComputeIntensity(sample, model), 1.0f);
    sample.normalForce = 30.0f;
    EXPECT_FLOAT_EQ(ComputeIntensity(sample, model), 4.0f);
}

} // namespace cfx
