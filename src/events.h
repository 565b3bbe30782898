// contactfx internal: the one owner of effect events (contactfx/events.h): scrape state, event ids and
// the decisions began / changed / ended / impact.
//
// Why a module of its own: the decisions need state that lives across steps (the scrape going on per
// body pair, how long it has been quiet, where it was last heard) and one id counter shared by scrapes
// and impacts. Kept here, the contact tracker records only what Box2D reported and the emitter only
// measures; neither writes scrape state or makes an event.
//
// Where it sits in the step (Effects::Step):
//
//   ContactTracker ──> Emitter ──> ParticleSystem
//     │ EndedPairs      │ per body pair: its fastest new touch, asleep or its intensity and loudest point
//     └─────────────> EventTracker ──> the step's events (Effects::Events, the event listener)
//
// BeginStep starts the step's list with the scrapes of the pairs that lost their last contact since the
// last step (inside Box2D's callbacks, or by ForgetFixture), in the order they ended. Then the emitter
// calls, rule by rule, body pair by body pair in the order of each pair's first contact in tracking
// order: Impact (when the pair has a new touch), then Asleep or Scrape. Events are appended in exactly
// that order: the order events.h documents.
//
// Inputs are plain facts (fixtures in the rule's order, compared, never dereferenced; points, normals,
// speeds): the module calls no Box2D function, so its decisions can be driven without a world. Materials
// are read from the side table when an event is made (FixtureMaterials::Recorded, which never reads the
// fixture), except for pairs that ended, whose materials the tracker recorded as they left.
//
// Allocation: the per-slot states and the event list only grow; with room reserved for the configured
// number of body pairs, a warmed-up world makes events without touching the heap.
// Threading: the thread that steps the world.
#pragma once

#include "contact_tracker.h"
#include "contactfx/events.h"
#include "contactfx/particle_system.h"
#include "contactfx/rules.h"
#include "fixture_materials.h"

#include <box2d/b2_math.h>
#include <cstdint>
#include <span>
#include <vector>

class b2Fixture;

namespace cfx::detail
{

/// A contact of a body pair that began touching since the last step: the fastest such contact of the pair.
struct NewTouch
{
    RuleId rule;
    const b2Fixture* fixtureA = nullptr; ///< the rule's materialA fixture
    const b2Fixture* fixtureB = nullptr; ///< the rule's materialB fixture
    b2Vec2 point{0.0f, 0.0f};            ///< m, world: the manifold point that approached fastest
    b2Vec2 normal{0.0f, 0.0f};           ///< unit, from fixtureA's side toward fixtureB's
    float approachSpeed = 0.0f;          ///< m/s along the normal before the solver, finite, >= 0
};

/// A body pair's loudest sampled manifold point in one step (the highest intensity).
struct LoudestPoint
{
    const b2Fixture* fixtureA = nullptr; ///< the rule's materialA fixture of the point's contact
    const b2Fixture* fixtureB = nullptr; ///< the rule's materialB fixture
    b2Vec2 point{0.0f, 0.0f};            ///< m, world
    b2Vec2 normal{0.0f, 0.0f};           ///< unit, from fixtureA's side toward fixtureB's
    float tangentialSpeed = 0.0f;        ///< m/s, sliding speed at the point
};

/// What one awake body pair measured in one step.
struct PairMeasure
{
    RuleId rule;
    float intensity = 0.0f;     ///< the body pair's intensity (what drives emission), finite, >= 0
    float normalImpulse = 0.0f; ///< N*s, sum of the pair's PostSolve normal impulses this step, finite
    /// Its loudest point; null when no manifold point was sampled (the pair is then silent).
    const LoudestPoint* loudest = nullptr;
};

class EventTracker
{
public:
    /// `materials` must outlive the tracker. `pairs`: body pairs to make room for
    /// (EffectsConfig::ContactRoom); `hitGroups`: particle hit groups a step reports at most
    /// (budget.particleHits).
    EventTracker(const FixtureMaterials& materials, std::size_t pairs, std::uint32_t hitGroups = 0);

