// contactfx: effect events for sound and gameplay.
//
// The same contact analysis that drives the particles, as events read after each step (like Box2D v3's
// event arrays), with an optional callback. A scrape is one body pair (all touching contacts of a rule
// between the same two bodies, however many fixtures or chain segments they span) rubbing above its
// rule's threshold: it begins, changes every step with its intensity, and always ends (the pair's last
// contact ended, a body fell asleep, intensity at or below the threshold for the rule's scrapeEndDelay,
// the last fixture or body destroyed), so a looping sound that follows its id always stops. An impact is
// a new touch (a manifold point new since its contact's last enabled PreSolve, approaching faster than
// 1 mm/s: a first touch, or a box's second corner coming down) whose approach speed along the normal, taken
// before the solver removes it, reaches the rule's impactThreshold; a contact the application disables in
// PreSolve has not touched. A body pair reports at most one per step (its fastest new touch). Particle hits
// are the step's pool particles that hit a body, one event per particle type and body (dirt pattering on
// the ground, sparks ticking on steel): ParticleSystem::Hits as events, with no rule.
//
// Order within a step, the same for the same inputs: first the scrapes that ended inside Box2D's
// callbacks since the last step (in callback order), then rule by rule, body pair by body pair in the
// order of each pair's first contact in tracking order: the pair's impact, then its scrape event; last, after
// the particle step, the particle hits, one per group of ParticleSystem::Hits in its order (the order the
// groups first appear among the particles, oldest particle first; at most budget.particleHits).
#pragma once

#include "contactfx/materials.h"

#include <box2d/b2_math.h>
#include <cstdint>

class b2Body;
class b2Fixture;

namespace cfx
{

enum class EffectEventType : std::uint8_t
{
    scrapeBegan,
    scrapeChanged,
    scrapeEnded,
    impact,
    particleHits, ///< pool particles of one type that hit one body in the step
};

/// Why a scrape ended.
enum class ScrapeEnd : std::uint8_t
{
    none,           ///< not a scrapeEnded event
    contactEnded,   ///< the fixtures stopped touching (or one became a sensor)
    asleep,         ///< a body fell asleep
    belowThreshold, ///< intensity at or below the threshold for scrapeEndDelay
    destroyed,      ///< a fixture or body was destroyed
    stopped,        ///< the application ended it: Effects::EndScrapes (it stops stepping)
    /// A fixture of it was given another material (Effects::SetMaterial); if the contact goes on, a new
    /// scrape begins under the rule the new materials select.
    materialChanged,
};

/// One event. Fields that do not apply to a type are zero (invalid ids for a particle hit's rule and
/// materials).
struct EffectEvent
{
    EffectEventType type = EffectEventType::scrapeBegan;
    ScrapeEnd end = ScrapeEnd::none;
    RuleId rule;
    MaterialId materialA; ///< the rule's materialA
    MaterialId materialB; ///< the rule's materialB
    /// The fixtures with materialA and materialB (scrapes: of the contact whose point is reported; an
    /// ended scrape: as last reported, or of the pair's last contact when it ended). After a `destroyed`
    /// end they are the addresses the destroyed fixtures had: compare, never dereference. (So they are after
    /// any end of a fixture destroyed without Effects::ForgetFixture: contactfx cannot know it is gone.)
    const b2Fixture* fixtureA = nullptr;
    const b2Fixture* fixtureB = nullptr;
    /// Scrape events: the scrape's id, the same from began to ended, never reused by this Effects (a new
    /// Effects counts from 1 again). Impacts: an id of
    /// their own from the same counter. Particle hits: 0.
    std::uint32_t id = 0;
    std::uint64_t step = 0; ///< Effects step counter when the event was made (first step: 0)
    /// m, world: the body pair's manifold point with the highest intensity (scrapes; where it was last
    /// reported for an ended scrape) or approach speed (impacts); particle hits: the mean of the points
    /// where the particles touched the body
    b2Vec2 point{0.0f, 0.0f};
    b2Vec2 normal{0.0f, 0.0f};    ///< unit, from fixtureA's side toward fixtureB's
    float intensity = 0.0f;       ///< scrapes: the body pair's intensity this step (what drives emission)
    float tangentialSpeed = 0.0f; ///< m/s, scrapes: sliding speed at that point
    float normalImpulse = 0.0f;   ///< N*s: sum of the body pair's PostSolve normal impulses this step
    /// m/s, impacts: approach speed along the normal before the solver; particle hits: the particles' mean
    float approachSpeed = 0.0f;
    /// Particle hits: the body hit. Valid during the step that reported it; afterwards compare it, never
    /// dereference it (it may have been destroyed).
    const b2Body* body = nullptr;
    ParticleTypeId particleType; ///< particle hits: the particles' type
    std::uint32_t count = 0;     ///< particle hits: how many particles hit (>= 1)
};

/// Receives every event of a step, in order, at the end of Effects::Step, on the thread that called Step;
/// `event` is valid during the call. It may read the world but must not step it or destroy bodies, nor step
/// the Effects (that throws InputError, field "listener"). It may call Effects::EndScrapes: the scrape ends
/// then follow the step's events, in Events() too, and it hears them after the rest, each event once. It may
/// replace or remove itself (Effects::SetEventListener): the new listener, or none, has the events after the
/// current one. It may destroy the Effects (a level torn down on an event): it then hears no more events of
/// the step, and Effects::Step (or EndScrapes) returns without touching the destroyed Effects.
class EffectEventListener
{
public:
    virtual ~EffectEventListener() = default;
    virtual void OnEffectEvent(const EffectEvent& event) = 0;
};

} // namespace cfx
