// A scene the render tests share: a rubber crate sliding fast over dirt, which throws dirt particles.
#pragma once

#include "test_world.h"

#include <gtest/gtest.h>

namespace cfx::test
{

/// Gives `ground` dirt and `crate` rubber, slides the crate along the ground at 12 m/s and steps until
/// the first particles live (at most 20 steps).
inline void SlideRubberOverDirt(TestWorld& world, b2Body* ground, b2Body* crate)
{
    world.effects->SetMaterial(ground, world.effects->FindMaterial("dirt"));
    world.effects->SetMaterial(crate, world.effects->FindMaterial("rubber"));
    crate->SetTransform(b2Vec2(0.0f, 0.5f), 0.0f);
    crate->SetLinearVelocity(b2Vec2(12.0f, 0.0f));
    for (int i = 0; i < 20 && world.effects->Particles().count == 0; ++i)
    {
        world.Step();
    }
}

} // namespace cfx::test
