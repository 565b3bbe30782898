// contactfx benchmarks: the particle benchmark scene and its timing (see particle_bench.h).
#include "scenes/particle_bench.h"

#include "particle_system_access.h"
#include "scenes/timing.h"

#include <algorithm>
#include <box2d/b2_body.h>
#include <box2d/b2_chain_shape.h>
#include <box2d/b2_fixture.h>
#include <chrono>
#include <cmath>
#include <malloc.h>
#if defined(__SANITIZE_ADDRESS__)
// From the ASan runtime (GCC ships no header for it).
extern "C" std::size_t __sanitizer_get_current_allocated_bytes();
#endif

namespace cfx::bench
{

namespace
{

constexpr int kSegments = 256;
constexpr float kHalfWidth = 64.0f;

ParticleTypeDef BenchType(ParticleBackend backend)
{
    ParticleTypeDef type;
    type.name = "bench";
    type.radius = 0.05f;
    type.restitution = 0.5f;
    type.drag = 0.2f;
    type.lifetime = 4.0f;
    type.gravityScale = 1.0f;
    type.categoryBits = 0x0002;
    type.maskBits = 0x0001;
    type.backend = backend;
    return type;
}

// Bytes the process has allocated and not freed. Under AddressSanitizer malloc is ASan's, which glibc's
// mallinfo2 does not see: ask ASan instead.
double HeapInUse()
{
#if defined(__SANITIZE_ADDRESS__)
    return static_cast<double>(__sanitizer_get_current_allocated_bytes());
#else
    const struct mallinfo2 info = mallinfo2();
    return static_cast<double>(info.uordblks) + static_cast<double>(info.hblkhd);
#endif
}

} // namespace

ParticleBenchScene::ParticleBenchScene(std::uint64_t seed)
    : m_world(std::make_unique<b2World>(b2Vec2(0.0f, -10.0f))), m_random(seed)
{
    // From right to left, so that the chain's one-sided normals point up.
    std::vector<b2Vec2> vertices;
    for (int i = 0; i <= kSegments; ++i)
    {
        const float x = kHalfWidth - 2.0f * kHalfWidth * static_cast<float>(i) / kSegments;
        vertices.emplace_back(x, 0.5f * std::sin(0.3f * x));
    }
    const b2Vec2 step = vertices[1] - vertices[0];
    b2ChainShape chain;
    chain.CreateChain(vertices.data(), static_cast<int>(vertices.size()), vertices.front() - step,
                      vertices.back() + step);
    b2BodyDef def;
    m_world->CreateBody(&def)->CreateFixture(&chain, 0.0f);
}

ParticleBenchScene::~ParticleBenchScene() = default;

void ParticleBenchScene::Populate(std::uint32_t count, ParticleBackend backend,
                                  const ParticleSystemOptions& options)
{
    m_count = count;
    m_types = {BenchType(backend)};
    m_particles = std::make_unique<ParticleSystem>(*m_world, m_types,
                                                   ParticleBudget{count, RecyclePolicy::oldest}, options);
    for (std::uint32_t i = 0; i < count; ++i)
    {
        SpawnOne(1.0f - m_random.Uniform(0.0f, 1.0f));
    }
}

void ParticleBenchScene::SpawnOne(float life)
{
    ParticleSpawn spawn;
    spawn.position = b2Vec2(m_random.Uniform(-60.0f, 60.0f), m_random.Uniform(2.0f, 20.0f));
    spawn.velocity = b2Vec2(m_random.Uniform(-5.0f, 5.0f), m_random.Uniform(-5.0f, 5.0f));
    spawn.life = life;
    spawn.type = ParticleTypeId{0};
    m_particles->Spawn(spawn);
}

void ParticleBenchScene::StepWorld()
{
    m_world->Step(1.0f / kBenchHz, 8, 3);
}

void ParticleBenchScene::StepParticles()
{
    m_particles->Step(1.0f / kBenchHz, m_world->GetGravity());
}

void ParticleBenchScene::IntegrateParticles()
{
    detail::ParticleSystemAccess::IntegrateWithoutCollision(*m_particles, 1.0f / kBenchHz,
                                                            m_world->GetGravity());
}

void ParticleBenchScene::Respawn()
{
    for (std::uint32_t i = m_particles->Count(); i < m_count; ++i)
    {
        SpawnOne(1.0f);
    }
}

void ParticleBenchScene::Step()
{
    StepWorld();
    StepParticles();
    Respawn();
}

void ParticleBenchScene::StepPlain()
{
    StepWorld();
    IntegrateParticles();
    Respawn();
}

ParticleBenchResult MeasureParticles(std::uint32_t count, ParticleBackend backend, std::uint32_t steps,
                                     std::uint32_t warmup, const ParticleSystemOptions& options)
{
    using Clock = std::chrono::steady_clock;
    ParticleBenchResult result;
    result.mode = backend == ParticleBackend::pool ? "pool" : "bodies";
    result.count = count;
    result.steps = steps;

    ParticleBenchScene scene;
    const double heapBefore = HeapInUse();
    scene.Populate(count, backend, options);
    for (std::uint32_t i = 0; i < warmup; ++i)
    {
        scene.Step();
    }
    result.bytesPerParticle =
        (HeapInUse() - heapBefore) / std::max<std::uint32_t>(1, scene.Particles().Count());

    // For the pool, a second scene with the same seed moves by the plain integration. The two are
    // stepped in turn, so that the machine's speed drifting (by up to half on a shared machine) between
    // two runs cannot skew the ratio of their timings.
    std::unique_ptr<ParticleBenchScene> plain;
    if (backend == ParticleBackend::pool)
    {
        plain = std::make_unique<ParticleBenchScene>();
        plain->Populate(count, backend, options);
        for (std::uint32_t i = 0; i < warmup; ++i)
        {
            plain->StepPlain();
        }
    }

    std::vector<double> step, update, plainUpdate;
    for (std::uint32_t i = 0; i < steps; ++i)
    {
        const Clock::time_point start = Clock::now();
        scene.StepWorld();
        const Clock::time_point worldDone = Clock::now();
        scene.StepParticles();
        const Clock::time_point updateDone = Clock::now();
        scene.Respawn();
        const Clock::time_point end = Clock::now();
        step.push_back(Milliseconds(end - start));
        update.push_back(Milliseconds(updateDone - worldDone));
        if (plain)
        {
            plain->StepWorld();
            const Clock::time_point plainStart = Clock::now();
            plain->IntegrateParticles();
            plainUpdate.push_back(Milliseconds(Clock::now() - plainStart));
            plain->Respawn();
        }
    }
    result.threads = scene.Particles().ThreadsUsed();
    Summarize(step, result.msMin, result.msMedian);
    Summarize(update, result.updateMsMin, result.updateMsMedian);
    if (plain)
    {
        result.plainThreads = plain->Particles().ThreadsUsed();
        Summarize(plainUpdate, result.plainMsMin, result.plainMsMedian);
    }
    return result;
}

} // namespace cfx::bench
