// contactfx: everything for one b2World behind one object.
//
//     b2World world(gravity);                    // the application's world
//     cfx::Effects fx(world, cfx::EffectsDef{cfx::DefaultPreset()}); // installs its contact listener
//     fx.SetMaterial(tyreFixture, "rubber");
//     for (;;) { world.Step(dt, 8, 3); fx.Step(dt); draw(fx.Particles()); }
//
// Data flows one way, once per step: Box2D's callbacks record touching contacts and impulses
// (ContactTracker) while the world steps; Effects::Step then turns the manifold points of each body pair
// (the tracked contacts of a rule between two bodies) into an intensity, emits particles at a rate that
// grows with it, finds where they start (never inside a solid), and advances the particles; the same
// pass reports scrapes and impacts as events (events.h). Nothing is created or destroyed inside Box2D
// callbacks.
//
// Lifetime: create after the world, destroy before it; one Effects per world at a time (destroy the old
// one before creating its replacement: creating a second one throws InputError). Contacts already
// touching when Effects is created are picked up at the next world step (PreSolve). Effects installs
// itself as the world's contact and destruction listener; give it the application's own listeners
// (EffectsDef or the setters, never b2World's setters while it lives) and it forwards every callback to
// them. A contact listener already set on the world (b2World::SetContactListener before Effects) is kept
// and forwarded to when EffectsDef names none. A destruction listener set on the world before cannot be
// (Box2D 2.4 has no way to read it): it is replaced, and not put back by the destructor either, so give it
// through EffectsDef::destructionListener (or set it again on the world after the Effects is gone).
// The destructor first destroys the bodies of its body-backed particles (ParticleBackend::body, the
// tutorial preset), their fixtures' goodbyes forwarded as in a step (the application's listener may call
// into the Effects then; Step does nothing then), and then puts the application's listeners back: the
// ones it forwards to at that time (none after SetContactListener(nullptr): Box2D's own). Through the
// destruction listener it forgets fixtures destroyed with their body and notices when the application
// destroys the Box2D body of a body-backed particle: that particle goes, and its body is never destroyed
// twice.
// Threading: one thread at a time, the one that steps the world (a Step while another thread steps the same
// Effects throws InputError). Effects on different worlds are independent: each may be created, stepped and
// destroyed on its own thread, at the same time as the others (Box2D 2.4.1 itself keeps process-wide
// statistics counters, b2_gjkCalls and b2_toiCalls, that concurrent world steps update without locks:
// ThreadSanitizer reports them in a Box2D built with it; they change no result). Stepping several worlds
// at once, give each ParticleSystemOptions::threads 1.
#pragma once

#include "contactfx/config.h"
#include "contactfx/events.h"
#include "contactfx/particle_system.h"
#include "contactfx/rules.h"
#include "contactfx/stats.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string_view>
#include <type_traits>

class b2World;
class b2Body;
class b2Fixture;
class b2ContactListener;
class b2DestructionListener;

namespace cfx
{

namespace detail
{
struct EffectsAccess;
}

/// How to create an Effects object.
struct EffectsDef
{
    /// Validated on creation. Empty unless given: no materials, no rules, no effects (presets.h has
    /// DefaultPreset() and TutorialPreset()).
    EffectsConfig config;
    std::uint64_t seed = 1;                               ///< seeds every random choice
    b2ContactListener* contactListener = nullptr;         ///< the application's, may be null
    b2DestructionListener* destructionListener = nullptr; ///< the application's, may be null
    EffectEventListener* eventListener = nullptr;         ///< receives each step's events, may be null
    ParticleSystemOptions particles{};                    ///< threads, and the particle check
};

/// What Effects::SetMaterial takes as a material's name: anything that converts to std::string_view (a
/// literal, std::string, const char*), but not nullptr (nor an integer, which does not convert).
template <class Name>
concept MaterialName = std::is_convertible_v<const Name&, std::string_view> && !std::is_null_pointer_v<Name>;

class Effects
{
public:
    /// Throws InputError (file "<api>", field path) when def.config is invalid, and (field "world") when
    /// `world` already has an Effects object.
    Effects(b2World& world, const EffectsDef& def);
    ~Effects();
    Effects(const Effects&) = delete;
    Effects& operator=(const Effects&) = delete;

