#include "contactfx/effects.h"

#include "contact_tracker.h"
#include "contactfx/error.h"
#include "effects_access.h"
#include "emitter.h"
#include "events.h"
#include "fixture_materials.h"
#include "nearest_name.h"
#include "particle_system_access.h"
#include "quoted_text.h"
#include "step_check.h"
#include "vector_text.h"

#include <algorithm>
#include <atomic>
#include <box2d/b2_body.h>
#include <box2d/b2_fixture.h>
#include <box2d/b2_world.h>
#include <mutex>
#include <thread>

namespace cfx
{

namespace
{

const EffectsConfig& Checked(const EffectsConfig& config)
{
    std::vector<Diagnostic> problems = Validate(config);
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }
    return config;
}

// The worlds that have an Effects object now, so that a second one on the same world is refused (it would
// take the first one's listeners, and destroying them in the wrong order would leave Box2D calling a
// destroyed tracker). Effects on different worlds may live on different threads: guarded by a mutex.
class WorldClaim
{
public:
    explicit WorldClaim(const b2World& world) : m_world(&world)
    {
        const std::lock_guard<std::mutex> lock(Mutex());
        std::vector<const b2World*>& claimed = Claimed();
        if (std::find(claimed.begin(), claimed.end(), m_world) != claimed.end())
        {
            throw InputError("<api>", "world",
                             "this b2World already has an Effects object: one Effects per world at a time "
                             "(destroy the old one before creating its replacement)");
        }
        claimed.push_back(m_world);
    }
    ~WorldClaim()
    {
        const std::lock_guard<std::mutex> lock(Mutex());
        std::vector<const b2World*>& claimed = Claimed();
        claimed.erase(std::find(claimed.begin(), claimed.end(), m_world));
    }
    WorldClaim(const WorldClaim&) = delete;
    WorldClaim& operator=(const WorldClaim&) = delete;

private:
    static std::mutex& Mutex()
    {
        static std::mutex mutex;
        return mutex;
    }
    static std::vector<const b2World*>& Claimed()
    {
        static std::vector<const b2World*> claimed;
        return claimed;
    }

    const b2World* m_world;
};

// A static fixture that goes (destroyed, or about to be with ForgetFixture) changes the particles' static
// geometry: said to the cache, so that even with ParticleSystemOptions::watchStaticGeometry false no
// particle meets it, nor names its body in a hit, after the step it went in.
void InvalidateIfStatic(ParticleSystem& particles, const b2Fixture& fixture)
{
    if (fixture.GetBody()->GetType() == b2_staticBody)
    {
        particles.InvalidateStaticGeometry();
    }
}

// Forgets fixtures destroyed with their body, and the bodies of body-backed particles the application
// destroyed (so the particle system never destroys them again), then forwards to the application's
// listener.
class Destruction final : public b2DestructionListener
{
public:
    Destruction(FixtureMaterials& materials, ContactTracker& tracker, ParticleSystem& particles,
                b2DestructionListener* application)
        : m_materials(materials), m_tracker(tracker), m_particles(particles), forward(application)
    {
    }

    void SayGoodbye(b2Joint* joint) override
    {
        if (forward != nullptr)
        {
            forward->SayGoodbye(joint);
        }
    }

    void SayGoodbye(b2Fixture* fixture) override
    {
        // Box2D ended the fixture's contacts just before: their scrapes ended by destruction.
        m_tracker.MarkDestroyed(fixture);
        m_materials.Erase(fixture);
        if (forward != nullptr)
        {
            forward->SayGoodbye(fixture); // before ForgetBody: to IsParticleBody it is still a particle's
        }
        m_particles.ForgetBody(fixture->GetBody()); // nothing unless it is a particle's body
        InvalidateIfStatic(m_particles, *fixture);
    }

private:
    FixtureMaterials& m_materials;
    ContactTracker& m_tracker;
    ParticleSystem& m_particles;

public:
    b2DestructionListener* forward;
};

// Box2D's do-nothing contact listener, the one every world starts with (b2ContactManager's constructor
// sets it; libbox2d does not export it): a world whose listener is this one has none of the application's.
const b2ContactListener* BoxDefaultContactListener()
{
    static const b2ContactManager probe;
    return probe.m_contactListener;
}

} // namespace

