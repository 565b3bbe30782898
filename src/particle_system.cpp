// contactfx: the particle pool (see particle_system.h). This file owns the storage, spawning, recycling
// and the shape of a step: scan the world (serial), advance runs of particles (taken by the threads as they
// free up), then join the runs and destroy dead particles' bodies (serial, Box2D is single-threaded).
#include "contactfx/particle_system.h"

#include "contactfx/config.h"
#include "contactfx/error.h"
#include "particle_system_access.h"
#include "particles/motion.h"
#include "particles/particle_check.h"
#include "particles/workers.h"
#include "particles/world_geometry.h"
#include "pointer_map.h"
#include "step_check.h"
#include "vector_text.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <box2d/b2_body.h>
#include <box2d/b2_circle_shape.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <cmath>
#include <utility>
#include <vector>

namespace cfx
{

namespace
{

// What a particle type is to the pool, flat.
struct TypeParams
{
    float gravityScale;
    float drag;
    float restitution;
    float restSpeed; // m/s
    float friction;
    float radius;
    float lifeRate; // life lost per second
    float density;
    float hitSpeed;
    std::uint16_t categoryBits;
    std::uint16_t maskBits;
    bool collide;
    bool bodyBacked;
};

// The least life loss a step subtracts (a lifetime of 4,096 steps); a smaller one is saved up, per type,
// until it reaches this. Subtracted from a float life below 1, a loss is rounded to the life's spacing
// (2^-24 at most): a loss under half of it is lost (at 10 kHz a lifetime of 3,600 s never ended) and a
// small one is off by up to half a spacing each step (1,000 s ran 19 % fast). From 2^-12 on, each step's
// rounding is within 2^-13 of its loss, and saving up delays a loss by less than 2^-12 of the lifetime.
constexpr double kLeastLifeLoss = 1.0 / 4096.0;

constexpr unsigned kMaxThreads = 8;
// Runs a split step is cut into, per thread and at most (see StepJob).
constexpr std::uint32_t kRunsPerThread = 16;
constexpr std::uint32_t kMaxRuns = kRunsPerThread * kMaxThreads;

// The threads a step of `particles` uses when each must get at least `perThread` of them: 1 .. threads.
unsigned PartsFor(std::uint64_t particles, std::uint64_t perThread, unsigned threads)
{
    return static_cast<unsigned>(std::clamp<std::uint64_t>(particles / perThread, 1, threads));
}

// What scales minParticlesPerThread for a step without collision. Such a step costs about a sixth as much
// per particle (0.020 against 0.12 ms at 10,000 particles on one thread); measured, a split pays from about
// 2,000 colliding and 16,000 plain particles a thread.
constexpr std::uint32_t kPlainPerColliding = 8;

// Bytes of the arrays every step walks, per slot; the layout promise of the header.
constexpr std::size_t kHotBytesPerSlot = 6 * sizeof(float) + sizeof(std::uint16_t);
static_assert(kHotBytesPerSlot == 26, "position, velocity, life, clearance and type: 26 bytes a particle");
static_assert(sizeof(particles::TypeStep) <= 64, "a type's step constants fit in a cache line");

// Logical index and time left to live, for lowest-life recycling; ordered by time left, then age.
using Candidate = std::pair<float, std::uint32_t>;

// Hit groups room is made for at creation, beyond ParticleBudget::particleHits (and never more than the
// pool's capacity, which bounds the hits of a step): a step with more distinct (type, body) pairs hit
// allocates once, as they first happen.
constexpr std::uint32_t kSpareHitGroups = 256;

// One (type, body) group of a step's hits while they are summed, in order of first appearance.
struct HitSums
{
    const b2Body* body;
    std::uint16_t type;
    std::uint32_t count;
    float speed, x, y;            // sums, in particle order
    std::uint32_t previousOfBody; // the group of the same body that appeared before this one, or kNoGroup
};
constexpr std::uint32_t kNoGroup = 0xFFFFFFFFu;

// A hash of where every moving body is (a non-static body with a velocity, not one of `ownBodies`: the
// particle bodies of body-backed types), position and angle bit for bit, with its address. b2World::Step
// changes it whenever it moves a body; creating, destroying or teleporting a body at rest does not, nor
// does a body-backed spawn.
std::uint64_t MovingPoses(const b2World& world, const detail::PointerMap* ownBodies)
{
    std::uint64_t hash = 0xcbf29ce484222325u; // FNV-1a over 32-bit words
    auto fold = [&hash](std::uint32_t word) { hash = (hash ^ word) * 0x100000001b3u; };
    for (const b2Body* body = world.GetBodyList(); body != nullptr; body = body->GetNext())
    {
        const b2Vec2 v = body->GetLinearVelocity();
        const bool moving = v.x != 0.0f || v.y != 0.0f || body->GetAngularVelocity() != 0.0f;
        if (body->GetType() != b2_staticBody && moving &&
            (ownBodies == nullptr || ownBodies->Find(body) == nullptr))
        {
            const auto address = reinterpret_cast<std::uintptr_t>(body);
            fold(static_cast<std::uint32_t>(address));
            fold(static_cast<std::uint32_t>(static_cast<std::uint64_t>(address) >> 32));
            fold(std::bit_cast<std::uint32_t>(body->GetPosition().x));
            fold(std::bit_cast<std::uint32_t>(body->GetPosition().y));
            fold(std::bit_cast<std::uint32_t>(body->GetAngle()));
        }
    }
    return hash;
}

} // namespace

struct ParticleSystem::Impl
{
    explicit Impl(b2World& w) : world(w) {}

