#include "contactfx/config.h"

#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

namespace cfx
{

MaterialId EffectsConfig::FindMaterial(std::string_view wanted) const
{
    for (std::size_t i = 0; i < materials.size(); ++i)
    {
        if (materials[i] == wanted)
        {
            return MaterialId{static_cast<std::uint16_t>(i)};
        }
    }
    return MaterialId{};
}

ParticleTypeId EffectsConfig::FindParticleType(std::string_view wanted) const
{
    for (std::size_t i = 0; i < particleTypes.size(); ++i)
    {
        if (particleTypes[i].name == wanted)
        {
            return ParticleTypeId{static_cast<std::uint16_t>(i)};
        }
    }
    return ParticleTypeId{};
}

namespace
{

// Collects diagnostics with paths built from a prefix.
class Checker
{
public:
    Checker(std::string_view file, std::vector<Diagnostic>& out) : m_file(file), m_out(out) {}

    void Fail(const std::string& path, const std::string& message)
    {
        m_out.push_back(Diagnostic{std::string(m_file), path, message});
    }

    // A finite number in [low, high]; the bounds' words say how the range reads.
    void Number(const std::string& path, float value, float low, float high, const char* expected)
    {
        if (!std::isfinite(value) || value < low || value > high)
        {
            std::ostringstream text;
            text << "expected " << expected << ", found ";
            if (std::isnan(value))
            {
                text << "NaN";
            }
            else
            {
                text << value;
            }
            Fail(path, text.str());
        }
    }
    void NonNegative(const std::string& path, float value)
    {
        Number(path, value, 0.0f, INFINITY, "a number >= 0");
    }
    void Positive(const std::string& path, float value)
    {
        Number(path, value, 1e-9f, INFINITY, "a number > 0");
    }
    void Unit(const std::string& path, float value) { Number(path, value, 0.0f, 1.0f, "a number in [0, 1]"); }
    void Finite(const std::string& path, float value)
    {
        Number(path, value, -INFINITY, INFINITY, "a finite number");
    }
    void Enum(const std::string& path, int value, int count)
    {
        if (value < 0 || value >= count)
        {
            Fail(path, "expected one of the " + std::to_string(count) + " named values, found " +
                           std::to_string(value));
        }
    }
    void Colour(const std::string& path, const Color& color)
    {
        Unit(path + ".r", color.r);
        Unit(path + ".g", color.g);
        Unit(path + ".b", color.b);
        Unit(path + ".a", color.a);
    }

private:
    std::string_view m_file;
    std::vector<Diagnostic>& m_out;
};

void CheckParticleType(Checker& check, const std::string& at, const ParticleTypeDef& type)
{
    check.Unit(at + ".lifeBase", type.lifeBase);
    check.NonNegative(at + ".lifeFromIntensity", type.lifeFromIntensity);
    check.Positive(at + ".lifetime", type.lifetime);
    check.Finite(at + ".inheritA", type.inheritA);
    check.Finite(at + ".inheritB", type.inheritB);
    check.Finite(at + ".slipFactor", type.slipFactor);
    check.Finite(at + ".normalSpeed", type.normalSpeed);
    check.NonNegative(at + ".spread", type.spread);
    check.Finite(at + ".gravityScale", type.gravityScale);
    check.NonNegative(at + ".drag", type.drag);
    check.Positive(at + ".radius", type.radius);
    check.Unit(at + ".restitution", type.restitution);
    check.NonNegative(at + ".friction", type.friction);
    check.Enum(at + ".backend", static_cast<int>(type.backend), 2);
    check.Positive(at + ".density", type.density);
    check.Colour(at + ".colorStart", type.colorStart);
    check.Colour(at + ".colorEnd", type.colorEnd);
    check.Positive(at + ".sizeStart", type.sizeStart);
    check.Positive(at + ".sizeEnd", type.sizeEnd);
    check.NonNegative(at + ".streak", type.streak);
}

void CheckRule(Checker& check, const std::string& at, const RuleDef& rule, const EffectsConfig& config)
{
    if (!config.FindMaterial(rule.materialA).IsValid())
    {
        check.Fail(at + ".materialA", "unknown material \"" + rule.materialA + "\"");
    }
    if (!config.FindMaterial(rule.materialB).IsValid())
    {
        check.Fail(at + ".materialB", "unknown material \"" + rule.materialB + "\"");
    }
    if (!config.FindParticleType(rule.particleType).IsValid())
    {
        check.Fail(at + ".particleType", "unknown particle type \"" + rule.particleType + "\"");
    }
    check.Enum(at + ".intensity.speed", static_cast<int>(rule.intensity.speed), 2);
    check.Enum(at + ".intensity.friction", static_cast<int>(rule.intensity.friction), 5);
    check.Enum(at + ".intensity.points", static_cast<int>(rule.intensity.points), 2);
    check.NonNegative(at + ".intensity.impulseWeight", rule.intensity.impulseWeight);
    check.NonNegative(at + ".threshold", rule.threshold);
    check.Enum(at + ".emission", static_cast<int>(rule.emission), 2);
    check.NonNegative(at + ".ratePerIntensity", rule.ratePerIntensity);
    check.NonNegative(at + ".maxRate", rule.maxRate);
    check.Enum(at + ".placement", static_cast<int>(rule.placement), 2);
    check.NonNegative(at + ".scrapeEndDelay", rule.scrapeEndDelay);
    check.NonNegative(at + ".impactThreshold", rule.impactThreshold);
    check.NonNegative(at + ".burstPerSpeed", rule.burstPerSpeed);
    check.NonNegative(at + ".burstMax", rule.burstMax);
}

// Both bounds finite and, when both are set, a non-empty open interval.
void CheckRange(Checker& check, const std::string& at, const char* aboveKey,
                const std::optional<float>& above, const char* belowKey, const std::optional<float>& below)
{
    if (above)
    {
        check.Finite(at + "." + aboveKey, *above);
    }
    if (below)
    {
        check.Finite(at + "." + belowKey, *below);
    }
    if (above && below && std::isfinite(*above) && std::isfinite(*below) && !(*below > *above))
    {
        std::ostringstream text;
        text << "expected a number > " << aboveKey << " (" << *above << "), found " << *below
             << " (no value would match)";
        check.Fail(at + "." + belowKey, text.str());
    }
}

void CheckAssignment(Checker& check, const std::string& at, const MaterialAssignment& rule,
                     const EffectsConfig& config)
{
    if (!config.FindMaterial(rule.material).IsValid())
    {
        check.Fail(at + ".material", "unknown material \"" + rule.material + "\"");
    }
    if (rule.bodyName.empty())
    {
        check.Fail(at + ".bodyName", "expected a non-empty pattern (\"*\" matches any name)");
    }
    if (rule.fixtureName.empty())
    {
        check.Fail(at + ".fixtureName", "expected a non-empty pattern (\"*\" matches any name)");
    }
    check.Enum(at + ".bodyType", static_cast<int>(rule.bodyType), 4);
    CheckRange(check, at, "frictionAbove", rule.frictionAbove, "frictionBelow", rule.frictionBelow);
    CheckRange(check, at, "massAbove", rule.massAbove, "massBelow", rule.massBelow);
}

} // namespace

std::vector<Diagnostic> Validate(const EffectsConfig& config, std::string_view file)
{
    std::vector<Diagnostic> out;
    Checker check(file, out);

    if (config.materials.size() >= MaterialId::kNone)
    {
        check.Fail("materials",
                   "expected at most 65534 materials, found " + std::to_string(config.materials.size()));
    }
    std::set<std::string_view> seen;
    for (std::size_t i = 0; i < config.materials.size(); ++i)
    {
        const std::string at = "materials[" + std::to_string(i) + "]";
        if (config.materials[i].empty())
        {
            check.Fail(at, "expected a non-empty name");
        }
        else if (!seen.insert(config.materials[i]).second)
        {
            check.Fail(at, "duplicate material \"" + config.materials[i] + "\"");
        }
    }

    if (config.particleTypes.size() >= ParticleTypeId::kNone)
    {
        check.Fail("particleTypes", "expected at most 65534 particle types");
    }
    seen.clear();
    for (std::size_t i = 0; i < config.particleTypes.size(); ++i)
    {
        const std::string at = "particleTypes[" + std::to_string(i) + "]";
        const ParticleTypeDef& type = config.particleTypes[i];
        if (type.name.empty())
        {
            check.Fail(at + ".name", "expected a non-empty name");
        }
        else if (!seen.insert(type.name).second)
        {
            check.Fail(at + ".name", "duplicate particle type \"" + type.name + "\"");
        }
        CheckParticleType(check, at, type);
    }

    if (config.rules.size() >= RuleId::kNone)
    {
        check.Fail("rules", "expected at most 65534 rules");
    }
    std::set<std::pair<std::string_view, std::string_view>> pairs;
    for (std::size_t i = 0; i < config.rules.size(); ++i)
    {
        const std::string at = "rules[" + std::to_string(i) + "]";
        const RuleDef& rule = config.rules[i];
        CheckRule(check, at, rule, config);
        std::string_view a = rule.materialA;
        std::string_view b = rule.materialB;
        if (b < a)
        {
            std::swap(a, b);
        }
        if (!pairs.insert({a, b}).second)
        {
            check.Fail(at, "a second rule for the pair " + std::string(a) + "+" + std::string(b));
        }
    }

    for (std::size_t i = 0; i < config.assignments.size(); ++i)
    {
        CheckAssignment(check, "assignments[" + std::to_string(i) + "]", config.assignments[i], config);
    }

    if (config.budget.capacity < 1 || config.budget.capacity > 4000000)
    {
        check.Fail("budget.capacity",
                   "expected a number in [1, 4000000], found " + std::to_string(config.budget.capacity));
    }
    check.Enum("budget.recycle", static_cast<int>(config.budget.recycle), 2);
    if (config.budget.contacts > 1000000)
    {
        check.Fail("budget.contacts",
                   "expected a number in [0, 1000000], found " + std::to_string(config.budget.contacts));
    }
    return out;
}

} // namespace cfx
