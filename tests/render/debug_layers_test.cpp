// Debug layers: a steel block sliding on concrete, its contact drawn as points by intensity, normal,
// impulse and rule name; pixels of those colours where the contact is.
#include "contactfx/draw/debug_layers.h"
#include "contactfx/draw/frame_builder.h"
#include "contactfx/effects.h"
#include "contactfx/render/cairo_renderer.h"
#include "contactfx/render/frame.h"
#include "test_world.h"

#include <box2d/b2_contact.h>
#include <gtest/gtest.h>
#include <vector>

namespace cfx::test
{

namespace
{

bool SameColor(const Color& a, const Color& b)
{
    return a == b;
}

struct SlidingBlock : ::testing::Test
{
    SlidingBlock()
    {
        ground = world.CreateGround();
        block = world.CreateBox(b2Vec2(0.0f, 0.5f), 1.0f, 0.5f, 0.6f);
        world.Attach();
        world.effects->SetMaterial(ground, world.Material("concrete"));
        world.effects->SetMaterial(block, world.Material("steel"));
        block->SetLinearVelocity(b2Vec2(15.0f, 0.0f));
        for (int i = 0; i < 4; ++i)
        {
            world.Step();
        }
        contact = world.world->GetContactList();
        while (contact != nullptr && !contact->IsTouching())
        {
            contact = contact->GetNext();
        }
    }