    b2World& world;
    std::vector<TypeParams> types;
    std::vector<particles::TypeStep> steps; // per type, rebuilt each step
    std::vector<double> pendingLifeLoss;    // per type: life loss saved up (see kLeastLifeLoss)
    bool anyBodyBacked = false;
    bool anyPoolCollides = false;
    RecyclePolicy policy = RecyclePolicy::oldest;
    unsigned threads = 1;
    std::uint32_t minPerThread = 1;
    particles::StaticWatch staticWatch = particles::StaticWatch::everyStep;

    // Hot: touched by every step, one entry per slot.
    std::vector<float> positionX, positionY, velocityX, velocityY, life;
    std::vector<std::uint16_t> type;
    std::vector<float> clearance;
    // Only with checkParticles: each particle's position at the start of the step.
    std::vector<float> startX, startY;
    // Only with checkParticles: where a moving body's push took each particle from (PoolArrays::viaX).
    std::vector<float> viaX, viaY;
    // Only with checkParticles: where along its flight each particle's push began (PoolArrays::pushFraction).
    std::vector<float> pushFraction;
    // Only with checkParticles: what the check needs to know of each particle's step (PoolArrays::stepFlags).
    std::vector<std::uint8_t> stepFlags;
    // Cold: bodies of body-backed particles (empty when no type is body-backed). bodySet holds the
    // bodies the system still owns: a body the application destroyed (ForgetBody) leaves it at once,
    // and its particle leaves the pool at the next Spawn or Step (DropForgotten).
    std::vector<b2Body*> body;
    detail::PointerMap bodySet;
    std::uint32_t forgotten = 0;        // bodies forgotten since the last DropForgotten
    const b2Body* destroying = nullptr; // the body DestroyOwnBody is destroying: not the application's doing
    std::uint32_t head = 0;

    particles::WorldGeometry geometry;
    // What the resting marks and clearances were made under (see motion.h).
    float lastDt = 0.0f;
    b2Vec2 lastGravity{0.0f, 0.0f};
    std::uint64_t lastBuilds = 0;
    // Whether this step's spawns were placed after the bodies moved (see ParticleSystem::Spawn): not known
    // until the first Spawn since the last step, which notes the moving bodies' poses, or Effects, which
    // spawns after b2World::Step, says so (ParticleSystemAccess::SpawnAfterWorldStep).
    enum class SpawnSide : std::uint8_t
    {
        none,        ///< no spawn since the last step
        posesNoted,  ///< spawnPoses holds the poses at the first spawn
        afterMoving, ///< declared placed after the bodies moved
    };
    SpawnSide spawnSide = SpawnSide::none;
    std::uint64_t spawnPoses = 0;
    /// The moving bodies' poses, the system's own particle bodies left out (see cfx::MovingPoses).
    std::uint64_t MovingPoses() const { return cfx::MovingPoses(world, anyBodyBacked ? &bodySet : nullptr); }
    particles::Workers workers;
    std::array<std::vector<b2Body*>, kMaxThreads> dead; // reserved to capacity when body-backed
    // While Effects emits (ParticleSystemAccess::DeferBodyDestruction), the bodies of the particles Spawn
    // recycles wait here instead of being destroyed: destroying one ends its contacts, and Effects is
    // reading the contact lists it would change. Reserved to capacity when body-backed (a step spawns at
    // most that many).
    bool deferDestruction = false;
    std::vector<b2Body*> recycledBodies;

    // Particle hits, when recorded (maxHitGroups > 0 and a pool type collides; else all empty). A step's
    // run writes its hits at hits[begin, begin + its count) (logical indices: a run has at most one hit
    // per particle); after the join they are summed into hitSums (scratch), and the groups kept go to
    // hitGroups (what Hits() shows). hitBodies: body -> its latest group in hitSums, emptied after each step
    // (looked up, never iterated: addresses never decide an order).
    std::uint32_t maxHitGroups = 0;
    std::vector<particles::ParticleHit> hits;
    std::vector<HitSums> hitSums;
    std::vector<std::uint32_t> hitOrder;
    std::vector<ParticleHitGroup> hitGroups;
    detail::PointerMap hitBodies;