// What Effects keeps out of its public header. Members are declared in the order they depend on each
// other: the claim on the world comes first (a second Effects throws before anything else), the tracker
// and the event tracker read the materials, the destruction listener edits the materials, the tracker
// and the particle system.
struct Effects::Internals
{
    Internals(b2World& world, const RuleTable& rules, const EffectsConfig& config, const EffectsDef& def,
              ParticleSystem& particles)
        : claim(world), tracker(rules, materials),
          destruction(materials, tracker, particles, def.destructionListener),
          emitter(config, def.seed, def.particles.checkParticles),
          events(materials, config.ContactRoom(), config.budget.particleHits)
    {
        // A listener the application set on the world before is kept and forwarded to, as one given here.
        b2ContactListener* worldListener = world.GetContactManager().m_contactListener;
        b2ContactListener* worldOwn = worldListener == BoxDefaultContactListener() ? nullptr : worldListener;
        tracker.SetForward(def.contactListener != nullptr ? def.contactListener : worldOwn);
        tracker.Reserve(config.budget.contacts, config.ContactRoom());
    }

    WorldClaim claim;
    // While the event listener is handed this step's events: the delivery's flag that the destructor sets
    // (the listener may destroy the Effects); null otherwise.
    bool* notifying = nullptr;
    // While the destructor destroys the particle bodies (the application's destruction listener may call
    // in): Step does nothing then.
    bool destroying = false;
    // The thread in Step or EndScrapes (none: the default id); see Hold.
    std::atomic<std::thread::id> stepping;
    FixtureMaterials materials;
    ContactTracker tracker;
    Destruction destruction;
    detail::Emitter emitter;
    detail::EventTracker events;
};

namespace
{

// Internals::stepping for one call of Step or EndScrapes: taken for this thread, or found taken by this
// thread already (a listener called inside a Step). Held by another thread, it throws InputError (field
// "thread"): an Effects is used by one thread at a time. Let go when the call ends, unless handed over to
// NotifyListener (whose listener may destroy the Effects).
class Hold
{
public:
    Hold(std::atomic<std::thread::id>& stepping, const char* call) : m_stepping(stepping)
    {
        const std::thread::id self = std::this_thread::get_id();
        std::thread::id idle;
        m_taken = stepping.compare_exchange_strong(idle, self);
        if (!m_taken && idle != self)
        {
            throw InputError(
                "<api>", "thread",
                std::string(call) +
                    " called on one thread while another thread steps the same Effects: an Effects "
                    "is stepped by one thread at a time");
        }
    }
    ~Hold()
    {
        if (m_taken && !m_handedOver)
        {
            m_stepping.store(std::thread::id());
        }
    }
    Hold(const Hold&) = delete;
    Hold& operator=(const Hold&) = delete;

    bool Taken() const { return m_taken; }
    void HandOver() { m_handedOver = true; }

private:
    std::atomic<std::thread::id>& m_stepping;
    bool m_taken = false;
    bool m_handedOver = false;
};

} // namespace

Effects::Effects(b2World& world, const EffectsDef& def)
    : m_world(world), m_config(Checked(def.config)), m_rules(BuildRuleTable(m_config)),
      m_particles(world, m_config.particleTypes, m_config.budget, def.particles),
      m_internals(std::make_unique<Internals>(world, m_rules, m_config, def, m_particles)),
      m_eventListener(def.eventListener)
{
    m_stats.spawnedByType.assign(m_config.particleTypes.size(), 0);
    m_stats.rules.assign(m_config.rules.size(), RuleStats{});
    m_world.SetContactListener(&m_internals->tracker);
    m_world.SetDestructionListener(&m_internals->destruction);
}

Effects::~Effects()
{
    if (m_internals->notifying != nullptr)
    {
        *m_internals->notifying = true; // destroyed by the event listener: the delivery stops at once
    }
    // The particle bodies go first, while this object is whole: the application's destruction listener
    // hears of their fixtures through it, as in a step, and may still call into it (a trial's listener
    // calling ForgetFixture read freed memory when they went after).
    m_internals->destroying = true;
    detail::ParticleSystemAccess::DestroyAllBodies(m_particles);
    // The application's listeners as they are now (one set on the world before Effects is forwarded to
    // until replaced; none: Box2D's own, also after SetContactListener(nullptr)).
    b2ContactListener* forward = m_internals->tracker.Forward();
    m_world.SetContactListener(
        forward != nullptr ? forward : const_cast<b2ContactListener*>(BoxDefaultContactListener()));
    m_world.SetDestructionListener(m_internals->destruction.forward);
}

