// contactfx benchmarks: the debris scene and its timing (see debris_bench.h).
#include "scenes/debris_bench.h"

#include "contactfx/presets.h"
#include "harness/state_hash.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_contact.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_polygon_shape.h>
#include <chrono>
#include <cmath>
#include <numeric>

namespace cfx::bench
{

namespace
{

constexpr float kBoxHalf = 0.2f;      // 0.4 m boxes
constexpr float kBoxDensity = 100.0f; // 16 kg a box
constexpr float kSteelFriction = 0.3f;
constexpr float kConcreteFriction = 0.5f;
constexpr float kColumnWidth = 0.5f; // the starting grid
constexpr float kRowHeight = 0.45f;
constexpr std::uint32_t kMinColumns = 24;
constexpr float kSlope = 0.6108652f; // 35 degrees
constexpr float kRampLength = 10.0f;
constexpr float kRampThickness = 0.4f;
constexpr float kRampGap = 2.0f;        // the upper ramp's end above the lower ramp's surface
constexpr std::uint32_t kDropEvery = 3; // steps
constexpr float kDropSpeed = 6.0f;      // m/s down the ramp, +- 1
constexpr float kSettledSpeed = 0.5f;   // m/s
constexpr float kFellOutBelow = -5.0f;  // m

// A static concrete plank whose upper surface runs from `top` along `down` for `length`.
void AddRamp(b2Body* ground, b2Vec2 top, b2Vec2 down, float length)
{
    const b2Vec2 normal(-down.y, down.x); // points up for either direction of `down`
    const b2Vec2 up = normal.y > 0.0f ? normal : -normal;
    const b2Vec2 centre = top + (0.5f * length) * down - (0.5f * kRampThickness) * up;
    b2PolygonShape shape;
    shape.SetAsBox(0.5f * length, 0.5f * kRampThickness, centre, std::atan2(down.y, down.x));
    b2FixtureDef def;
    def.shape = &shape;
    def.friction = kConcreteFriction;
    ground->CreateFixture(&def);
}

void AddBox(b2Body* ground, float x0, float y0, float x1, float y1)
{
    b2PolygonShape shape;
    shape.SetAsBox(0.5f * (x1 - x0), 0.5f * (y1 - y0), b2Vec2(0.5f * (x0 + x1), 0.5f * (y0 + y1)), 0.0f);
    b2FixtureDef def;
    def.shape = &shape;
    def.friction = kConcreteFriction;
    ground->CreateFixture(&def);
}

// Whether a dynamic body's centre is within `reach` of a point (its box may then overlap a box there).
class AnyDynamicNear final : public b2QueryCallback
{
public:
    AnyDynamicNear(b2Vec2 point, float reach) : m_point(point), m_reach(reach) {}
    bool ReportFixture(b2Fixture* fixture) override
    {
        const b2Body* body = fixture->GetBody();
        found = found || (body->GetType() == b2_dynamicBody &&
                          b2DistanceSquared(body->GetPosition(), m_point) < m_reach * m_reach);
        return !found;
    }
    bool found = false;

private:
    b2Vec2 m_point;
    float m_reach;
};

} // namespace

DebrisBenchScene::DebrisBenchScene(std::uint32_t boxes, std::uint64_t seed, std::uint32_t capacity,
                                   const ParticleSystemOptions& particles)
    : m_world(std::make_unique<b2World>(b2Vec2(0.0f, -10.0f))), m_random(seed)
{
    EffectsDef def;
    def.config = DefaultPreset();
    if (capacity > 0)
    {
        def.config.budget.capacity = capacity;
    }
    def.seed = seed;
    def.particles = particles;
    m_effects = std::make_unique<Effects>(*m_world, def);
    const std::uint32_t count = std::max<std::uint32_t>(boxes, 1);
    const auto columns = std::max(
        kMinColumns, static_cast<std::uint32_t>(std::ceil(2.0 * std::sqrt(static_cast<double>(count)))));
    const std::uint32_t rows = (count + columns - 1) / columns;
    m_binHalfWidth = 0.5f * kColumnWidth * static_cast<float>(columns) + 0.05f;
    m_wallTop = kRowHeight * static_cast<float>(rows) + 1.5f;
    BuildStatic();
    m_boxes.reserve(count);
    b2PolygonShape shape;
    shape.SetAsBox(kBoxHalf, kBoxHalf);
    b2FixtureDef fixture;
    fixture.shape = &shape;
    fixture.density = kBoxDensity;
    fixture.friction = kSteelFriction;
    const MaterialId steel = m_effects->FindMaterial("steel");
    for (std::uint32_t i = 0; i < count; ++i)
    {
        const std::uint32_t column = i % columns, row = i / columns;
        b2BodyDef body;
        body.type = b2_dynamicBody;
        body.position.Set(-m_binHalfWidth + 0.05f + kColumnWidth * (static_cast<float>(column) + 0.5f) +
                              m_random.Uniform(-0.03f, 0.03f),
                          kRowHeight * (static_cast<float>(row) + 0.5f) + 0.02f);
        body.angle = m_random.Uniform(-0.05f, 0.05f);
        body.userData.pointer = i;
        b2Body* box = m_world->CreateBody(&body);
        box->CreateFixture(&fixture);
        m_effects->SetMaterial(box, steel);
        m_boxes.push_back(box);
    }
}

DebrisBenchScene::~DebrisBenchScene()
{
    m_effects.reset(); // before the world
}

void DebrisBenchScene::BuildStatic()
{
    b2BodyDef def;
    b2Body* ground = m_world->CreateBody(&def);
    const float w = m_binHalfWidth;
    // The bin: floor and walls, 0.5 m thick, the inside from -w to w above y = 0.
    AddBox(ground, -w - 0.5f, -0.5f, w + 0.5f, 0.0f);
    AddBox(ground, -w - 0.5f, 0.0f, -w, m_wallTop);
    AddBox(ground, w, 0.0f, w + 0.5f, m_wallTop);
    for (const float side : {-1.0f, 1.0f}) // left, right: both fall toward the bin
    {
        const b2Vec2 down(-side * std::cos(kSlope), -std::sin(kSlope));
        // The lower ramp ends 1 m above the wall, 0.3 m inside the bin.
        const b2Vec2 lowerEnd(side * (w - 0.3f), m_wallTop + 1.0f);
        const b2Vec2 lowerTop = lowerEnd - kRampLength * down;
        AddRamp(ground, lowerTop, down, kRampLength);
        // The upper ramp ends kRampGap above the lower one's surface, 1.5 m past its top.
        const float along = 1.5f / std::cos(kSlope);
        const b2Vec2 upperEnd = lowerTop + along * down + b2Vec2(0.0f, kRampGap);
        const b2Vec2 upperTop = upperEnd - kRampLength * down;
        AddRamp(ground, upperTop, down, kRampLength);
        m_upperRamps.push_back(Ramp{upperTop, down});
    }
    const MaterialId concrete = m_effects->FindMaterial("concrete");
    m_effects->SetMaterial(ground, concrete);
}

void DebrisBenchScene::StepWorld()
{
    m_world->Step(1.0f / kDebrisHz, 8, 3);
}

void DebrisBenchScene::StepEffects()
{
    const EffectsStats& stats = m_effects->Stats();
    const std::uint32_t liveBefore = stats.live;
    const std::uint64_t spawnedBefore =
        std::accumulate(stats.spawnedByType.begin(), stats.spawnedByType.end(), std::uint64_t{0});
    const std::uint64_t recycledBefore = stats.recycled;
    m_effects->Step(1.0f / kDebrisHz);
    // Every spawn adds a particle (the preset's lives are >= 0.5), recycling one when the pool is full.
    const std::uint64_t spawned =
        std::accumulate(stats.spawnedByType.begin(), stats.spawnedByType.end(), std::uint64_t{0}) -
        spawnedBefore;
    m_liveDuringStep = static_cast<std::uint32_t>(std::min<std::uint64_t>(
        liveBefore + spawned - (stats.recycled - recycledBefore), m_effects->Config().budget.capacity));
}

void DebrisBenchScene::Step()
{
    StepWorld();
    StepEffects();
    Drop();
}

DebrisBenchScene::StepSeconds DebrisBenchScene::TimedStep()
{
    using StepClock = std::chrono::steady_clock;
    const StepClock::time_point start = StepClock::now();
    StepWorld();
    const StepClock::time_point worldDone = StepClock::now();
    StepEffects();
    const StepClock::time_point end = StepClock::now();
    Drop();
    return StepSeconds{std::chrono::duration<double>(worldDone - start).count(),
                       std::chrono::duration<double>(end - worldDone).count()};
}

b2Body* DebrisBenchScene::PickBoxToDrop() const
{
    b2Body* best = nullptr;
    for (b2Body* box : m_boxes)
    {
        const b2Vec2 p = box->GetPosition();
        if (p.y < kFellOutBelow)
        {
            return box;
        }
        const bool inBin = std::abs(p.x) < m_binHalfWidth && p.y > 0.0f && p.y < m_wallTop;
        if (inBin && box->GetLinearVelocity().Length() < kSettledSpeed &&
            (best == nullptr || p.y > best->GetPosition().y))
        {
            best = box;
        }
    }
    return best;
}

bool DebrisBenchScene::SpotIsFree(b2Vec2 centre) const
{
    const float reach = 2.0f * kBoxHalf + 0.05f; // boxes lying on the ramp touch at 2 half sides
    AnyDynamicNear query(centre, reach);
    b2AABB box;
    box.lowerBound = centre - b2Vec2(reach, reach);
    box.upperBound = centre + b2Vec2(reach, reach);
    m_world->QueryAABB(&query, box);
    return !query.found;
}

void DebrisBenchScene::Drop()
{
    const bool due = m_steps % kDropEvery == 0;
    ++m_steps;
    if (!due)
    {
        return;
    }
    const Ramp& ramp = m_upperRamps[m_dropTurn % m_upperRamps.size()];
    const b2Vec2 normal =
        ramp.down.x > 0.0f ? b2Vec2(-ramp.down.y, ramp.down.x) : b2Vec2(ramp.down.y, -ramp.down.x);
    const float along = 0.6f + m_random.Uniform(0.0f, 0.4f);
    const float speed = kDropSpeed + m_random.Uniform(-1.0f, 1.0f);
    const float spin = m_random.Uniform(-0.5f, 0.5f);
    const b2Vec2 centre = ramp.top + along * ramp.down + (kBoxHalf + 0.01f) * normal;
    if (!SpotIsFree(centre))
    {
        return; // the side keeps its turn
    }
    b2Body* box = PickBoxToDrop();
    if (box == nullptr)
    {
        return;
    }
    ++m_dropTurn;
    ++m_dropped;
    box->SetTransform(centre, std::atan2(ramp.down.y, ramp.down.x)); // a side on the ramp
    box->SetLinearVelocity(speed * ramp.down);
    box->SetAngularVelocity(spin);
    box->SetAwake(true);
}

std::uint32_t DebrisBenchScene::BoxesInBin() const
{
    std::uint32_t inside = 0;
    for (const b2Body* box : m_boxes)
    {
        const b2Vec2 p = box->GetPosition();
        inside += std::abs(p.x) < m_binHalfWidth && p.y > 0.0f && p.y < m_wallTop ? 1u : 0u;
    }
    return inside;
}

std::uint32_t DebrisBenchScene::BoxesTouchingBoxes() const
{
    std::vector<char> touching(m_boxes.size(), 0);
    for (b2Contact* contact = m_world->GetContactList(); contact != nullptr; contact = contact->GetNext())
    {
        b2Body* a = contact->GetFixtureA()->GetBody(); // GetUserData has no const form in Box2D 2.4
        b2Body* b = contact->GetFixtureB()->GetBody();
        if (contact->IsTouching() && a->GetType() == b2_dynamicBody && b->GetType() == b2_dynamicBody)
        {
            touching[a->GetUserData().pointer] = 1;
            touching[b->GetUserData().pointer] = 1;
        }
    }
    return static_cast<std::uint32_t>(std::count(touching.begin(), touching.end(), 1));
}

std::uint64_t DebrisBenchScene::StateHash() const
{
    cfx::StateHash hash;
    for (const b2Body* box : m_boxes)
    {
        const float state[] = {
            box->GetPosition().x,       box->GetPosition().y,       box->GetAngle(),
            box->GetLinearVelocity().x, box->GetLinearVelocity().y, box->GetAngularVelocity()};
        hash.Add(state, sizeof state);
    }
    hash.Add(m_effects->Particles());
    const EffectsStats& stats = m_effects->Stats();
    hash.Add(stats.spawnedByType.data(), stats.spawnedByType.size() * sizeof(std::uint64_t));
    hash.Add(&stats.recycled, sizeof stats.recycled);
    hash.Add(&m_dropped, sizeof m_dropped);
    return hash.Value();
}

DebrisBenchResult MeasureDebris(std::uint32_t boxes, std::uint32_t steps, std::uint32_t warmup,
                                std::uint64_t seed)
{
    DebrisBenchResult result;
    result.boxes = boxes;
    result.steps = steps;
    result.warmup = warmup;
    DebrisBenchScene scene(boxes, seed);
    result.capacity = scene.Fx().Config().budget.capacity;
    for (std::uint32_t i = 0; i < warmup; ++i)
    {
        scene.Step();
    }

    std::vector<double> world, effects;
    world.reserve(steps);
    effects.reserve(steps);
    double worldSum = 0.0, effectsSum = 0.0, perParticleSum = 0.0;
    std::uint32_t stepsWithParticles = 0;
    std::uint64_t recycled = scene.Fx().Stats().recycled;
    for (std::uint32_t i = 0; i < steps; ++i)
    {
        const DebrisBenchScene::StepSeconds seconds = scene.TimedStep();
        world.push_back(1.0e3 * seconds.world);
        effects.push_back(1.0e3 * seconds.effects);
        worldSum += world.back();
        effectsSum += effects.back();
        const std::uint32_t live = scene.LiveDuringLastStep();
        result.liveMax = std::max(result.liveMax, live);
        if (live > 0)
        {
            perParticleSum += 1.0e6 * effects.back() / static_cast<double>(live);
            ++stepsWithParticles;
        }
        result.stepsFull += scene.Fx().Stats().recycled > recycled ? 1u : 0u;
        recycled = scene.Fx().Stats().recycled;
    }
    std::sort(world.begin(), world.end());
    std::sort(effects.begin(), effects.end());
    if (steps > 0)
    {
        result.worldMsMedian = world[steps / 2];
        result.effectsMsMedian = effects[steps / 2];
        const auto rank = static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(steps)));
        result.effectsMsP99 = effects[std::max<std::size_t>(rank, 1) - 1];
        result.effectsMsMax = effects.back();
    }
    result.effectsOverWorld = worldSum > 0.0 ? effectsSum / worldSum : 0.0;
    result.nsPerParticle = stepsWithParticles > 0 ? perParticleSum / stepsWithParticles : 0.0;
    const EffectsStats& stats = scene.Fx().Stats();
    result.liveAfterMax = stats.liveMax;
    result.sparks = stats.spawnedByType[scene.Fx().Config().FindParticleType("sparks").index];
    result.dropped = scene.Dropped();
    result.touchingAtEnd = scene.BoxesTouchingBoxes();
    return result;
}

} // namespace cfx::bench