    // Lowest-life recycling: the next victims, cheapest first; invalid after a step.
    std::vector<Candidate> candidates;
    std::size_t nextCandidate = 0;
    bool candidatesValid = false;

    particles::PoolArrays Arrays(std::uint32_t capacity)
    {
        return particles::PoolArrays{positionX.data(),
                                     positionY.data(),
                                     velocityX.data(),
                                     velocityY.data(),
                                     life.data(),
                                     type.data(),
                                     clearance.data(),
                                     anyBodyBacked ? body.data() : nullptr,
                                     startX.empty() ? nullptr : startX.data(),
                                     startX.empty() ? nullptr : startY.data(),
                                     viaX.empty() ? nullptr : viaX.data(),
                                     viaX.empty() ? nullptr : viaY.data(),
                                     pushFraction.empty() ? nullptr : pushFraction.data(),
                                     stepFlags.empty() ? nullptr : stepFlags.data(),
                                     capacity,
                                     head};
    }

    // Destroys a particle's body unless the application did (ForgetBody): never destroyed twice. It is
    // still in bodySet while Box2D destroys it, so that the application's listeners, which hear of its
    // fixtures and contacts going, still see it as a particle body (IsParticleBody).
    void DestroyOwnBody(b2Body* particleBody)
    {
        if (bodySet.Find(particleBody) != nullptr)
        {
            destroying = particleBody;
            world.DestroyBody(particleBody);
            destroying = nullptr;
            bodySet.Erase(particleBody);
        }
    }

    void ReleaseBody(std::uint32_t slot)
    {
        if (anyBodyBacked && body[slot] != nullptr)
        {
            if (deferDestruction)
            {
                recycledBodies.push_back(body[slot]);
            }
            else
            {
                DestroyOwnBody(body[slot]);
            }
            body[slot] = nullptr;
        }
    }

    void DestroyRecycledBodies()
    {
        deferDestruction = false;
        for (b2Body* recycled : recycledBodies)
        {
            DestroyOwnBody(recycled);
        }
        recycledBodies.clear();
    }

    // Removes the particles whose bodies the application destroyed (ForgetBody), keeping the others in
    // order; returns the new count. Runs before anything creates a body, so a forgotten body's address
    // cannot have been given to a new particle yet: a live slot's body missing from bodySet is forgotten.
    std::uint32_t DropForgotten(std::uint32_t count, std::uint32_t capacity)
    {
        if (forgotten == 0)
        {
            return count;
        }
        forgotten = 0;
        candidatesValid = false;
        const particles::PoolArrays pool = Arrays(capacity);
        std::uint32_t kept = 0;
        for (std::uint32_t i = 0; i < count; ++i)
        {
            const std::uint32_t slot = pool.Slot(i);
            if (body[slot] != nullptr && bodySet.Find(body[slot]) == nullptr)
            {
                body[slot] = nullptr;
                continue;
            }
            if (kept != i)
            {
                particles::MoveParticles(pool, i, kept, 1);
            }
            ++kept;
        }
        return kept;
    }

    b2Body* CreateBody(const TypeParams& params, b2Vec2 position, b2Vec2 velocity)
    {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position = position;
        def.linearVelocity = velocity;
        def.fixedRotation = true;
        def.linearDamping = params.drag;
        def.gravityScale = params.gravityScale;
        b2Body* created = world.CreateBody(&def);
        b2CircleShape circle;
        circle.m_radius = params.radius;
        b2FixtureDef fixtureDef;
        fixtureDef.shape = &circle;
        fixtureDef.density = params.density;
        fixtureDef.friction = params.friction;
        fixtureDef.restitution = params.restitution;
        fixtureDef.restitutionThreshold = params.restSpeed;
        fixtureDef.filter.categoryBits = params.categoryBits;
        fixtureDef.filter.maskBits = params.collide ? params.maskBits : 0;
        created->CreateFixture(&fixtureDef);
        bodySet.Set(created, 1);
        return created;
    }

    // Adds `count` hits to the step's groups, in order: serial, runs in run order (logical particle order),
    // so the sums are the same bits for any number of threads.
    void SumHits(const particles::ParticleHit* first, std::uint32_t count)
    {
        // Particles spawned together mostly hit the same body: the last group found is tried first.
        std::uint32_t last = kNoGroup;
        for (const particles::ParticleHit& hit : std::span(first, count))
        {
            if (last != kNoGroup && hitSums[last].body == hit.body && hitSums[last].type == hit.type)
            {
                Add(hitSums[last], hit);
                continue;
            }
            std::uint64_t* latest = hitBodies.Find(hit.body);
            auto group = latest == nullptr ? kNoGroup : static_cast<std::uint32_t>(*latest);
            while (group != kNoGroup && hitSums[group].type != hit.type)
            {
                group = hitSums[group].previousOfBody;
            }
            if (group == kNoGroup)
            {
                group = static_cast<std::uint32_t>(hitSums.size());
                const std::uint32_t previous =
                    latest == nullptr ? kNoGroup : static_cast<std::uint32_t>(*latest);
                hitSums.push_back(HitSums{hit.body, hit.type, 0, 0.0f, 0.0f, 0.0f, previous});
                hitBodies.Set(hit.body, group);
            }
            Add(hitSums[group], hit);
            last = group;
        }
    }