void Effects::CheckMaterialArguments(const void* target, const char* targetField, MaterialId material) const
{
    if (target == nullptr)
    {
        throw InputError("<api>", targetField, "null");
    }
    if (material.IsValid() && material.index >= m_config.materials.size())
    {
        throw InputError(
            "<api>", "material",
            "index " + std::to_string(material.index) + " names no material of this config (it has " +
                std::to_string(m_config.materials.size()) + "; MaterialId{} removes a material)");
    }
}

void Effects::SetMaterial(b2Fixture* fixture, MaterialId material)
{
    CheckMaterialArguments(fixture, "fixture", material);
    if (m_internals->materials.Get(fixture) != material)
    {
        m_internals->tracker.EndContactsOf(fixture, ScrapeEnd::materialChanged); // read the old materials
        m_internals->materials.Set(fixture, material);
    }
}

MaterialId Effects::RequireMaterial(std::string_view name) const
{
    const MaterialId material = m_config.FindMaterial(name);
    if (!material.IsValid())
    {
        detail::SuggestionBudget budget;
        throw InputError("<api>", "material",
                         "unknown material " + detail::QuotedText(name) +
                             detail::DidYouMean(name, m_config.materials, budget) +
                             " (materials: " + detail::NameList(m_config.materials, "none") + ")");
    }
    return material;
}

std::string_view Effects::NameText(const char* name)
{
    if (name == nullptr)
    {
        throw InputError("<api>", "material", "null (a material's name was expected)");
    }
    return name;
}

void Effects::SetMaterialNamed(b2Fixture* fixture, std::string_view material)
{
    CheckMaterialArguments(fixture, "fixture", MaterialId{});
    SetMaterial(fixture, RequireMaterial(material));
}

void Effects::SetMaterialNamed(b2Body* body, std::string_view material)
{
    CheckMaterialArguments(body, "body", MaterialId{});
    SetMaterial(body, RequireMaterial(material));
}

MaterialId Effects::Material(const b2Fixture* fixture) const
{
    return m_internals->materials.Get(fixture);
}

void Effects::SetContactListener(b2ContactListener* listener)
{
    m_internals->tracker.SetForward(listener);
}

void Effects::SetMaterial(b2Body* body, MaterialId material)
{
    CheckMaterialArguments(body, "body", material);
    for (b2Fixture* fixture = body->GetFixtureList(); fixture != nullptr; fixture = fixture->GetNext())
    {
        SetMaterial(fixture, material);
    }
}

void Effects::ForgetFixture(b2Fixture* fixture)
{
    CheckMaterialArguments(fixture, "fixture", MaterialId{});
    m_internals->tracker.ForgetFixture(fixture);
    m_internals->materials.Erase(fixture);
    InvalidateIfStatic(m_particles, *fixture);
}

void Effects::SetDestructionListener(b2DestructionListener* listener)
{
    m_internals->destruction.forward = listener;
}

