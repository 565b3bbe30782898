// contactfx benchmarks: the debris scene, the cost of the effects layer among many moving bodies, written
// once for Google Benchmark (`Debris/200`, `Debris/1000`), `contactfx bench debris` and the tests.
//
// N dynamic steel boxes (0.4 m, density 100: 16 kg, friction 0.3) in a closed loop over static concrete
// (friction 0.5; Box2D's mix gives 0.39, a friction angle of 21 degrees):
//
//   - a bin (floor and two walls) whose inner width grows with N (max(24, 2 sqrt(N)) columns of 0.5 m),
//     holding the pile; all N boxes start in it, stacked in a loose grid that settles at once;
//   - on each side, two ramps of 10 m at 35 degrees, one above the other, falling toward the bin: a box
//     slides down the upper one, drops 2 m onto the lower one and is thrown off its end into the bin.
//
// Every 3 steps (20 boxes a second at 60 Hz; the sides take turns) the dropper takes the highest box that
// has settled in the bin (inside it, slower than 0.5 m/s; ties: the lower index), or first any box that
// fell out of the scene, and puts it near the top of an upper ramp, lying on it, sliding down at 6 m/s
// (plus up to 1 m/s either way, a spin of up to 0.5 rad/s and a place within 0.4 m, from the scene's own
// SplitMix64 generator); when a box's centre is within 0.45 m of that place the side keeps its turn and
// nothing is dropped. So sparks never stop: 30 to 60 boxes are out of the bin at any time, sliding steel
// on concrete at several metres a second, landing on the lower ramps and on the pile, and the pile stays
// awake under the arrivals.
//
// Effects: DefaultPreset() as is (8,192 particles, oldest recycled; sparks from steel on concrete, the
// only pair with a rule in the scene), unless a smaller capacity is asked for. The ramps emit about 300
// sparks a step, more than 8,192 sparks living 0.45 to 0.9 s can hold, so from about the 125th step on
// the pool is full whenever sparks are emitted and recycles its oldest (kDebrisWarmup skips the filling).
// Sparks collide with the boxes (moving bodies) and the concrete. 60 Hz, gravity (0, -10),
// world.Step(1/60, 8, 3). Same boxes, seed and capacity: the same bits, step for step.
#pragma once

#include "contactfx/effects.h"
#include "scenes/split_mix.h"

#include <box2d/b2_world.h>
#include <cstdint>
#include <memory>
#include <vector>

class b2Body;

namespace cfx::bench
{

inline constexpr float kDebrisHz = 60.0f;
/// Untimed steps before a measurement: the pool is full from about the 125th step on.
inline constexpr std::uint32_t kDebrisWarmup = 150;

class DebrisBenchScene
{
public:
    /// The world, its `boxes` boxes in the bin and the effects layer (capacity 0: the preset's; `particles`:
    /// threads and checks of the effects' particle system).
    explicit DebrisBenchScene(std::uint32_t boxes, std::uint64_t seed = 1, std::uint32_t capacity = 0,
                              const ParticleSystemOptions& particles = {});
    ~DebrisBenchScene();
    DebrisBenchScene(const DebrisBenchScene&) = delete;
    DebrisBenchScene& operator=(const DebrisBenchScene&) = delete;

    /// world.Step, Effects::Step, then the dropper.
    void Step();

    /// The parts of a step, for timing them apart.
    void StepWorld();
    void StepEffects();
    void Drop(); ///< every 6th call, puts one box back at the top of a ramp (not part of what is timed)

    /// Wall-clock seconds of the two timed parts of one step.
    struct StepSeconds
    {
        double world = 0.0;   ///< world.Step
        double effects = 0.0; ///< Effects::Step
    };
    /// Step(), timing world.Step and Effects::Step apart (the drop is not timed).
    StepSeconds TimedStep();

    b2World& World() { return *m_world; }
    Effects& Fx() { return *m_effects; }
    const Effects& Fx() const { return *m_effects; }
    std::uint32_t Boxes() const { return static_cast<std::uint32_t>(m_boxes.size()); }
    std::uint64_t Steps() const { return m_steps; }
    /// Boxes put back at the top of a ramp so far.
    std::uint64_t Dropped() const { return m_dropped; }
    /// The particles the last Effects::Step moved: live after emission, before they moved (the most
    /// live at once during that step). Stats().live, counted after they moved, is lower by those that
    /// died in the step (aged out or crushed).
    std::uint32_t LiveDuringLastStep() const { return m_liveDuringStep; }

    /// Boxes whose centre is inside the bin.
    std::uint32_t BoxesInBin() const;
    /// Boxes that touch at least one other box.
    std::uint32_t BoxesTouchingBoxes() const;
    /// A hash of every box's position, angle and velocities and every particle's position, velocity,
    /// life and type, bit for bit, and the effects' counters.
    std::uint64_t StateHash() const;

private:
    struct Ramp
    {
        b2Vec2 top;  ///< the upper end of the surface a box slides on
        b2Vec2 down; ///< unit vector down the slope
    };

    void BuildStatic();
    void BuildBoxes();
    b2Body* PickBoxToDrop() const;
    bool SpotIsFree(b2Vec2 centre) const;

    std::unique_ptr<b2World> m_world;
    std::unique_ptr<Effects> m_effects; // destroyed before the world
    std::vector<b2Body*> m_boxes;
    std::vector<Ramp> m_upperRamps; // left, right
    float m_binHalfWidth = 0.0f;
    float m_wallTop = 0.0f;
    SplitMix64 m_random;
    std::uint64_t m_steps = 0;
    std::uint64_t m_dropped = 0;
    std::uint32_t m_dropTurn = 0;
    std::uint32_t m_liveDuringStep = 0;
};

/// What one measured run gives. Times are per step, in milliseconds.
struct DebrisBenchResult
{
    std::uint32_t boxes = 0;
    std::uint32_t steps = 0;      ///< timed
    std::uint32_t warmup = 0;     ///< untimed steps before them
    double worldMsMedian = 0.0;   ///< world.Step (contactfx's contact listener inside it included)
    double effectsMsMedian = 0.0; ///< Effects::Step
    double effectsMsP99 = 0.0;    ///< nearest rank: the ceil(0.99 steps)-th smallest
    double effectsMsMax = 0.0;
    double effectsOverWorld = 0.0;  ///< sum of Effects::Step times / sum of world.Step times
    std::uint32_t liveMax = 0;      ///< most live particles at once (LiveDuringLastStep over the steps)
    std::uint32_t liveAfterMax = 0; ///< most live particles at the end of a step (Stats().liveMax)
    std::uint32_t capacity = 0;     ///< the particle budget
    /// Mean over the steps that moved particles of (that step's Effects::Step time in ns / the particles
    /// it moved, LiveDuringLastStep).
    double nsPerParticle = 0.0;
    std::uint32_t stepsFull = 0;     ///< steps whose emission found the pool full (recycled particles)
    std::uint64_t sparks = 0;        ///< particles emitted in all
    std::uint64_t dropped = 0;       ///< boxes put back at the top of a ramp
    std::uint32_t touchingAtEnd = 0; ///< boxes touching another box after the last step
};

/// Builds the scene with `boxes` boxes, steps it `warmup` times, then times `steps` steps, world.Step and
/// Effects::Step apart (the dropper is not timed).
DebrisBenchResult MeasureDebris(std::uint32_t boxes, std::uint32_t steps,
                                std::uint32_t warmup = kDebrisWarmup, std::uint64_t seed = 1);

} // namespace cfx::bench