    static void Add(HitSums& sums, const particles::ParticleHit& hit)
    {
        sums.count += 1;
        sums.speed += hit.speed;
        sums.x += hit.x;
        sums.y += hit.y;
    }

    // Turns the summed groups into hitGroups: all of them in order of first appearance, or when there are
    // more than maxHitGroups, the maxHitGroups with the most hits (ties: the first to appear), still in
    // order of first appearance. Empties the scratch; returns how many groups were dropped.
    std::uint32_t KeepHitGroups()
    {
        const auto groups = static_cast<std::uint32_t>(hitSums.size());
        hitOrder.clear();
        for (std::uint32_t group = 0; group < groups; ++group)
        {
            hitOrder.push_back(group);
            hitBodies.Erase(hitSums[group].body);
        }
        const std::uint32_t kept = std::min(groups, maxHitGroups);
        if (kept < groups)
        {
            // A strict total order: the set kept does not depend on how nth_element gets there.
            const auto larger = [this](std::uint32_t a, std::uint32_t b)
            { return hitSums[a].count != hitSums[b].count ? hitSums[a].count > hitSums[b].count : a < b; };
            std::nth_element(hitOrder.begin(), hitOrder.begin() + kept, hitOrder.end(), larger);
            std::sort(hitOrder.begin(), hitOrder.begin() + kept);
        }
        for (std::uint32_t k = 0; k < kept; ++k)
        {
            const HitSums& sums = hitSums[hitOrder[k]];
            const auto count = static_cast<float>(sums.count);
            hitGroups.push_back(ParticleHitGroup{ParticleTypeId{sums.type}, sums.body, sums.count,
                                                 sums.speed / count, b2Vec2(sums.x / count, sums.y / count)});
        }
        hitSums.clear();
        return groups - kept;
    }