    /// Starts the step numbered `step` (ContactTracker::Step) lasting `dt` s (> 0): clears the last
    /// step's events, then each pair in `ended` (ContactTracker::EndedPairs, in that order) ends its
    /// scrape, if one is going on, with the pair's reason (EndedPair::reason) and the last contact's fixtures
    /// and materials, and its slot is cleared for the next pair that takes it.
    void BeginStep(std::uint64_t step, float dt, std::span<const EndedPair> ended);

    /// A body pair's fastest new touch this step: an impact, with a fresh id, when its approach speed
    /// reaches `rule.impactThreshold`. `normalImpulse`: N*s, the pair's sum this step. Returns whether
    /// it was an impact (then the emitter bursts).
    bool Impact(const RuleDef& rule, const NewTouch& touch, float normalImpulse);

    /// A body of the pair in `slot` sleeps: its scrape, if one is going on, ends as `asleep`.
    void Asleep(std::uint32_t slot);

    /// The awake pair in `slot` measured `measure`: intensity above `rule.threshold` begins its scrape
    /// (fresh id) or changes it; at or below, a scrape going on changes until it has been quiet for
    /// `rule.scrapeEndDelay`, then ends as `belowThreshold`. Each report names the loudest point, or the
    /// one last reported when none was sampled.
    void Scrape(const RuleDef& rule, std::uint32_t slot, const PairMeasure& measure);

    /// Appends a particleHits event per group, in order (after the step's contact events).
    void ParticleHits(std::span<const ParticleHitGroup> groups);
    /// What EndAll keeps of the events made so far.
    enum class Keep : std::uint8_t
    {
        none,   ///< the events become the scrape ends
        events, ///< the scrape ends follow them (EndScrapes called by the event listener)
    };
    /// Ends every open scrape with `reason`: one scrapeEnded per open scrape, in id order (stamped with the
    /// last step), after the events `keep` keeps. Allocation-free.
    void EndAll(ScrapeEnd reason, Keep keep);

    /// The world's origin moved to `newOrigin` (b2World::ShiftOrigin): the points the open scrapes last
    /// reported move by -newOrigin. The events already made stay as they were reported.
    void ShiftOrigin(b2Vec2 newOrigin);

    /// The events of this step so far, in order. Valid until the next BeginStep.
    std::span<const EffectEvent> Events() const { return m_events; }
    /// The id of the scrape going on in `slot`, 0 when none.
    std::uint32_t ScrapeId(std::uint32_t slot) const
    {
        return slot < m_scrapes.size() ? m_scrapes[slot].id : 0;
    }

private:
    // One body pair's scrape; a slot's state is cleared when its pair ends.
    struct ScrapeState
    {
        RuleId rule;
        std::uint32_t id = 0;                // the scrape going on, 0 when none
        float quietTime = 0.0f;              // s at or below the threshold
        b2Vec2 point{0.0f, 0.0f};            // m, world: where it was last reported
        b2Vec2 normal{0.0f, 0.0f};           // unit, rule's A toward B, as last reported
        const b2Fixture* fixtureA = nullptr; // the fixtures of the point last reported
        const b2Fixture* fixtureB = nullptr;
    };

    ScrapeState& StateOf(std::uint32_t slot);
    // An event of `type` naming the rule's two fixtures, their materials as recorded now, and this step.
    EffectEvent Named(EffectEventType type, RuleId rule, const b2Fixture* fixtureA,
                      const b2Fixture* fixtureB) const;
    // Appends the ended event of `scrape` (id != 0), named by the two fixtures, and clears its id and
    // quiet time; returns the event appended.
    EffectEvent& End(ScrapeState& scrape, ScrapeEnd reason, const b2Fixture* fixtureA,
                     const b2Fixture* fixtureB);

    const FixtureMaterials& m_materials;
    std::vector<ScrapeState> m_scrapes; // by pair slot (ContactTracker's)
    std::vector<EffectEvent> m_events;
    std::uint32_t m_nextId = 1; // scrapes and impacts: never 0, never reused
    std::uint64_t m_step = 0;
    float m_dt = 0.0f;
};

} // namespace cfx::detail
