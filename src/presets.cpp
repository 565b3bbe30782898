#include "contactfx/presets.h"

namespace cfx
{

namespace
{

// The tutorial removes a fixed amount of life per step at its 60 Hz; as a lifetime in seconds:
constexpr float kTutorialHz = 60.0f;
constexpr float TutorialLifetime(float lifeLostPerStep)
{
    return 1.0f / (lifeLostPerStep * kTutorialHz);
}

const std::vector<std::string> kMaterials = {"steel", "rubber", "concrete", "dirt"};

constexpr Color kSmoke{0.5f, 0.5f, 0.5f, 1.0f};
constexpr Color kSparks{0.9f, 1.0f, 0.1f, 1.0f};
constexpr Color kDirt{1.0f, 0.6f, 0.4f, 1.0f};

ParticleTypeDef TutorialType(const char* name, Color color)
{
    ParticleTypeDef type;
    type.name = name;
    type.lifeBase = 0.0f;
    type.lifeFromIntensity = 0.3f;
    type.backend = ParticleBackend::body;
    type.velocityFrame = VelocityFrame::world; // the tutorial's fractions of world velocities
    type.radius = 0.01f;
    type.density = 1.0f;
    type.friction = 2.0f;
    type.restSpeed =
        1.0f; // Box2D 2.3's b2_velocityThreshold, the tutorial's (2.4 mixes in the ground's 1 m/s)
    type.categoryBits = 0x0002;
    type.maskBits = 0x0001;
    type.colorStart = color;
    type.colorEnd = color;
    type.sizeStart = 0.12f; // the tutorial's 8-pixel point at its default zoom
    type.sizeEnd = 0.12f;
    return type;
}

RuleDef Rule(const char* a, const char* b, const char* particle)
{
    RuleDef rule;
    rule.materialA = a;
    rule.materialB = b;
    rule.particleType = particle;
    return rule;
}

MaterialAssignment Assign(const char* material, BodyTypeFilter bodyType)
{
    MaterialAssignment assignment;
    assignment.material = material;
    assignment.bodyType = bodyType;
    return assignment;
}

// How the tutorial told its materials apart before they were stored in the scene (NOTES.md): steel is a
// fixture of the body heavier than 3 kg (the car), concrete a static fixture with friction above 0.5,
// dirt one below, rubber any other dynamic body heavier than 0.4 kg (the wheels). First match wins.
std::vector<MaterialAssignment> TutorialGuesses()
{
    MaterialAssignment steel = Assign("steel", BodyTypeFilter::any);
    steel.massAbove = 3.0f;
    MaterialAssignment concrete = Assign("concrete", BodyTypeFilter::staticBody);
    concrete.frictionAbove = 0.5f;
    MaterialAssignment dirt = Assign("dirt", BodyTypeFilter::staticBody);
    dirt.frictionBelow = 0.5f;
    MaterialAssignment rubber = Assign("rubber", BodyTypeFilter::dynamicBody);
    rubber.massAbove = 0.4f;
    return {steel, concrete, dirt, rubber};
}

} // namespace

EffectsConfig TutorialPreset()
{
    EffectsConfig config;
    config.name = "tutorial";
    config.materials = kMaterials;

    ParticleTypeDef smoke = TutorialType("smoke", kSmoke);
    smoke.inheritA = smoke.inheritB = 0.1f;
    smoke.spread = 2.0f;
    smoke.gravityScale = 0.0f;
    smoke.drag = 4.0f;
    smoke.restitution = 0.1f;
    smoke.lifetime = TutorialLifetime(0.01f);

    ParticleTypeDef sparks = TutorialType("sparks", kSparks);
    sparks.spread = 3.0f;
    sparks.gravityScale = 0.5f;
    sparks.drag = 1.0f;
    sparks.restitution = 0.8f;
    sparks.lifetime = TutorialLifetime(0.015f);

    ParticleTypeDef dirt = TutorialType("dirt", kDirt);
    dirt.inheritA = dirt.inheritB = 0.3f;
    dirt.spread = 2.0f;
    dirt.gravityScale = 1.0f;
    dirt.drag = 0.1f;
    dirt.restitution = 0.2f;
    dirt.lifetime = TutorialLifetime(0.005f);

    config.particleTypes = {smoke, sparks, dirt};

    config.rules = {Rule("steel", "concrete", "sparks"), Rule("rubber", "concrete", "smoke"),
                    Rule("steel", "dirt", "dirt"), Rule("rubber", "dirt", "dirt")};
    for (RuleDef& rule : config.rules)
    {
        rule.intensity = IntensityModel{SpeedMode::full, FrictionMix::product, ManifoldPoints::first, 0.0f};
        rule.threshold = 1.0f;
        rule.emission = EmissionMode::perStep;
        rule.placement = SpawnPlacement::tutorialDrop;
    }
    config.budget = ParticleBudget{100, RecyclePolicy::oldest};
    config.assignments = TutorialGuesses();
    return config;
}

EffectsConfig DefaultPreset()
{
    EffectsConfig config;
    config.name = "default";
    config.materials = kMaterials;

    ParticleTypeDef smoke;
    smoke.name = "smoke";
    smoke.lifeBase = 0.5f;
    smoke.lifeFromIntensity = 0.1f;
    smoke.lifetime = 2.0f;
    smoke.inheritA = 0.1f; // the tyre's surface
    smoke.normalSpeed = 0.4f;
    smoke.spread = 0.5f;
    smoke.gravityScale = -0.05f; // warm smoke drifts up
    smoke.drag = 2.5f;
    smoke.radius = 0.05f;
    smoke.restitution = 0.1f;
    smoke.friction = 0.2f;
    smoke.colorStart = Color{0.5f, 0.5f, 0.5f, 0.8f};
    smoke.colorEnd = Color{0.75f, 0.75f, 0.75f, 0.5f};
    smoke.sizeStart = 0.15f;
    smoke.sizeEnd = 0.9f;

    ParticleTypeDef sparks;
    sparks.name = "sparks";
    sparks.lifeBase = 0.5f;
    sparks.lifeFromIntensity = 0.15f;
    sparks.lifetime = 0.9f;
    sparks.slipFactor = 0.5f; // thrown along the scrape
    sparks.normalSpeed = 1.5f;
    sparks.spread = 2.0f;
    sparks.gravityScale = 1.0f;
    sparks.drag = 0.3f;
    sparks.radius = 0.01f;
    sparks.restitution = 0.5f;
    sparks.friction = 0.3f;
    sparks.colorStart = Color{0.9f, 1.0f, 0.1f, 1.0f};
    sparks.colorEnd = Color{1.0f, 0.35f, 0.05f, 1.0f};
    sparks.sizeStart = 0.06f;
    sparks.sizeEnd = 0.03f;
    sparks.streak = 0.03f;

    ParticleTypeDef dirt;
    dirt.name = "dirt";
    dirt.lifeBase = 0.6f;
    dirt.lifeFromIntensity = 0.1f;
    dirt.lifetime = 2.5f;
    dirt.slipFactor = 0.4f; // a spinning wheel throws dirt backwards
    dirt.normalSpeed = 2.5f;
    dirt.spread = 1.2f;
    dirt.gravityScale = 1.0f;
    dirt.drag = 0.1f;
    dirt.radius = 0.03f;
    dirt.restitution = 0.15f;
    dirt.friction = 0.9f;
    dirt.colorStart = Color{1.0f, 0.6f, 0.4f, 1.0f};
    dirt.colorEnd = Color{0.7f, 0.45f, 0.3f, 1.0f};
    dirt.sizeStart = 0.08f;
    dirt.sizeEnd = 0.06f;

    config.particleTypes = {smoke, sparks, dirt};

    auto withModel = [](RuleDef rule, float threshold, float rate, float maxRate)
    {
        rule.intensity = IntensityModel{SpeedMode::tangential, FrictionMix::sqrt, ManifoldPoints::all, 0.02f};
        rule.threshold = threshold;
        rule.emission = EmissionMode::rate;
        rule.ratePerIntensity = rate;
        rule.maxRate = maxRate;
        rule.placement = SpawnPlacement::surface;
        return rule;
    };
    // Hard hits burst: sparks from steel on concrete, dirt from anything landing on dirt.
    config.rules = {withModel(Rule("steel", "concrete", "sparks"), 1.0f, 80.0f, 800.0f),
                    withModel(Rule("rubber", "concrete", "smoke"), 1.5f, 30.0f, 250.0f),
                    withModel(Rule("steel", "dirt", "dirt"), 0.5f, 40.0f, 300.0f),
                    withModel(Rule("rubber", "dirt", "dirt"), 0.5f, 40.0f, 300.0f)};
    config.rules[0].burstPerSpeed = 6.0f;
    config.rules[0].burstMax = 40.0f;
    config.rules[2].burstPerSpeed = 4.0f;
    config.rules[3].burstPerSpeed = 2.0f;
    config.budget = ParticleBudget{8192, RecyclePolicy::oldest};
    config.assignments = TutorialGuesses(); // plain scenes get effects without a `material` property
    return config;
}

} // namespace cfx