void Effects::Step(float dt)
{
    if (m_internals->destroying)
    {
        return; // called by the application's destruction listener from the destructor: no step to take
    }
    // One Step at a time: two threads stepping one Effects at once deadlocked its helper threads (or raced
    // with one thread), and a listener stepping it from inside a Step would hand on the events of the step
    // that called it while the next one replaced them.
    Hold hold(m_internals->stepping, "Effects::Step");
    if (!hold.Taken())
    {
        throw InputError("<api>", "listener",
                         m_internals->notifying != nullptr
                             ? "Effects::Step called from the event listener: it is handing on the events of "
                               "the step that called it"
                             : "Effects::Step called from a listener during a Step of the same Effects");
    }
    if (m_world.IsLocked())
    {
        throw InputError("<api>", "listener",
                         "Effects::Step called inside b2World::Step (from a contact listener): call it after "
                         "b2World::Step returns");
    }
    // Checked before anything changes (the particle system checks again, for its own users).
    detail::CheckStepTime(dt);
    if (!m_world.GetGravity().IsValid())
    {
        throw InputError("<api>", "gravity",
                         "expected the world's gravity to be finite, found " +
                             detail::VectorText(m_world.GetGravity()));
    }
    ContactTracker& tracker = m_internals->tracker;
    detail::EventTracker& events = m_internals->events;
    tracker.Prune();
    events.BeginStep(tracker.Step(), dt, tracker.EndedPairs());
    {
        // The emission reads the tracker's contact lists, so the bodies of the particles its spawns
        // recycle are destroyed after it (destroying a body ends its contacts).
        struct RecycledBodies
        {
            ParticleSystem& particles;
            ~RecycledBodies() { detail::ParticleSystemAccess::DestroyDeferredBodies(particles); }
        } recycled{m_particles};
        detail::ParticleSystemAccess::DeferBodyDestruction(m_particles);
        detail::ParticleSystemAccess::SpawnAfterWorldStep(m_particles);
        m_internals->emitter.Emit(m_world, m_config, tracker, events, m_particles, m_stats, dt);
        // Everything recorded has been read. A contact that ends from here on (the recycled bodies, and
        // the particle step's) is reported in the next step.
        tracker.EndStep();
    }
    m_particles.Step(dt, m_world.GetGravity());
    events.ParticleHits(m_particles.Hits());
    m_stats.steps += 1;
    m_stats.time += static_cast<double>(dt);
    m_stats.live = m_particles.Count();
    m_stats.liveMax = std::max(m_stats.liveMax, m_stats.live);
    m_stats.recycled = m_particles.Recycled();
    m_stats.crushed = m_particles.Counters().crushed;
    m_stats.particleStepsInside = m_particles.Counters().stepsInside;
    m_stats.crossings = m_particles.Counters().crossings;
    m_stats.passedThroughMoving = m_particles.Counters().passedThroughMoving;
    m_stats.nonFinite = m_particles.Counters().nonFinite;
    m_stats.skippedBodies = m_particles.Counters().skippedBodies;
    m_stats.droppedHitGroups = m_particles.Counters().droppedHitGroups;
    m_stats.staticGeometryBuilds = m_particles.StaticGeometryBuilds();
    m_stats.staleMaterials = m_internals->materials.Stale();
    hold.HandOver();
    NotifyListener();
}

bool Effects::ClearParticles()
{
    if (!m_particles.Clear())
    {
        return false;
    }
    m_stats.live = 0;
    return true;
}

bool Effects::BuildStaticGeometry()
{
    const bool built = m_particles.BuildStaticGeometry();
    m_stats.staticGeometryBuilds = m_particles.StaticGeometryBuilds();
    return built;
}

void Effects::ShiftOrigin(b2Vec2 newOrigin)
{
    m_particles.ShiftOrigin(newOrigin); // checks newOrigin first
    m_internals->tracker.ShiftOrigin(newOrigin);
    m_internals->events.ShiftOrigin(newOrigin);
}

void Effects::EndScrapes()
{
    Hold hold(m_internals->stepping, "Effects::EndScrapes");
    if (!hold.Taken())
    {
        // Called by a listener during a Step (or its delivery of events) on this thread: the scrape ends
        // follow the step's events, which the delivery then hands on too (each event once).
        m_internals->events.EndAll(ScrapeEnd::stopped, detail::EventTracker::Keep::events);
        return;
    }
    m_internals->events.EndAll(ScrapeEnd::stopped, detail::EventTracker::Keep::none);
    hold.HandOver();
    NotifyListener();
}

void Effects::NotifyListener()
{
    // The listener may destroy this Effects (a level torn down on an event): the destructor sets
    // `destroyed`, and the delivery then returns without touching what was freed. Otherwise it ends the
    // hold of the Step or EndScrapes that called it (Hold::HandOver).
    bool destroyed = false;
    struct Delivery
    {
        bool& destroyed;
        bool*& notifying;
        std::atomic<std::thread::id>& stepping;
        ~Delivery()
        {
            if (!destroyed)
            {
                notifying = nullptr;
                stepping.store(std::thread::id());
            }
        }
    } delivery{destroyed, m_internals->notifying, m_internals->stepping};
    if (m_eventListener == nullptr)
    {
        return;
    }
    m_internals->notifying = &destroyed;
    // By index, each event copied: the listener may end the scrapes (EndScrapes), which appends to the
    // events and may move them; and it may replace or remove itself (SetEventListener), which takes effect
    // from the next event.
    for (std::size_t i = 0; i < m_internals->events.Events().size() && m_eventListener != nullptr; ++i)
    {
        const EffectEvent event = m_internals->events.Events()[i];
        m_eventListener->OnEffectEvent(event);
        if (destroyed)
        {
            return;
        }
    }
}

std::span<const EffectEvent> Effects::Events() const
{
    return m_internals->events.Events();
}

namespace detail
{

const ContactTracker& EffectsAccess::Tracker(const Effects& effects)
{
    return effects.m_internals->tracker;
}

} // namespace detail

} // namespace cfx
