// Debug layers: the world's touching contacts that have a rule, read after Effects::Step, as shapes and
// labels of a draw list. Contacts are visited in Box2D's contact-list order, which is deterministic.
#include "contactfx/draw/debug_layers.h"

#include "contactfx/effects.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <cmath>

namespace cfx
{

namespace
{

b2Color ToB2(const Color& color)
{
    return b2Color(color.r, color.g, color.b, color.a);
}

// A debug line, kDebugLineWidth px wide.
void Line(DrawList& list, ShapeRecorder& draw, b2Vec2 from, b2Vec2 to, const Color& color)
{
    draw.DrawSegment(from, to, ToB2(color));
    list.shapes.back().strokeWidth = kDebugLineWidth;
}

// A label is left out when one with the same text is closer than kLabelSpacing (a chain's segments
// under one body), and moved down a line while it would overlap another, at most kMostLabelMoves lines:
// one that still overlaps is left out too (a trial's pile of balls stacked labels over each other and a
// hundred pixels below their contacts).
constexpr float kLabelSpacing = 48.0f; // px
constexpr float kLabelLine = 16.0f;    // px
constexpr float kLabelWidth = 160.0f;  // px, what a label is assumed to cover to its right
constexpr int kMostLabelMoves = 2;

void AddLabel(DrawList& list, b2Vec2 at, std::string text)
{
    for (const TextLabel& label : list.labels)
    {
        if (label.text == text && b2Distance(label.at, at) < kLabelSpacing)
        {
            return;
        }
    }
    const auto overlaps = [&]
    {
        return std::any_of(list.labels.begin(), list.labels.end(),
                           [&](const TextLabel& label) {
                               return std::abs(label.at.y - at.y) < kLabelLine &&
                                      std::abs(label.at.x - at.x) < kLabelWidth;
                           });
    };
    for (int move = 0; move < kMostLabelMoves && overlaps(); ++move)
    {
        at.y += kLabelLine;
    }
    if (!overlaps())
    {
        list.labels.push_back(TextLabel{at, std::move(text), Color{1.0f, 1.0f, 1.0f, 1.0f}});
    }
}

void AddContact(DrawList& list, ShapeRecorder& draw, const Effects& effects, b2Contact& contact, RuleId rule,
                const DebugLayers& layers)
{
    const b2Manifold& manifold = *contact.GetManifold();
    b2WorldManifold world;
    contact.GetWorldManifold(&world);
    const RuleDef& def = effects.Config().rules[rule.index];
    const int points = def.intensity.points == ManifoldPoints::first ? std::min(manifold.pointCount, 1)
                                                                     : manifold.pointCount;
    const b2Fixture& fixtureA = *contact.GetFixtureA();
    const b2Fixture& fixtureB = *contact.GetFixtureB();
    float totalImpulse = 0.0f;
    for (int i = 0; i < manifold.pointCount; ++i)
    {
        totalImpulse += manifold.points[i].normalImpulse;
    }
    const float pixel = 1.0f / list.camera.pixelsPerMetre; // m
    for (int i = 0; i < points; ++i)
    {
        const b2Vec2 point = world.points[i];
        if (layers.normals)
        {
            Line(list, draw, point, point + layers.normalLength * world.normal, kDebugNormalColor);
        }
        if (layers.impulses && manifold.points[i].normalImpulse > 0.0f)
        {
            const float length = layers.impulseScale * manifold.points[i].normalImpulse;
            Line(list, draw, point, point - length * world.normal, kDebugImpulseColor);
        }
        if (layers.manifoldPoints)
        {
            ContactSample sample;
            sample.point = point;
            sample.normal = world.normal;
            sample.velocityA = fixtureA.GetBody()->GetLinearVelocityFromWorldPoint(point);
            sample.velocityB = fixtureB.GetBody()->GetLinearVelocityFromWorldPoint(point);
            sample.frictionA = fixtureA.GetFriction();
            sample.frictionB = fixtureB.GetFriction();
            sample.normalForce = layers.stepTime > 0.0f ? totalImpulse / layers.stepTime : 0.0f;
            const float intensity = ComputeIntensity(sample, def.intensity);
            draw.DrawPoint(point, kDebugPointSize, ToB2(IntensityColor(intensity, def.threshold)));
            if (intensity > def.threshold)
            {
                draw.DrawCircle(point, kDebugPointSize * pixel, ToB2(kDebugThresholdColor));
            }
        }
    }
    if (layers.ruleNames && points > 0)
    {
        const b2Vec2 at = list.camera.ToPixels(world.points[0]);
        AddLabel(list, at + b2Vec2(8.0f, -8.0f), RuleLabel(effects, rule));
    }
}

} // namespace

DebugLayers DebugLayers::All()
{
    DebugLayers layers;
    layers.manifoldPoints = layers.normals = layers.impulses = layers.ruleNames = layers.velocities = true;
    return layers;
}

Color IntensityColor(float intensity, float threshold)
{
    const float t = threshold > 0.0f ? intensity / threshold : (intensity > 0.0f ? 2.0f : 0.0f);
    const float x = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, 2.0f);
    if (x <= 1.0f)
    {
        return Color{0.0f, x, 1.0f - x, 1.0f}; // blue -> green
    }
    return Color{x - 1.0f, 2.0f - x, 0.0f, 1.0f}; // green -> red
}

std::string RuleLabel(const Effects& effects, RuleId rule)
{
    const RuleDef& def = effects.Config().rules[rule.index];
    return def.materialA + "/" + def.materialB + ": " + def.particleType;
}

void AddDebugLayers(DrawList& list, const Effects& effects, std::span<const ParticleSprite> sprites,
                    const DebugLayers& layers, const DrawStyle& style)
{
    if (!layers.Any())
    {
        return;
    }
    ShapeRecorder draw(list, style);
    if (layers.manifoldPoints || layers.normals || layers.impulses || layers.ruleNames)
    {
        for (b2Contact* contact = effects.World().GetContactList(); contact != nullptr;
             contact = contact->GetNext())
        {
            if (!contact->IsTouching() || contact->GetFixtureA()->IsSensor() ||
                contact->GetFixtureB()->IsSensor())
            {
                continue;
            }
            const RuleId rule = effects.Rules().Find(effects.Material(contact->GetFixtureA()),
                                                     effects.Material(contact->GetFixtureB()));
            if (rule.IsValid())
            {
                AddContact(list, draw, effects, *contact, rule, layers);
            }
        }
    }
    if (layers.velocities)
    {
        for (const ParticleSprite& sprite : sprites)
        {
            Line(list, draw, sprite.position, sprite.position + layers.velocityTime * sprite.velocity,
                 kDebugVelocityColor);
        }
    }
}

} // namespace cfx