    void BuildCandidates(std::uint32_t count, std::uint32_t capacity)
    {
        const particles::PoolArrays pool = Arrays(capacity);
        candidates.clear();
        for (std::uint32_t i = 0; i < count; ++i)
        {
            const std::uint32_t slot = pool.Slot(i);
            candidates.emplace_back(life[slot] / types[type[slot]].lifeRate, i);
        }
        const std::size_t keep = std::min<std::size_t>(count, std::max<std::size_t>(64, count / 64));
        std::nth_element(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(keep - 1),
                         candidates.end());
        candidates.resize(keep);
        std::sort(candidates.begin(), candidates.end());
        nextCandidate = 0;
        candidatesValid = true;
    }
};

ParticleSystem::ParticleSystem(b2World& world, std::span<const ParticleTypeDef> types,
                               const ParticleBudget& budget, const ParticleSystemOptions& options)
    : m_impl(std::make_unique<Impl>(world)), m_capacity(budget.capacity)
{
    // Used alone, nothing has checked the definition yet (Effects has: a second look costs nothing).
    if (std::vector<Diagnostic> problems = ValidateParticles(types, budget); !problems.empty())
    {
        throw InputError(std::move(problems));
    }
    Impl& impl = *m_impl;
    for (const ParticleTypeDef& def : types)
    {
        TypeParams params{};
        params.gravityScale = def.gravityScale;
        params.drag = def.drag;
        params.restitution = def.restitution;
        params.restSpeed = def.restSpeed;
        params.friction = def.friction;
        params.radius = def.radius;
        params.lifeRate = 1.0f / def.lifetime;
        params.density = def.density;
        params.hitSpeed = def.hitSpeed;
        params.categoryBits = def.categoryBits;
        params.maskBits = def.maskBits;
        params.collide = def.collide;
        params.bodyBacked = def.backend == ParticleBackend::body;
        impl.anyBodyBacked = impl.anyBodyBacked || params.bodyBacked;
        impl.anyPoolCollides = impl.anyPoolCollides || (!params.bodyBacked && params.collide);
        impl.types.push_back(params);
    }
    impl.steps.resize(impl.types.size());
    impl.pendingLifeLoss.assign(impl.types.size(), 0.0);
    impl.policy = budget.recycle;
    const unsigned hardware = particles::UsableHardwareThreads();
    impl.threads = std::clamp(options.threads == 0 ? hardware : options.threads, 1u, kMaxThreads);
    impl.minPerThread = std::max<std::uint32_t>(1, options.minParticlesPerThread);
    impl.staticWatch =
        options.watchStaticGeometry ? particles::StaticWatch::everyStep : particles::StaticWatch::onRequest;
    // The helpers the fullest pool can use, now: starting a thread allocates, and a step never does.
    impl.workers.Start(PartsFor(m_capacity, impl.minPerThread, impl.threads));
    impl.positionX.resize(m_capacity);
    impl.positionY.resize(m_capacity);
    impl.velocityX.resize(m_capacity);
    impl.velocityY.resize(m_capacity);
    impl.life.resize(m_capacity);
    impl.type.resize(m_capacity);
    impl.clearance.resize(m_capacity);
    if (options.checkParticles)
    {
        impl.startX.resize(m_capacity);
        impl.startY.resize(m_capacity);
        impl.viaX.resize(m_capacity);
        impl.viaY.resize(m_capacity);
        impl.pushFraction.resize(m_capacity);
        impl.stepFlags.resize(m_capacity);
    }
    if (impl.anyBodyBacked)
    {
        impl.body.assign(m_capacity, nullptr);
        impl.bodySet.Reserve(m_capacity);
        impl.recycledBodies.reserve(m_capacity);
        for (unsigned part = 0; part < impl.threads; ++part)
        {
            impl.dead[part].reserve(m_capacity);
        }
    }
    if (impl.policy == RecyclePolicy::lowestLife)
    {
        impl.candidates.reserve(m_capacity);
    }
    if (budget.particleHits > 0 && impl.anyPoolCollides)
    {
        impl.maxHitGroups = budget.particleHits;
        impl.hits.resize(m_capacity);
        const std::uint32_t groups = std::min(m_capacity, budget.particleHits + kSpareHitGroups);
        impl.hitSums.reserve(groups);
        impl.hitOrder.reserve(groups);
        impl.hitBodies.Reserve(groups);
        impl.hitGroups.reserve(std::min(m_capacity, budget.particleHits));
    }
}

ParticleSystem::~ParticleSystem()
{
    detail::ParticleSystemAccess::DestroyAllBodies(*this);
}

void detail::ParticleSystemAccess::DestroyAllBodies(ParticleSystem& system)
{
    ParticleSystem::Impl& impl = *system.m_impl;
    impl.DestroyRecycledBodies();
    system.m_count = impl.DropForgotten(system.m_count, system.m_capacity);
    for (std::uint32_t i = 0; i < system.m_count; ++i)
    {
        impl.ReleaseBody(system.View().Slot(i));
    }
}

void ParticleSystem::Spawn(const ParticleSpawn& spawn)
{
    if (spawn.type.index >= m_impl->types.size())
    {
        throw InputError("<api>", "type",
                         spawn.type.IsValid() ? "index " + std::to_string(spawn.type.index) +
                                                    " names no particle type of this system (it has " +
                                                    std::to_string(m_impl->types.size()) + ")"
                                              : std::string("no particle type (ParticleTypeId{})"));
    }
    if (spawn.life <= 0.0f)
    {
        return;
    }
    if (std::isnan(spawn.life) || !particles::Sane(spawn.position) || !particles::Sane(spawn.velocity))
    {
        ++m_counters.nonFinite; // never stored: nothing not finite reaches a step, or Box2D
        return;
    }
    Impl& impl = *m_impl;
    m_count = impl.DropForgotten(m_count, m_capacity);
    std::uint32_t slot;
    if (m_count < m_capacity)
    {
        slot = View().Slot(m_count);
        ++m_count;
        impl.candidatesValid = false;
    }
    else if (impl.policy == RecyclePolicy::lowestLife)
    {
        // Full: the particle with the least time left makes room and the new one takes its place.
        if (!impl.candidatesValid || impl.nextCandidate == impl.candidates.size())
        {
            impl.BuildCandidates(m_count, m_capacity);
        }
        slot = View().Slot(impl.candidates[impl.nextCandidate++].second);
        impl.ReleaseBody(slot);
        ++m_recycled;
    }
    else
    {
        // Full: the oldest particle (at the head of the ring) makes room, and the ring turns by one,
        // so the new particle is the newest in order.
        slot = impl.head;
        impl.ReleaseBody(slot);
        impl.head = impl.head + 1 == m_capacity ? 0 : impl.head + 1;
        ++m_recycled;
    }
    const TypeParams& params = impl.types[spawn.type.index];
    impl.positionX[slot] = spawn.position.x;
    impl.positionY[slot] = spawn.position.y;
    impl.velocityX[slot] = spawn.velocity.x;
    impl.velocityY[slot] = spawn.velocity.y;
    impl.life[slot] = std::min(spawn.life, 1.0f);
    impl.type[slot] = spawn.type.index;
    impl.clearance[slot] = particles::kSpawnedClearance;
    if (impl.spawnSide == Impl::SpawnSide::none)
    {
        impl.spawnPoses = impl.MovingPoses();
        impl.spawnSide = Impl::SpawnSide::posesNoted;
    }
    if (impl.anyBodyBacked)
    {
        impl.body[slot] =
            params.bodyBacked ? impl.CreateBody(params, spawn.position, spawn.velocity) : nullptr;
    }
}

void ParticleSystem::Step(float dt, b2Vec2 gravity)
{
    detail::CheckStepTime(dt);
    if (!gravity.IsValid())
    {
        throw InputError("<api>", "gravity",
                         "expected a finite gravity, found " + detail::VectorText(gravity));
    }
    Advance(dt, gravity, true);
}

void ParticleSystem::ForgetBody(const b2Body* body)
{
    Impl& impl = *m_impl;
    if (impl.anyBodyBacked && body != nullptr && body != impl.destroying && impl.bodySet.Erase(body))
    {
        impl.forgotten += 1;
    }
}

void detail::ParticleSystemAccess::SpawnAfterWorldStep(ParticleSystem& system)
{
    system.m_impl->spawnSide = ParticleSystem::Impl::SpawnSide::afterMoving;
}

void detail::ParticleSystemAccess::DeferBodyDestruction(ParticleSystem& system)
{
    system.m_impl->deferDestruction = true;
}

void detail::ParticleSystemAccess::DestroyDeferredBodies(ParticleSystem& system)
{
    system.m_impl->DestroyRecycledBodies();
}

void detail::ParticleSystemAccess::IntegrateWithoutCollision(ParticleSystem& system, float dt, b2Vec2 gravity)
{
    system.Advance(dt, gravity, false);
}

namespace
{

// One step's split of the particles into runs, shared with the helper threads. The runs are more than the
// threads, and each thread takes the next run not yet taken until none is left: where particles cost more
// (the young ones, near the bodies that made them) a thread takes fewer runs, so the threads finish together.
// Which thread advances a run does not change its result, and the runs are joined, and their dead bodies
// destroyed, in their order: the same bits for any number of threads and any timing.
struct StepJob
{
    /// What one run left.
    struct Run
    {
        std::uint32_t kept;
        std::uint32_t owner;     ///< the part (thread) that advanced it
        std::uint32_t deadBegin; ///< its dead bodies: [deadBegin, deadEnd) of its owner's list
        std::uint32_t deadEnd;
        std::uint32_t hitCount; ///< its hits: [begin, begin + hitCount) of `hits`
    };

