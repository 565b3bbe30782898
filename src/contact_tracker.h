// contactfx: which contacts may make effects right now.
//
// The tracker is the b2ContactListener that Effects installs on the world. For each rule it keeps the
// touching contacts whose two fixtures' materials select that rule, in a dense array (insertion order,
// swap-remove), plus the PostSolve normal impulses of each manifold point and, for a new touch, the
// approach speed before the solver. A new touch is a manifold point that was not in the contact's manifold
// at its last enabled PreSolve: the first touch, a second corner coming down onto the same fixture (which a
// chain would report as a new contact on the next segment), or the first step a contact the application
// disabled is let through (a disabled contact has not touched: a one-way platform passed from below).
// Callbacks only record what Box2D reported: the world is locked while they run. Every callback is forwarded,
// unchanged, to the application's own listener when it has one, after contactfx has recorded it. The tracker
// makes no effect and no event: the emitter (particles) and the event tracker (src/events.h: scrapes,
// impacts, their ids) read what it recorded after the step.
//
// Contacts of one rule between the same two bodies form one body pair (TrackedPair): one sliding contact
// however many fixtures, chain segments or manifold points it spans. Whatever must survive a contact
// moving from one segment to the next (the fraction of a particle owed, the scrape going on) is kept per
// pair slot by the module that owns it. A pair lives while at least one of its contacts is tracked; a
// contact finds its pair when tracking begins by walking the shorter of its two bodies' Box2D contact
// lists for another tracked contact of the same rule between the same bodies (no map keyed by addresses,
// nothing iterated in address order). Pair slots are reused from a free list, in an order fixed by
// Box2D's callback order.
//
// A contact leaves tracking when it ends (EndContact: also sent by Box2D when a fixture or body is
// destroyed, a body disabled, or a filter change stops the pair from colliding) and when one of its
// fixtures becomes a sensor (found by Prune() after the step; PreSolve brings it back if the fixture
// becomes solid again while still touching). Nothing dangles: a tracked b2Contact* is always alive.
// When the last contact of a pair that an Effects step has seen leaves, the pair goes into EndedPairs()
// with that contact's fixtures: the modules that keep state per pair slot learn there that the slot's
// pair is gone (a pair that began and ended between two steps was never seen, so nobody holds state
// for it). A pair whose last contact stops touching is only held for ending until the step reads it
// (Prune): Box2D may report that end before the next contact of the same two bodies begins in the same
// world step (a circle rolling from one chain segment onto the next, in one direction of the chain), and a
// contact of the same rule between the same bodies that begins meanwhile takes the pair back, its slot and
// everything kept for it (the scrape goes on).
//
// Threading: Box2D 2.4 calls listeners on the thread running b2World::Step; use from that thread only.
#pragma once

#include "contactfx/config.h"
#include "contactfx/events.h"
#include "contactfx/rules.h"
#include "fixture_materials.h"
#include "pointer_map.h"

#include <box2d/b2_math.h>
#include <box2d/b2_world_callbacks.h>
#include <cstdint>
#include <span>
#include <vector>

class b2Contact;

namespace cfx
{

/// The rule table a config describes: rule i for the pair of its two materials (the config must be valid).
RuleTable BuildRuleTable(const EffectsConfig& config);

/// A touching contact that a rule watches.
struct TrackedContact
{
    b2Contact* contact = nullptr;
    RuleId rule;
    bool swapped = false;        ///< fixture A carries the rule's materialB (so A and B are swapped)
    std::uint32_t pair = 0;      ///< slot of its body pair (ContactTracker::Pair)
    float normalImpulse[2] = {}; ///< N*s, largest PostSolve normal impulse per manifold point this step

    // New touches (manifold points new since the last enabled PreSolve, see the file comment), the stuff
    // of impacts (events.h).
    bool newTouch = false;             ///< a point began touching since the last EndStep, approach recorded
    bool disabled = true;              ///< not enabled at its last PreSolve (or none yet): every point is new
    float approachSpeed = 0.0f;        ///< m/s along the normal in PreSolve, before the solver, >= 0
    b2Vec2 approachPoint{0.0f, 0.0f};  ///< m, world: the new point approaching fastest
    b2Vec2 approachNormal{0.0f, 0.0f}; ///< unit, from the contact's fixture A to fixture B
};

/// The tracked contacts of one rule between the same two bodies: one sliding contact, whatever the
/// tessellation. Lives while `contacts` > 0.
struct TrackedPair
{
    RuleId rule;
    std::uint32_t contacts = 0;  ///< tracked contacts that belong to it; 0: a free slot
    std::uint64_t beganStep = 0; ///< value of the step counter when its first contact was tracked
};

/// A body pair that lost its last contact since the last EndStep, after an Effects step had seen it
/// (ContactTracker::EndedPairs).
struct EndedPair
{
    std::uint32_t slot = 0; ///< its pair slot, free now (perhaps already reused by a newer pair)
    /// Why: contactEnded (the fixtures stopped touching or one became a sensor), destroyed (the fixture
    /// or body of its last contact: ForgetFixture, or Box2D's destruction listener through MarkDestroyed)
    /// or materialChanged (EndContactsOf).
    ScrapeEnd reason = ScrapeEnd::contactEnded;
    /// The last contact's fixtures in the rule's order (materialA's first) and their materials as
    /// recorded when it left. The fixtures may have been destroyed since: compare, never dereference.
    const b2Fixture* fixtureA = nullptr;
    const b2Fixture* fixtureB = nullptr;
    MaterialId materialA;
    MaterialId materialB;
};

class ContactTracker final : public b2ContactListener
{
public:
    /// `rules` and `materials` must outlive the tracker.
    ContactTracker(const RuleTable& rules, const FixtureMaterials& materials);
    /// Makes room for `perRule` touching contacts of each rule, `total` of all rules together, and as
    /// many body pairs and ended pairs: up to that many, tracking allocates nothing.
    void Reserve(std::uint32_t perRule, std::size_t total);