    MaterialId FindMaterial(std::string_view name) const { return m_config.FindMaterial(name); }
    /// Gives `fixture` a material (an invalid id removes it). Takes effect at the next world step, for
    /// contacts already touching too: their scrapes end (ScrapeEnd::materialChanged), and those that go on
    /// touching are tracked again under the rule the new materials select. The same material again
    /// changes nothing. Throws InputError (file "<api>", field "fixture" or "material") for a null fixture
    /// or an id that is neither invalid nor one of the config's materials; nothing changes then.
    void SetMaterial(b2Fixture* fixture, MaterialId material);
    /// Gives every fixture of `body` the material; throws as above (field "body" for a null body).
    void SetMaterial(b2Body* body, MaterialId material);
    /// The same with the material's name, which must be one of the config's: throws InputError (file
    /// "<api>", field "material") naming the nearest material when it is not, and as above; nothing changes
    /// then. Prefer it to SetMaterial(fixture, FindMaterial(name)), where a misspelt name gives an invalid
    /// id, which removes the fixture's material without a word. Takes what converts to std::string_view
    /// (a literal, std::string, const char*: a null one throws, field "material") and nothing else, so
    /// SetMaterial(fixture, {}) still removes the material and SetMaterial(fixture, 0) does not compile.
    template <MaterialName Name> void SetMaterial(b2Fixture* fixture, const Name& material)
    {
        SetMaterialNamed(fixture, NameText(material));
    }
    template <MaterialName Name> void SetMaterial(b2Body* body, const Name& material)
    {
        SetMaterialNamed(body, NameText(material));
    }
    /// The fixture's material, or an invalid id (also for a null fixture).
    MaterialId Material(const b2Fixture* fixture) const;
    /// Call before b2Body::DestroyFixture (Box2D 2.4 tells no listener about it): forgets the fixture's
    /// material and its contacts. Fixtures destroyed with their body are handled automatically. Without
    /// it, a later fixture at the freed address does not inherit the material when it differs in body,
    /// shape or geometry (counted in EffectsStats::staleMaterials); one re-created identically on the same
    /// body cannot be told apart and keeps it (docs/api.md, "Destroying fixtures"). Throws InputError
    /// (file "<api>", field "fixture") for a null fixture; nothing changes then.
    void ForgetFixture(b2Fixture* fixture);

    /// The application's listeners, forwarded every Box2D callback from the next one on (null: none). They
    /// must stay valid until replaced, and after the Effects is destroyed while the world uses them (the
    /// destructor puts them back on the world).
    void SetContactListener(b2ContactListener* listener);
    void SetDestructionListener(b2DestructionListener* listener);
    void SetEventListener(EffectEventListener* listener) { m_eventListener = listener; }

    /// Runs after each b2World::Step with the same dt (s, > 0): emission, spawning, particle motion.
    /// With substeps (several world steps a frame), call it after each of them: called once after several,
    /// it sees only the contacts of the last, and the emission of the others is lost (four substeps of
    /// 1/240 s and one Step(1/60): 43 % fewer sparks in a trial). Not detected.
    /// Called again without a world step in between (a paused world), it moves the particles but emits
    /// nothing and leaves the scrapes as they are: the contacts are as the last world step left them. The
    /// particles still meet the bodies as moving with their velocities over dt (a trial's 0.5 s step threw
    /// smoke off a paused spinning wheel at up to 38 m/s): in a pause, step with the usual dt or not at all.
    /// Throws InputError (file "<api>", field "dt" or "gravity") when dt is not finite and > 0 or the
    /// world's gravity is not finite, (field "listener") when called from a listener during a Step of this
    /// Effects or inside b2World::Step, and (field "thread") while another thread steps it; nothing changes
    /// then.
    void Step(float dt);
    /// Ends every scrape going on, for an application that stops stepping (a level ends, the game
    /// quits): Events() then holds one scrapeEnded per open scrape, reason ScrapeEnd::stopped, in id
    /// order, with the scrape's last point and normal and the last step's number, and the event listener
    /// gets them. So every scrapeBegan has its scrapeEnded, and a sound looping on a scrape stops. Nothing
    /// else changes: a contact still scraping at the next Step begins a new scrape, with a new id. Called by
    /// a listener during a Step (the event listener, or the destruction listener as particle bodies go),
    /// the ends follow that step's events and the event listener hears them with the rest. Throws
    /// InputError (field "thread") when another thread steps this Effects.
    void EndScrapes();