    particles::PoolArrays pool;
    const particles::TypeStep* steps;
    const particles::WorldGeometry* geometry;
    std::vector<b2Body*>* dead;
    particles::ParticleHit* hits; ///< by logical index; null: hits are not recorded
    float dt;
    particles::StepTrust trust;
    std::uint32_t runCount;
    std::array<std::uint32_t, kMaxRuns + 1> begin;
    std::array<Run, kMaxRuns> runs;
    std::array<particles::StepCounts, kMaxThreads> counts;
    std::atomic<std::uint32_t> next{0};

    static void Advance(void* context, unsigned part)
    {
        auto& job = *static_cast<StepJob*>(context);
        std::vector<b2Body*>& dead = job.dead[part];
        for (std::uint32_t run = job.next.fetch_add(1, std::memory_order_relaxed); run < job.runCount;
             run = job.next.fetch_add(1, std::memory_order_relaxed))
        {
            const auto deadBegin = static_cast<std::uint32_t>(dead.size());
            particles::HitSink sink{job.hits == nullptr ? nullptr : job.hits + job.begin[run], 0};
            const std::uint32_t kept = particles::AdvanceRange(
                job.pool, job.steps, job.geometry, job.dt, job.trust, job.begin[run], job.begin[run + 1],
                dead, job.counts[part], job.hits == nullptr ? nullptr : &sink);
            job.runs[run] = Run{kept, part, deadBegin, static_cast<std::uint32_t>(dead.size()), sink.count};
        }
    }
};

} // namespace

void ParticleSystem::Advance(float dt, b2Vec2 gravity, bool collide)
{
    Impl& impl = *m_impl;
    m_count = impl.DropForgotten(m_count, m_capacity);
    impl.candidatesValid = false;
    for (std::size_t t = 0; t < impl.types.size(); ++t)
    {
        const TypeParams& params = impl.types[t];
        particles::TypeStep& step = impl.steps[t];
        step.gravityDelta = (dt * params.gravityScale) * gravity;
        step.damping = 1.0f / (1.0f + dt * params.drag);
        // Exactly as the step computes it from a zero velocity.
        step.restVelocity =
            b2Vec2((0.0f + step.gravityDelta.x) * step.damping, (0.0f + step.gravityDelta.y) * step.damping);
        // A loss of at least kLeastLifeLoss is the step's own (the bits it always was); a smaller one is
        // saved up in doubles and taken when it reaches that.
        double& pending = impl.pendingLifeLoss[t];
        const float own = dt * params.lifeRate;
        if (pending == 0.0 && own >= kLeastLifeLoss)
        {
            step.lifeLoss = own;
        }
        else
        {
            pending += static_cast<double>(dt) * static_cast<double>(params.lifeRate);
            step.lifeLoss = pending >= kLeastLifeLoss ? static_cast<float>(pending) : 0.0f;
            // Taken whole: the float's rounding (under 2^-24 of it) is dropped, so that a later step whose
            // own loss is large enough is its own again.
            pending = step.lifeLoss > 0.0f ? 0.0 : pending;
        }
        step.side = particles::ParticleSide{params.radius,    params.restitution,  params.friction,
                                            params.restSpeed, params.categoryBits, params.maskBits};
        step.hitSpeed = params.hitSpeed;
        step.bodyBacked = params.bodyBacked;
        step.sweeps = params.collide && !params.bodyBacked;
    }
    const bool scan = collide && impl.anyPoolCollides && m_count > 0;
    struct SpawnSideReset // whatever happens below, the next step's spawns start anew
    {
        Impl& impl;
        ~SpawnSideReset() { impl.spawnSide = Impl::SpawnSide::none; }
    } spawnSideReset{impl};
    particles::StepTrust trust;
    if (scan)
    {
        const detail::ParticleBodyFilter particleBodies(*this);
        impl.geometry.Scan(impl.world, impl.anyBodyBacked ? &particleBodies : nullptr, dt, impl.staticWatch);
        trust.clearance = impl.geometry.StaticBuilds() == impl.lastBuilds;
        trust.resting = trust.clearance && dt == impl.lastDt && gravity == impl.lastGravity;
        trust.spawnsAfterMoving =
            impl.spawnSide != Impl::SpawnSide::posesNoted || impl.MovingPoses() == impl.spawnPoses;
        impl.lastDt = dt;
        impl.lastGravity = gravity;
        impl.lastBuilds = impl.geometry.StaticBuilds();
        m_counters.skippedBodies = impl.geometry.SkippedBodies();
    }
    else
    {
        impl.lastBuilds = 0; // particles move without collision: their clearances and marks go stale
    }

    const std::uint64_t perThread = std::uint64_t{impl.minPerThread} * (scan ? 1u : kPlainPerColliding);
    const unsigned parts = PartsFor(m_count, perThread, impl.threads);
    StepJob job;
    job.pool = impl.Arrays(m_capacity);
    job.steps = impl.steps.data();
    job.geometry = scan ? &impl.geometry : nullptr;
    job.dead = impl.dead.data();
    job.hits = scan && impl.maxHitGroups > 0 ? impl.hits.data() : nullptr;
    job.dt = dt;
    job.trust = trust;
    job.runCount = parts == 1 ? 1u : std::min<std::uint32_t>(kRunsPerThread * parts, kMaxRuns);
    for (std::uint32_t run = 0; run <= job.runCount; ++run)
    {
        job.begin[run] = static_cast<std::uint32_t>(static_cast<std::uint64_t>(m_count) * run / job.runCount);
    }
    impl.workers.Run(parts, &StepJob::Advance, &job);
    m_threadsUsed = parts;

    std::uint32_t total = 0;
    for (std::uint32_t run = 0; run < job.runCount; ++run)
    {
        const StepJob::Run& done = job.runs[run];
        if (job.begin[run] != total && done.kept > 0)
        {
            particles::MoveParticles(job.pool, job.begin[run], total, done.kept);
        }
        total += done.kept;
        const std::vector<b2Body*>& dead = impl.dead[done.owner];
        for (std::uint32_t k = done.deadBegin; k < done.deadEnd; ++k)
        {
            impl.DestroyOwnBody(dead[k]);
        }
    }
    for (unsigned part = 0; part < parts; ++part)
    {
        impl.dead[part].clear();
    }
    m_count = total;
    impl.hitGroups.clear();
    if (job.hits != nullptr)
    {
        for (std::uint32_t run = 0; run < job.runCount; ++run)
        {
            impl.SumHits(job.hits + job.begin[run], job.runs[run].hitCount);
        }
        m_counters.droppedHitGroups += impl.KeepHitGroups();
    }
    for (unsigned part = 0; part < parts; ++part)
    {
        m_counters.crushed += job.counts[part].crushed;
        m_counters.nonFinite += job.counts[part].nonFinite;
    }
    if (!impl.startX.empty() && scan)
    {
        particles::CheckCounts found;
        const detail::ParticleBodyFilter particleBodies(*this);
        particles::CheckParticles(impl.world, impl.Arrays(m_capacity), impl.steps.data(), m_count,
                                  impl.anyBodyBacked ? &particleBodies : nullptr, dt, found);
        m_counters.stepsInside += found.inside;
        m_counters.crossings += found.crossings;
        m_counters.passedThroughMoving += found.passedThrough;
    }
}

void ParticleSystem::ShiftOrigin(b2Vec2 newOrigin)
{
    if (!newOrigin.IsValid())
    {
        throw InputError("<api>", "newOrigin",
                         "expected a finite vector, found " + detail::VectorText(newOrigin));
    }
    if (newOrigin.x == 0.0f && newOrigin.y == 0.0f)
    {
        return; // nothing moves: the cache stays (a shift of zero every 20 steps rebuilt it 20 times)
    }
    Impl& impl = *m_impl;
    // Every slot, live or not: a rare call, and no ring arithmetic to get wrong.
    for (std::uint32_t slot = 0; slot < m_capacity; ++slot)
    {
        impl.positionX[slot] -= newOrigin.x;
        impl.positionY[slot] -= newOrigin.y;
    }
    for (std::size_t slot = 0; slot < impl.startX.size(); ++slot)
    {
        impl.startX[slot] -= newOrigin.x;
        impl.startY[slot] -= newOrigin.y;
        impl.viaX[slot] -= newOrigin.x;
        impl.viaY[slot] -= newOrigin.y;
    }
    for (ParticleHitGroup& group : impl.hitGroups)
    {
        group.centre -= newOrigin;
    }
    // The cache, the clearances and the resting marks are in world coordinates: all made again.
    impl.geometry.Invalidate();
}

bool ParticleSystem::Clear()
{
    Impl& impl = *m_impl;
    // Not inside b2World::Step (Box2D cannot destroy bodies then), nor from a destruction listener while this
    // system destroys a particle's body (in its own step, or in a Clear: the body would go twice). No throw:
    // both are inside Box2D's calls, which an exception would leave half done.
    if (impl.world.IsLocked() || impl.destroying != nullptr)
    {
        return false;
    }
    m_count = impl.DropForgotten(m_count, m_capacity);
    for (std::uint32_t i = 0; i < m_count; ++i)
    {
        impl.ReleaseBody(View().Slot(i));
    }
    m_count = 0;
    impl.candidatesValid = false;
    impl.hitGroups.clear();
    impl.spawnSide = Impl::SpawnSide::none; // the next spawn notes the poses anew
    return true;
}

void ParticleSystem::InvalidateStaticGeometry()
{
    m_impl->geometry.Invalidate();
}

bool ParticleSystem::BuildStaticGeometry()
{
    Impl& impl = *m_impl;
    return impl.geometry.UpdateStatic(impl.world, impl.staticWatch);
}

ParticleView ParticleSystem::View() const
{
    const Impl& impl = *m_impl;
    ParticleView view;
    view.positionX = impl.positionX.data();
    view.positionY = impl.positionY.data();
    view.velocityX = impl.velocityX.data();
    view.velocityY = impl.velocityY.data();
    view.life = impl.life.data();
    view.type = impl.type.data();
    view.head = impl.head;
    view.count = m_count;
    view.capacity = m_capacity;
    return view;
}

std::span<const ParticleHitGroup> ParticleSystem::Hits() const
{
    return m_impl->hitGroups;
}

bool ParticleSystem::IsParticleBody(const b2Body* body) const
{
    return body != nullptr && m_impl->bodySet.Find(body) != nullptr;
}

std::uint64_t ParticleSystem::StaticGeometryBuilds() const
{
    return m_impl->geometry.StaticBuilds();
}

std::size_t ParticleSystem::BytesPerSlot() const
{
    const Impl& impl = *m_impl;
    std::size_t bytes = kHotBytesPerSlot;
    if (impl.anyBodyBacked)
    {
        // The body, and room in each run's dead list and in the recycled list.
        bytes += sizeof(b2Body*) * (2 + impl.threads);
    }
    if (impl.policy == RecyclePolicy::lowestLife)
    {
        bytes += sizeof(Candidate);
    }
    if (impl.maxHitGroups > 0)
    {
        bytes += sizeof(particles::ParticleHit); // room for the particle's hit of a step
    }
    return bytes;
}

std::size_t ParticleSystem::MemoryBytes() const
{
    const Impl& impl = *m_impl;
    std::size_t bytes = static_cast<std::size_t>(m_capacity) * BytesPerSlot();
    bytes += impl.types.capacity() * sizeof(TypeParams) + impl.steps.capacity() * sizeof(particles::TypeStep);
    bytes += (impl.startX.capacity() + impl.startY.capacity() + impl.viaX.capacity() + impl.viaY.capacity() +
              impl.pushFraction.capacity()) *
                 sizeof(float) +
             impl.stepFlags.capacity();
    bytes += impl.hitSums.capacity() * sizeof(HitSums) + impl.hitOrder.capacity() * sizeof(std::uint32_t) +
             impl.hitGroups.capacity() * sizeof(ParticleHitGroup);
    return bytes + impl.geometry.Bytes();
}

} // namespace cfx
