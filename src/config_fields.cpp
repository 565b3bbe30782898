// The field tables of the effects configuration (contactfx/config_fields.h).
//
// One row per member: name, member, unit, range, doc line, enum names, text rule, relation, editor step.
// Ranges are wide enough for any real effect and narrow enough that nothing derived from them (start
// speeds, positions, particle counts per step, the float-to-int casts of the emitter and the particle
// grid) can overflow or make a step's cost unbounded. The order of each table is the order in which
// fields are checked and read (enums after the plain fields, as the reader has always reported them).
#include "contactfx/config_fields.h"

#include "float_text.h"

#include <array>
#include <cmath>
#include <string>

namespace cfx
{

bool FieldRange::Contains(float value) const
{
    const bool aboveMin = minExclusive ? value > min : value >= min;
    return std::isfinite(value) && aboveMin && value <= max;
}

std::string ExpectedInteger(const FieldRange& range)
{
    return "an integer in [" + std::to_string(static_cast<long long>(range.min)) + ", " +
           std::to_string(static_cast<long long>(range.max)) + "]";
}

std::string ExpectedNumber(const FieldRange& range)
{
    using detail::FloatText;
    return range.minExclusive ? "a number > " + FloatText(range.min) + " and <= " + FloatText(range.max)
                              : "a number between " + FloatText(range.min) + " and " + FloatText(range.max);
}

std::string_view ExpectedText(TextRule rule)
{
    switch (rule)
    {
    case TextRule::any:
        return "a string";
    case TextRule::name:
        return "a non-empty name";
    case TextRule::pattern:
        return "a non-empty pattern";
    case TextRule::material:
        return "a material name";
    case TextRule::particleType:
        return "a particle type name";
    case TextRule::optionalParticleType:
        return "a particle type name or \"\"";
    }
    return "a string";
}

namespace
{

template <typename T> struct MemberOf;
template <typename S, typename T> struct MemberOf<T S::*>
{
    using Struct = S;
    using Type = T;
};

// The get/set pair of an enum member.
template <auto Member> constexpr auto Choice()
{
    using S = typename MemberOf<decltype(Member)>::Struct;
    using E = typename MemberOf<decltype(Member)>::Type;
    return ChoiceMember<S>{[](const S& s) { return static_cast<int>(s.*Member); },
                           [](S& s, int value) { s.*Member = static_cast<E>(value); }};
}

constexpr FieldRange kUnit{0.0f, 1.0f};

constexpr std::string_view kBackends[] = {"pool", "body"};
constexpr std::string_view kVelocityFrames[] = {"surface", "world"};
constexpr std::string_view kEmissionModes[] = {"rate", "perStep"};
constexpr std::string_view kPlacements[] = {"surface", "tutorialDrop"};
constexpr std::string_view kSpeedModes[] = {"full", "tangential"};
constexpr std::string_view kFrictionMixes[] = {"product", "sqrt", "min", "max", "mean"};
constexpr std::string_view kManifoldPoints[] = {"first", "all"};
constexpr std::string_view kBodyTypeFilters[] = {"any", "static", "kinematic", "dynamic"};
constexpr std::string_view kRecyclePolicies[] = {"oldest", "lowestLife"};
constexpr std::string_view kTimbres[] = {"auto", "hiss", "squeal", "rumble"};

using P = ParticleTypeDef;
const std::array kParticleTypeFields{
    Field<P>{.name = "name", .member = &P::name, .doc = "what rules refer to", .text = TextRule::name},
    Field<P>{.name = "lifeBase",
             .member = &P::lifeBase,
             .range = kUnit,
             .doc = "start life = clamp(lifeBase + lifeFromIntensity * intensity, 0, 1)",
             .step = 0.01f},
    Field<P>{.name = "lifeFromIntensity",
             .member = &P::lifeFromIntensity,
             .unit = "per unit of intensity",
             .range = {0.0f, 1000.0f},
             .doc = "the tutorial uses 0.3 with lifeBase 0",
             .step = 0.01f},
    Field<P>{.name = "lifetime",
             .member = &P::lifetime,
             .unit = "s",
             .range = {0.0f, 3600.0f, true},
             .doc = "time for life to fall from 1 to 0",
             .step = 0.01f},
    Field<P>{.name = "inheritA",
             .member = &P::inheritA,
             .range = {-10.0f, 10.0f},
             .doc = "fraction of the velocity of the body whose material is the rule's `materialA`, at the "
                    "contact point (relative to the surface, see `velocityFrame`)",
             .step = 0.01f},
    Field<P>{.name = "inheritB",
             .member = &P::inheritB,
             .range = {-10.0f, 10.0f},
             .doc = "the same for the body whose material is the rule's `materialB`",
             .step = 0.01f},
    Field<P>{.name = "slipFactor",
             .member = &P::slipFactor,
             .range = {-10.0f, 10.0f},
             .doc = "fraction of the other body's sliding velocity over the surface (sparks thrown along a "
                    "scrape, dirt thrown back by a spinning wheel)",
             .step = 0.01f},
    Field<P>{.name = "normalSpeed",
             .member = &P::normalSpeed,
             .unit = "m/s",
             .range = {-1000.0f, 1000.0f},
             .doc = "speed away from the surface",
             .step = 0.05f},
    Field<P>{.name = "spread",
             .member = &P::spread,
             .unit = "m/s",
             .range = {0.0f, 1000.0f},
             .doc = "uniform random in [-spread, spread] added per axis",
             .step = 0.05f},
    Field<P>{.name = "gravityScale",
             .member = &P::gravityScale,
             .range = {-100.0f, 100.0f},
             .doc = "times the world's gravity; negative rises",
             .step = 0.01f},
    Field<P>{.name = "drag",
             .member = &P::drag,
             .unit = "1/s",
             .range = {0.0f, 1000.0f},
             .doc = "Box2D's linear damping: v *= 1 / (1 + dt * drag)",
             .step = 0.05f},
    Field<P>{.name = "collide",
             .member = &P::collide,
             .doc = "collide with the world's fixtures (never with other particles)"},
    Field<P>{.name = "radius",
             .member = &P::radius,
             .unit = "m",
             .range = {0.001f, 10.0f},
             .doc = "collision radius (from 1 mm: below, float rounding at coordinates of metres is "
                    "larger than the particle); starts are looked for within the larger of 1 m and the other "
                    "body's size plus 0.1 m along the surface (the tutorial's drop: 1 m), so a particle much "
                    "wider than the body making the contact finds none and is not spawned (`spawn_rejected`)",
             .step = 0.001f},
    Field<P>{
        .name = "restitution", .member = &P::restitution, .range = kUnit, .doc = "bounce", .step = 0.01f},
    Field<P>{.name = "restSpeed",
             .member = &P::restSpeed,
             .unit = "m/s",
             .range = {0.0f, 1000.0f},
             .doc =
                 "a hit approaching slower than this does not bounce; the smaller of this and the fixture's "
                 "restitution threshold counts, as Box2D mixes them",
             .step = 0.05f},
    Field<P>{.name = "friction",
             .member = &P::friction,
             .range = {0.0f, 1000.0f},
             .doc = "Coulomb friction on each hit",
             .step = 0.01f},
    Field<P>{.name = "categoryBits",
             .member = &P::categoryBits,
             .range = {0.0f, 65535.0f},
             .doc = "like `b2Filter`: a fixture is hit when its mask has these bits and its category is in "
                    "`maskBits`"},
    Field<P>{.name = "maskBits",
             .member = &P::maskBits,
             .range = {0.0f, 65535.0f},
             .doc = "the fixture categories particles of this type hit"},
    Field<P>{.name = "hitSpeed",
             .member = &P::hitSpeed,
             .unit = "m/s",
             .range = {0.0f, 1000.0f},
             .doc = "a touch approaching the surface at least this fast is a particle hit (resting particles "
                    "approach at 0.16 to 0.33 m/s)",
             .step = 0.05f},
    Field<P>{.name = "density",
             .member = &P::density,
             .unit = "kg/m²",
             .range = {0.0f, 1.0e6f, true},
             .doc = "body backend only",
             .step = 0.05f},
    Field<P>{.name = "colorStart",
             .member = &P::colorStart,
             .range = kUnit,
             .doc = "colour at birth, [r, g, b] or [r, g, b, a]; the drawn opacity is alpha times life"},
    Field<P>{.name = "colorEnd", .member = &P::colorEnd, .range = kUnit, .doc = "colour at death"},
    Field<P>{.name = "sizeStart",
             .member = &P::sizeStart,
             .unit = "m",
             .range = {0.0f, 100.0f, true},
             .doc = "drawn diameter at birth",
             .step = 0.005f},
    Field<P>{.name = "sizeEnd",
             .member = &P::sizeEnd,
             .unit = "m",
             .range = {0.0f, 100.0f, true},
             .doc = "drawn diameter at death",
             .step = 0.005f},
    Field<P>{.name = "streak",
             .member = &P::streak,
             .unit = "s",
             .range = {0.0f, 10.0f},
             .doc = "draw as a line along the velocity covering this much motion (sparks); 0 draws a soft "
                    "round point",
             .step = 0.001f},
    Field<P>{.name = "backend",
             .member = Choice<&P::backend>(),
             .doc = "a light pool particle, or a Box2D body (the tutorial's way; pushes what it hits)",
             .choices = kBackends},
    Field<P>{.name = "velocityFrame",
             .member = Choice<&P::velocityFrame>(),
             .doc = "`inheritA`, `inheritB` and `slipFactor` are fractions of velocities relative to the "
                    "surface, whose own velocity is added (a grinding wheel or a conveyor throws the same "
                    "spray as a still surface), or of world velocities (the tutorial's)",
             .choices = kVelocityFrames},
};

using I = IntensityModel;
const std::array kIntensityFields{
    Field<I>{.name = "impulseWeight",
             .member = &I::impulseWeight,
             .unit = "1/N",
             .range = {0.0f, 1000.0f},
             .doc = "intensity = speed * friction * (1 + impulseWeight * normal force); the normal force is "
                    "the whole body pair's",
             .step = 0.001f},
    Field<I>{.name = "speed",
             .member = Choice<&I::speed>(),
             .doc = "relative speed at the point, or only its part along the surface",
             .choices = kSpeedModes},
    Field<I>{.name = "friction",
             .member = Choice<&I::friction>(),
             .doc = "how the two frictions mix (`sqrt` is Box2D's)",
             .choices = kFrictionMixes},
    Field<I>{.name = "points",
             .member = Choice<&I::points>(),
             .doc = "which manifold points of each contact are sampled",
             .choices = kManifoldPoints},
};

using R = RuleDef;
const std::array kRuleFields{
    Field<R>{.name = "materialA",
             .member = &R::materialA,
             .doc = "the pair's first material; the order does not matter, except that `inheritA` follows it",
             .text = TextRule::material},
    Field<R>{.name = "materialB",
             .member = &R::materialB,
             .doc = "the pair's second material (`inheritB` follows it)",
             .text = TextRule::material},
    Field<R>{.name = "particleType",
             .member = &R::particleType,
             .doc = "what is emitted",
             .text = TextRule::particleType},
    Field<R>{
        .name = "intensity", .member = &R::intensity, .doc = "how a contact sample becomes an intensity"},
    Field<R>{.name = "threshold",
             .member = &R::threshold,
             .range = {0.0f, 1.0e6f},
             .doc = "intensities at or below it emit nothing (`rate`: the pair's intensity; `perStep`: each "
                    "sample's)",
             .step = 0.05f},
    Field<R>{.name = "ratePerIntensity",
             .member = &R::ratePerIntensity,
             .unit = "1/s per unit",
             .range = {0.0f, 1.0e6f},
             .doc = "rate = ratePerIntensity * (intensity - threshold)",
             .step = 0.5f},
    Field<R>{.name = "maxRate",
             .member = &R::maxRate,
             .unit = "1/s",
             .range = {0.0f, 1.0e5f},
             .doc = "cap per body pair, over time: at most `maxRate * (T + 1/30)` in any T seconds (with "
                    "`burstMax`, what bounds the particles one pair can start per step)",
             .step = 1.0f},
    Field<R>{.name = "scrapeEndDelay",
             .member = &R::scrapeEndDelay,
             .unit = "s",
             .range = {0.0f, 3600.0f},
             .doc = "a scrape event ends after the intensity stayed at or below the threshold this long",
             .step = 0.01f},
    Field<R>{.name = "impactThreshold",
             .member = &R::impactThreshold,
             .unit = "m/s",
             .range = {0.0f, 1.0e4f},
             .doc = "approach speed along the normal at a new touch that makes an impact event",
             .step = 0.05f},
    Field<R>{.name = "burstPerSpeed",
             .member = &R::burstPerSpeed,
             .unit = "per m/s",
             .range = {0.0f, 1.0e4f},
             .doc =
                 "an impact bursts this many particles per m/s above `impactThreshold` (or `burstThreshold`, "
                 "when higher)",
             .step = 0.1f},
    Field<R>{.name = "burstThreshold",
             .member = &R::burstThreshold,
             .unit = "m/s",
             .range = {0.0f, 1.0e4f},
             .doc =
                 "approach speed an impact must pass to burst, when above `impactThreshold`: softer impacts "
                 "make events and sound but no particles",
             .step = 0.05f},
    Field<R>{.name = "burstMax",
             .member = &R::burstMax,
             .range = {0.0f, 1.0e5f},
             .doc = "most particles one impact bursts",
             .step = 1.0f},
    Field<R>{.name = "burstParticleType",
             .member = &R::burstParticleType,
             .doc = "what impacts burst; `\"\"`: the rule's `particleType` (so one pair can scrape dust and "
                    "burst splinters)",
             .text = TextRule::optionalParticleType},
    Field<R>{.name = "emission",
             .member = Choice<&R::emission>(),
             .doc =
                 "particles per second per body pair growing with its intensity (independent of the step "
                 "rate and of how each body's surface is cut into fixtures, chain segments and manifold "
                 "points; a ground made of several bodies is several pairs, each emitting), or one per "
                 "sample per contact per step (the tutorial: the emission then follows the step rate, twice "
                 "as many at 120 Hz as at 60)",
             .choices = kEmissionModes},
    Field<R>{.name = "placement",
             .member = Choice<&R::placement>(),
             .doc = "outside both surfaces near the contact, or the tutorial's drop onto the static ground "
                    "below (stepping aside from a wheel or body standing there); never inside a solid: with "
                    "no free start near the contact the particle is not spawned (`spawn_rejected`)",
             .choices = kPlacements},
};

using A = MaterialAssignment;
const std::array kAssignmentFields{
    Field<A>{.name = "material",
             .member = &A::material,
             .doc = "what matching fixtures get",
             .text = TextRule::material},
    Field<A>{.name = "bodyName",
             .member = &A::bodyName,
             .doc = "glob on the body's RUBE `name`: `*` any run of characters, `?` one character, anything "
                    "else itself (case-sensitive); the whole name must match",
             .text = TextRule::pattern},
    Field<A>{.name = "fixtureName",
             .member = &A::fixtureName,
             .doc = "the same for the fixture's `name`",
             .text = TextRule::pattern},
    Field<A>{.name = "frictionAbove",
             .member = &A::frictionAbove,
             .range = {-1000.0f, 1000.0f},
             .doc = "fixture friction > this (strict); absent: no bound",
             .step = 0.01f},
    Field<A>{.name = "frictionBelow",
             .member = &A::frictionBelow,
             .range = {-1000.0f, 1000.0f},
             .doc = "fixture friction < this; when both bounds are given, it must exceed `frictionAbove`",
             .greaterThan = "frictionAbove",
             .step = 0.01f},
    Field<A>{.name = "massAbove",
             .member = &A::massAbove,
             .unit = "kg",
             .range = {-1.0e12f, 1.0e12f},
             .doc =
                 "the body's mass as Box2D computes it after loading (static and kinematic bodies weigh 0) "
                 "> this",
             .step = 0.1f},
    Field<A>{.name = "massBelow",
             .member = &A::massBelow,
             .unit = "kg",
             .range = {-1.0e12f, 1.0e12f},
             .doc = "the body's mass < this; when both bounds are given, it must exceed `massAbove`",
             .greaterThan = "massAbove",
             .step = 0.1f},
    Field<A>{.name = "bodyType",
             .member = Choice<&A::bodyType>(),
             .doc = "the body's type",
             .choices = kBodyTypeFilters},
};

using B = ParticleBudget;
const std::array kBudgetFields{
    Field<B>{.name = "capacity",
             .member = &B::capacity,
             .range = {1.0f, 4.0e6f},
             .doc = "hard cap on live particles; one step spawns at most this many, and what its emission "
                    "owes beyond that is not spawned (`spawn_over_capacity`)",
             .step = 256.0f},
    Field<B>{.name = "recycle",
             .member = Choice<&B::recycle>(),
             .doc =
                 "who makes room when full: the particle spawned first, or the one with the least time left",
             .choices = kRecyclePolicies},
    Field<B>{
        .name = "contacts",
        .member = &B::contacts,
        .range = {0.0f, 1.0e6f},
        .doc =
            "touching contacts (and body pairs) room is made for at creation, for each rule (about 800 "
            "bytes a contact a rule; rules times contacts at most 2^22): with no more touching one rule at "
            "once, neither the contact callbacks nor `Effects::Step` allocate for them (the particles' own "
            "warm-up in the first steps aside)",
        .step = 64.0f},
    Field<B>{.name = "particleHits",
             .member = &B::particleHits,
             .range = {0.0f, 4096.0f},
             .doc = "particle hit groups (per type and body) a step reports at most, the largest kept; 0 "
                    "records no hits",
             .step = 1.0f},
};

using SC = SoundConfig;
const std::array kSoundFields{
    Field<SC>{.name = "maxVoices",
              .member = &SC::maxVoices,
              .range = {1.0f, 4096.0f},
              .doc = "most voices sounding at once; beyond it the loudest win (ties: the older voice)",
              .step = 1.0f},
    Field<SC>{.name = "impactMergeWindow",
              .member = &SC::impactMergeWindow,
              .unit = "s",
              .range = {0.0f, 10.0f},
              .doc =
                  "impacts of one body pair within this time of its impact voice's start merge into "
                  "that voice, which takes the loudest; particle hits of one type and body gather this long "
                  "(at most `particleHitLength`, the whole steps that fit) before their voice starts, so "
                  "it is also their delay",
              .step = 0.005f},
    Field<SC>{.name = "trackedPairs",
              .member = &SC::trackedPairs,
              .range = {0.0f, 1.0e6f},
              .doc = "body pairs tracked at once (scraping, sounding, releasing or cooling down) room is "
                     "made for at creation: with no more at once, `SoundVoices::Step` does not allocate",
              .step = 16.0f},
    Field<SC>{.name = "gain",
              .member = &SC::gain,
              .range = {0.0f, 4.0f},
              .doc = "the synthesizer's level: a voice's amplitude is gain * loudness before the soft "
                     "limiter",
              .step = 0.01f},
    Field<SC>{.name = "particleHitGain",
              .member = &SC::particleHitGain,
              .unit = "1/(m/s)",
              .range = {0.0f, 1000.0f},
              .doc = "particle hits' loudness = 1 - exp(-particleHitGain * mean speed * sqrt(count))",
              .step = 0.005f},
    Field<SC>{.name = "particleHitLength",
              .member = &SC::particleHitLength,
              .unit = "s",
              .range = {0.0f, 10.0f, true},
              .doc = "how long a particle hits voice lasts (a tick or a tap), decaying to silence",
              .step = 0.005f},
};

using SR = SoundRuleDef;
const std::array kSoundRuleFields{
    Field<SR>{.name = "materialA",
              .member = &SR::materialA,
              .doc = "with `materialB`, the pair rule this sound rule is for (either order)",
              .text = TextRule::material},
    Field<SR>{.name = "materialB",
              .member = &SR::materialB,
              .doc = "the pair's other material",
              .text = TextRule::material},
    Field<SR>{.name = "scrapeStart",
              .member = &SR::scrapeStart,
              .range = kUnit,
              .doc = "loudness at or above which a scrape starts a voice",
              .step = 0.005f},
    Field<SR>{.name = "scrapeContinueRatio",
              .member = &SR::scrapeContinueRatio,
              .range = kUnit,
              .doc = "a sounding scrape voice goes on while its loudness stays at or above scrapeStart times "
                     "this (hysteresis); below it, or when the scrape ends, it releases",
              .step = 0.01f},
    Field<SR>{.name = "scrapeWindow",
              .member = &SR::scrapeWindow,
              .unit = "s",
              .range = {0.0f, 1.0f},
              .doc = "a scrape's drive is averaged over this much of the past: a landing's one-step spike of "
                     "force sounds alike at every step rate from 1 / scrapeWindow up; 0: each step's own",
              .step = 0.005f},
    Field<SR>{.name = "minDuration",
              .member = &SR::minDuration,
              .unit = "s",
              .range = {0.0f, 10.0f},
              .doc = "a scrape voice sounds at least this long before it may release",
              .step = 0.005f},
    Field<SR>{.name = "release",
              .member = &SR::release,
              .unit = "s",
              .range = {0.0f, 10.0f},
              .doc =
                  "fade to silence after a scrape voice lets go; a scrape of the same body pair that comes "
                  "back meanwhile takes the voice over",
              .step = 0.005f},
    Field<SR>{.name = "cooldown",
              .member = &SR::cooldown,
              .unit = "s",
              .range = {0.0f, 60.0f},
              .doc = "least time between two voice starts of the same kind for one body pair (an impact "
                     "inside it is dropped unless it merges; a scrape waits)",
              .step = 0.005f},
    Field<SR>{.name = "intensityGain",
              .member = &SR::intensityGain,
              .unit = "per unit of intensity",
              .range = {0.0f, 1000.0f},
              .doc = "scrape loudness = 1 - exp(-(intensityGain * intensity + slipSpeedGain * slip speed + "
                     "forceGain * normal force))",
              .step = 0.001f},
    Field<SR>{.name = "slipSpeedGain",
              .member = &SR::slipSpeedGain,
              .unit = "per m/s",
              .range = {0.0f, 1000.0f},
              .doc = "scrape loudness from the tangential (slip) speed",
              .step = 0.001f},
    Field<SR>{.name = "forceGain",
              .member = &SR::forceGain,
              .unit = "1/N",
              .range = {0.0f, 1000.0f},
              .doc = "scrape loudness from the body pair's normal force (its normal impulse / dt)",
              .step = 0.0001f},
    Field<SR>{.name = "approachSpeedGain",
              .member = &SR::approachSpeedGain,
              .unit = "per m/s",
              .range = {0.0f, 1000.0f},
              .doc = "impact loudness = 1 - exp(-(approachSpeedGain * approach speed + impulseGain * normal "
                     "impulse))",
              .step = 0.001f},
    Field<SR>{.name = "impulseGain",
              .member = &SR::impulseGain,
              .unit = "1/(N*s)",
              .range = {0.0f, 1000.0f},
              .doc = "impact loudness from the body pair's normal impulse in the step of the impact",
              .step = 0.001f},
    Field<SR>{.name = "impactLength",
              .member = &SR::impactLength,
              .unit = "s",
              .range = {0.0f, 10.0f, true},
              .doc = "how long an impact voice lasts; its loudness decays to 0 over it",
              .step = 0.005f},
    Field<SR>{.name = "brightSpeed",
              .member = &SR::brightSpeed,
              .unit = "m/s",
              .range = {0.0f, 1000.0f, true},
              .doc = "slip speed at which a scrape sounds brightest (highest filter, highest pitch)",
              .step = 0.1f},
    Field<SR>{.name = "timbre",
              .member = Choice<&SR::timbre>(),
              .doc = "the built-in synthesizer's colour: `auto` picks from the material names (rubber, tyre, "
                     "tire: squeal; dirt, sand, soil, mud, grass, gravel: rumble; else hiss)",
              .choices = kTimbres},
};

} // namespace

std::span<const Field<ParticleTypeDef>> ParticleTypeFields()
{
    return kParticleTypeFields;
}

std::span<const Field<RuleDef>> RuleFields()
{
    return kRuleFields;
}

std::span<const Field<IntensityModel>> IntensityFields()
{
    return kIntensityFields;
}

std::span<const Field<MaterialAssignment>> AssignmentFields()
{
    return kAssignmentFields;
}

std::span<const Field<ParticleBudget>> BudgetFields()
{
    return kBudgetFields;
}

std::span<const Field<SoundConfig>> SoundFields()
{
    return kSoundFields;
}

std::span<const Field<SoundRuleDef>> SoundRuleFields()
{
    return kSoundRuleFields;
}

} // namespace cfx