    /// The application's listener, forwarded every callback; may be null.
    void SetForward(b2ContactListener* listener) { m_forward = listener; }
    b2ContactListener* Forward() const { return m_forward; }

    /// The world's origin moved to `newOrigin` (b2World::ShiftOrigin): the recorded approach points move
    /// by -newOrigin.
    void ShiftOrigin(b2Vec2 newOrigin);

    /// Touching contacts of one rule, in a stable, deterministic order.
    std::span<TrackedContact> Contacts(RuleId rule) { return m_byRule[rule.index]; }
    std::span<const TrackedContact> Contacts(RuleId rule) const { return m_byRule[rule.index]; }
    int RuleCount() const { return static_cast<int>(m_byRule.size()); }
    std::size_t TrackedCount() const { return m_index.Size(); }

    /// After b2World::Step: drops contacts that became sensors or stopped touching without EndContact,
    /// then ends the pairs that lost their last contact and did not get one back (EndedPairs).
    void Prune();
    /// Once the step has read what was recorded (after emission), before the next b2World::Step: zeroes
    /// the recorded impulses, forgets new touches and ended pairs, and advances the step counter. Pairs
    /// tracked before it count as seen by a step.
    void EndStep();

    /// Whether Box2D called PreSolve since the last EndStep: a world step solved a touching contact
    /// of awake bodies. False after no world step, and after one where no awake body touched anything.
    bool Solved() const { return m_solved; }
    /// Whether a tracked contact has an awake body that is not static: one Box2D's next step solves.
    bool AnyAwake() const;
    /// Drops every contact that involves `fixture` (before it is destroyed by the application); pairs
    /// that end with them are marked destroyed.
    void ForgetFixture(const b2Fixture* fixture) { EndContactsOf(fixture, ScrapeEnd::destroyed); }
    /// Drops every contact that involves `fixture`; pairs that end with them end for `reason`. Contacts
    /// still touching are tracked again by the next PreSolve, under the rule their materials then select
    /// (Effects::SetMaterial, reason materialChanged).
    void EndContactsOf(const b2Fixture* fixture, ScrapeEnd reason);
    /// After Box2D destroyed `fixture` (b2DestructionListener): pairs that ended with its contacts are
    /// marked destroyed.
    void MarkDestroyed(const b2Fixture* fixture);

    /// Pairs an Effects step had seen that ended since the last EndStep, in the order they ended. A slot
    /// appears at most once: a pair that takes a freed slot is seen only by a later step.
    std::span<const EndedPair> EndedPairs() const { return m_endedPairs; }
    /// The body pair in `slot` (TrackedContact::pair).
    const TrackedPair& Pair(std::uint32_t slot) const { return m_pairs[slot]; }
    /// Number of pair slots, used and free: every TrackedContact::pair is below it.
    std::size_t PairSlots() const { return m_pairs.size(); }
    /// Pairs with at least one tracked contact.
    std::size_t PairCount() const { return m_pairs.size() - m_freePairs.size(); }
    /// The step counter: Effects steps completed.
    std::uint64_t Step() const { return m_step; }
    /// The fixtures of a tracked contact in the rule's order (materialA's first).
    const b2Fixture* RuleFixtureA(const TrackedContact& tracked) const;
    const b2Fixture* RuleFixtureB(const TrackedContact& tracked) const;

    // b2ContactListener: record, then forward.
    void BeginContact(b2Contact* contact) override;
    void EndContact(b2Contact* contact) override;
    void PreSolve(b2Contact* contact, const b2Manifold* oldManifold) override;
    void PostSolve(b2Contact* contact, const b2ContactImpulse* impulse) override;

private:
    /// The contact's tracking, or null when it is not tracked.
    TrackedContact* Tracked(const b2Contact* contact);
    /// The contact's tracking, begun now if it is solid and its materials select a rule; else null.
    TrackedContact* Track(b2Contact* contact);
    void Untrack(b2Contact* contact, ScrapeEnd reason);
    /// After the application's PreSolve: notes the contact's new touches (see the file comment).
    void NoteTouches(b2Contact* contact, const b2Manifold& oldManifold, TrackedContact& tracked);
    std::uint32_t FindOrAddPair(b2Contact* contact, RuleId rule);

    const RuleTable& m_rules;
    const FixtureMaterials& m_materials;
    b2ContactListener* m_forward = nullptr;
    std::vector<std::vector<TrackedContact>> m_byRule;
    detail::PointerMap m_index;             // contact -> (rule << 32) | slot
    std::vector<TrackedPair> m_pairs;       // by slot; slots with contacts == 0 are free
    std::vector<std::uint32_t> m_freePairs; // free slots, reused last freed first
    std::vector<EndedPair> m_endedPairs;
    // A seen pair whose last contact stopped touching since the last Prune: ended there unless a contact of
    // the same rule between the same bodies takes it back first.
    struct EndingPair
    {
        EndedPair ended;
        const b2Body* bodyA = nullptr;
        const b2Body* bodyB = nullptr;
    };
    std::vector<EndingPair> m_endingPairs; // in the order their last contacts left
    std::uint64_t m_step = 0;
    bool m_solved = false; // PreSolve was called since the last EndStep
};

} // namespace cfx
