// contactfx benchmarks: the particle benchmark scene, written once for Google Benchmark and
// `contactfx bench particles`, identical for the pool and the body-per-particle mode.
//
// A static one-sided chain of 256 segments over x in [-64, 64] along y = 0.5 sin(0.3 x); N particles of
// radius 0.05, restitution 0.5, drag 0.2 and a 4 s life, started at uniform random x in [-60, 60],
// y in [2, 20], velocity uniform in [-5, 5] per axis; 60 Hz, gravity (0, -10). Particles only hit the
// chain (category 2, mask 1). A particle that dies is respawned the same way, so the count stays N. The
// first particles start with a life uniform in (0, 1] so that deaths are spread evenly over time (about
// N / 240 each step) instead of all falling on one step.
#pragma once

#include "contactfx/particle_system.h"
#include "contactfx/particle_types.h"
#include "scenes/split_mix.h"

#include <box2d/b2_world.h>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cfx::bench
{

inline constexpr float kBenchHz = 60.0f;

class ParticleBenchScene
{
public:
    /// The world and its chain; no particles yet.
    explicit ParticleBenchScene(std::uint64_t seed = 1);
    ~ParticleBenchScene();

    /// Creates the particle system and its `count` particles.
    void Populate(std::uint32_t count, ParticleBackend backend, const ParticleSystemOptions& options = {});

    /// world.Step, the particles' step, respawning the dead.
    void Step();
    /// The same with the particles' plain integration (no collision): the reference for Step.
    void StepPlain();

    /// The parts of a step, for timing them apart.
    void StepWorld();
    void StepParticles();
    void IntegrateParticles();
    void Respawn();

    b2World& World() { return *m_world; }
    ParticleSystem& Particles() { return *m_particles; }
    std::uint32_t Count() const { return m_count; }

private:
    void SpawnOne(float life);

    std::unique_ptr<b2World> m_world;
    std::vector<ParticleTypeDef> m_types;
    std::unique_ptr<ParticleSystem> m_particles; // destroyed before the world
    std::uint32_t m_count = 0;
    SplitMix64 m_random;
};

/// What one measured run gives.
struct ParticleBenchResult
{
    std::string mode; ///< "pool" or "bodies"
    std::uint32_t count = 0;
    std::uint32_t steps = 0;
    double msMin = 0.0; ///< whole step: world.Step + particles + respawn
    double msMedian = 0.0;
    double updateMsMin = 0.0; ///< the particles' step alone
    double updateMsMedian = 0.0;
    double plainMsMin = 0.0; ///< pool only: the plain integration of the same arrays
    double plainMsMedian = 0.0;
    double bytesPerParticle = 0.0; ///< heap in use after warm-up minus before, per live particle
    unsigned threads = 1;          ///< threads the particle step used
    unsigned plainThreads = 1;     ///< pool only: threads the plain integration used
};

/// Builds the scene, warms it up for `warmup` steps, then times `steps` steps. For the pool, also times
/// the plain integration in a second scene with the same seed, warmed up the same way and stepped in
/// turn with the first (one step of each), so that both timings see the machine at the same speed.
ParticleBenchResult MeasureParticles(std::uint32_t count, ParticleBackend backend, std::uint32_t steps,
                                     std::uint32_t warmup, const ParticleSystemOptions& options = {});

} // namespace cfx::bench