    /// Call right after b2World::ShiftOrigin(newOrigin), with the same vector (m): the particles (pool
    /// ones; body-backed ones move with their bodies) and the points the scrapes going on last reported
    /// move by -newOrigin with the world. Events already delivered keep their points. The pair may come
    /// anywhere between steps, also between b2World::Step and Step: the particles then start where they
    /// would have with the shift before the world step. Throws InputError (file "<api>", field
    /// "newOrigin") when it is not finite; nothing changes then.
    void ShiftOrigin(b2Vec2 newOrigin);

    /// Removes every particle now (ParticleSystem::Clear): a level restarted in place with the same world
    /// and Effects leaves none of the last attempt's particles behind. Events, scrapes and counters stay
    /// (EndScrapes ends the scrapes). Returns false, changing nothing, inside b2World::Step (a contact
    /// listener) or from a destruction listener while a particle's body is being destroyed.
    bool ClearParticles();

    /// The particles' static geometry cache (ParticleSystem): build it now, after loading a level, rather
    /// than in the first step with a colliding particle (returns whether it built); or, with
    /// EffectsDef::particles.watchStaticGeometry false, say that the static geometry changed. See
    /// docs/particles.md, Static geometry. EffectsStats::staticGeometryBuilds counts the builds.
    bool BuildStaticGeometry();
    void InvalidateStaticGeometry() { m_particles.InvalidateStaticGeometry(); }

    /// Whether `body` is the Box2D body of one of this object's body-backed particles (ParticleBackend::
    /// body, the tutorial preset). Such bodies are in the world like any other: the application's contact
    /// and destruction listeners hear of their contacts and fixtures, and its world queries meet them;
    /// this tells them apart. O(1).
    bool IsParticleBody(const b2Body* body) const { return m_particles.IsParticleBody(body); }

    const EffectsStats& Stats() const { return m_stats; }
    /// The scrape and impact events of the last Step (or EndScrapes), in order (events.h). Valid until
    /// the next Step or EndScrapes.
    std::span<const EffectEvent> Events() const;
    ParticleView Particles() const { return m_particles.View(); }
    const EffectsConfig& Config() const { return m_config; }
    const RuleTable& Rules() const { return m_rules; }
    b2World& World() const { return m_world; }

private:
    friend struct detail::EffectsAccess; // the library's own tests and tools (src/effects_access.h)
    struct Internals;      // materials table, contact tracker, listeners, emitter, event tracker
    void NotifyListener(); // gives the event listener every event of Events(); ends Step's hold
    /// Throws SetMaterial's InputError for a null `target` (named `targetField`) or a material id that is
    /// neither invalid nor one of the config's.
    void CheckMaterialArguments(const void* target, const char* targetField, MaterialId material) const;
    /// The id of the config's material `name`; throws InputError (field "material") when it has none.
    MaterialId RequireMaterial(std::string_view name) const;
    void SetMaterialNamed(b2Fixture* fixture, std::string_view material);
    void SetMaterialNamed(b2Body* body, std::string_view material);
    /// A name as text; throws InputError (field "material") for a null pointer.
    static std::string_view NameText(const char* name);
    static std::string_view NameText(std::string_view name) { return name; }

    b2World& m_world;
    EffectsConfig m_config;
    RuleTable m_rules;
    ParticleSystem m_particles;
    std::unique_ptr<Internals> m_internals;
    EffectsStats m_stats;
    EffectEventListener* m_eventListener = nullptr;
};

} // namespace cfx