    TestWorld world;
    b2Body* ground = nullptr;
    b2Body* block = nullptr;
    b2Contact* contact = nullptr;
    Camera camera = MakeCamera(400, 200, 8.0f, b2Vec2(0.0f, 0.5f)); // 50 px per metre
};

} // namespace

TEST(DebugColors, IntensityIsBlueAtNothingGreenAtTheThresholdRedFromTwiceIt)
{
    EXPECT_EQ(IntensityColor(0.0f, 2.0f), (Color{0.0f, 0.0f, 1.0f, 1.0f}));
    EXPECT_EQ(IntensityColor(2.0f, 2.0f), (Color{0.0f, 1.0f, 0.0f, 1.0f}));
    EXPECT_EQ(IntensityColor(4.0f, 2.0f), (Color{1.0f, 0.0f, 0.0f, 1.0f}));
    EXPECT_EQ(IntensityColor(40.0f, 2.0f), IntensityColor(4.0f, 2.0f));
    EXPECT_EQ(IntensityColor(1.0f, 0.0f), IntensityColor(4.0f, 2.0f)) << "any intensity over a 0 threshold";
}

TEST_F(SlidingBlock, EveryLayerDrawsWhereTheContactIs)
{
    ASSERT_NE(contact, nullptr);
    const b2Manifold& manifold = *contact->GetManifold();
    ASSERT_EQ(manifold.pointCount, 2);
    b2WorldManifold points;
    contact->GetWorldManifold(&points);

    DrawList list;
    list.Begin(camera, Color{});
    std::vector<ParticleSprite> sprites;
    CollectSprites(*world.effects, sprites);
    ASSERT_FALSE(sprites.empty()) << "steel on concrete at 15 m/s makes sparks";
    DebugLayers layers = DebugLayers::All();
    AddDebugLayers(list, *world.effects, sprites, layers, DrawStyle{});

    int normals = 0, impulses = 0, squares = 0, rings = 0, velocities = 0;
    for (const ShapeCommand& shape : list.shapes)
    {
        const b2Vec2 start = list.vertices[shape.first];
        if (shape.kind == ShapeKind::segment && SameColor(shape.stroke, kDebugVelocityColor))
        {
            ++velocities;
            continue;
        }
        int point = -1;
        for (int i = 0; i < manifold.pointCount; ++i)
        {
            point = b2Distance(start, points.points[i]) < 1e-6f ? i : point;
        }
        ASSERT_GE(point, 0) << "every contact shape starts at a manifold point";
        const b2Vec2 end = list.vertices[shape.first + shape.count - 1];
        if (shape.kind == ShapeKind::segment && SameColor(shape.stroke, kDebugNormalColor))
        {
            ++normals;
            EXPECT_EQ(shape.strokeWidth, kDebugLineWidth);
            EXPECT_NEAR(b2Dot(end - start, points.normal), layers.normalLength, 1e-5f);
        }
        else if (shape.kind == ShapeKind::segment && SameColor(shape.stroke, kDebugImpulseColor))
        {
            ++impulses;
            EXPECT_NEAR(b2Distance(end, start), layers.impulseScale * manifold.points[point].normalImpulse,
                        1e-5f);
            EXPECT_LT(b2Dot(end - start, points.normal), 0.0f);
        }
        else if (shape.kind == ShapeKind::point)
        {
            ++squares;
            EXPECT_EQ(shape.pointSize, kDebugPointSize);
            EXPECT_EQ(shape.fill.a, 1.0f);
        }
        else if (shape.kind == ShapeKind::circle && SameColor(shape.stroke, kDebugThresholdColor))
        {
            ++rings;
        }
    }
    EXPECT_EQ(normals, 2);
    EXPECT_EQ(impulses, 2) << "the block presses on both points";
    EXPECT_EQ(squares, 2);
    EXPECT_EQ(rings, 2) << "at 15 m/s both points rub above the threshold";
    EXPECT_EQ(velocities, static_cast<int>(sprites.size()));
    ASSERT_EQ(list.labels.size(), 1u) << "one contact, one label";
    const RuleId rule = world.effects->Rules().Find(world.Material("steel"), world.Material("concrete"));
    EXPECT_EQ(list.labels[0].text, RuleLabel(*world.effects, rule));
    EXPECT_NE(list.labels[0].text.find("sparks"), std::string::npos);
}

// A trial launched sixty balls into a scene: their rule names were stacked over each other and moved up to
// six lines (96 px) below their contacts. Labels never overlap now, and stay within two lines of where
// they belong; what finds no room there is left out.
TEST(DebugLabels, ManyContactsGiveLabelsThatNeverOverlap)
{
    TestWorld world;
    b2Body* ground = world.CreateGround();
    // 0.61 m apart at 80 px a metre: 49 px, just beyond the spacing that leaves out a label of the same text,
    // so each label's place is taken by up to three before it.
    std::vector<b2Body*> balls;
    for (int i = 0; i < 12; ++i)
    {
        balls.push_back(world.CreateCircle(b2Vec2(-4.0f + 0.61f * static_cast<float>(i), 0.1f), 0.1f, 0.6f));
    }
    world.Attach();
    world.effects->SetMaterial(ground, world.Material("concrete"));
    for (b2Body* ball : balls)
    {
        world.effects->SetMaterial(ball, world.Material("steel"));
        ball->SetLinearVelocity(b2Vec2(10.0f, 0.0f));
    }
    world.Step();
    DebugLayers layers;
    layers.ruleNames = true;
    DrawList list;
    list.Begin(MakeCamera(800, 400, 10.0f, b2Vec2(0.0f, 0.0f)), Color{});
    AddDebugLayers(list, *world.effects, {}, layers, DrawStyle{});
    ASSERT_GT(list.labels.size(), 1u);
    EXPECT_LT(list.labels.size(), balls.size()) << "crowded: some are left out";
    float top = list.labels[0].at.y;
    float bottom = top;
    for (const TextLabel& label : list.labels)
    {
        top = std::min(top, label.at.y);
        bottom = std::max(bottom, label.at.y);
    }
    EXPECT_LE(bottom - top, 2.0f * 16.0f) << "every contact is on the ground: at most two lines down";
    for (std::size_t i = 0; i < list.labels.size(); ++i)
    {
        for (std::size_t j = i + 1; j < list.labels.size(); ++j)
        {
            const b2Vec2 a = list.labels[i].at;
            const b2Vec2 b = list.labels[j].at;
            EXPECT_TRUE(std::abs(a.y - b.y) >= 16.0f || std::abs(a.x - b.x) >= 160.0f)
                << "labels " << i << " and " << j;
        }
    }
}

TEST_F(SlidingBlock, NothingIsAddedWithNoLayerOn)
{
    DrawList list;
    list.Begin(camera, Color{});
    AddDebugLayers(list, *world.effects, {}, DebugLayers{}, DrawStyle{});
    EXPECT_TRUE(list.shapes.empty());
    EXPECT_TRUE(list.labels.empty());
}

TEST_F(SlidingBlock, TheRenderedFrameShowsNormalAndImpulseColoursBesideTheContact)
{
    ASSERT_NE(contact, nullptr);
    b2WorldManifold points;
    contact->GetWorldManifold(&points);
    FrameOptions options;
    options.overlay = false;
    options.debug.normals = true;
    options.debug.impulses = true;
    FrameScratch scratch;
    render::CairoRenderer renderer(camera.width, camera.height);
    render::RenderFrame(*world.effects, 0.0f, camera, options, renderer, scratch);
    // Count pixels of each colour within a few pixels of the normal's and the impulse's middles.
    auto near = [&](const Color& color, b2Vec2 where)
    {
        const b2Vec2 at = camera.ToPixels(where);
        int found = 0;
        for (int dy = -3; dy <= 3; ++dy)
        {
            for (int dx = -3; dx <= 3; ++dx)
            {
                const render::Pixel p =
                    renderer.PixelAt(static_cast<int>(at.x) + dx, static_cast<int>(at.y) + dy);
                found += std::abs(p.r - color.r * 255.0f) < 40.0f &&
                                 std::abs(p.g - color.g * 255.0f) < 40.0f &&
                                 std::abs(p.b - color.b * 255.0f) < 40.0f
                             ? 1
                             : 0;
            }
        }
        return found;
    };
    const b2Vec2 point = points.points[0];
    const float impulse = contact->GetManifold()->points[0].normalImpulse;
    EXPECT_GT(near(kDebugNormalColor, point + 0.5f * options.debug.normalLength * points.normal), 0);
    EXPECT_GT(near(kDebugImpulseColor, point - 0.5f * options.debug.impulseScale * impulse * points.normal),
              0);
    FrameOptions plain = options;
    plain.debug = DebugLayers{};
    render::RenderFrame(*world.effects, 0.0f, camera, plain, renderer, scratch);
    EXPECT_EQ(near(kDebugNormalColor, point + 0.5f * options.debug.normalLength * points.normal), 0);
}

} // namespace cfx::test
