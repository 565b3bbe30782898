// The live effects editor. Widgets edit a draft; when an edit is finished (a field left, a combo or
// checkbox changed) and the draft is valid, it replaces the simulation's effects at once. An invalid
// draft is never applied: its problems are listed, field by field, until they are fixed.
#include "contactfx/scene/effects_json.h"
#include "panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>
#include <span>

namespace cfx::testbed
{

namespace
{

// Each widget helper returns true when an edit of it is finished.
bool Finished()
{
    return ImGui::IsItemDeactivatedAfterEdit();
}

bool Float(const char* label, float& value, float speed, float low, float high)
{
    ImGui::DragFloat(label, &value, speed, low, high, "%.3f");
    return Finished();
}

bool Text(const char* label, std::string& value)
{
    ImGui::InputText(label, &value);
    return Finished();
}

template <typename Enum> bool EnumCombo(const char* label, Enum& value, std::span<const char* const> names)
{
    int index = static_cast<int>(value);
    if (ImGui::Combo(label, &index, names.data(), static_cast<int>(names.size())))
    {
        value = static_cast<Enum>(index);
        return true;
    }
    return false;
}

bool NameCombo(const char* label, std::string& value, const std::vector<std::string>& names)
{
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str()))
    {
        for (const std::string& name : names)
        {
            if (ImGui::Selectable(name.c_str(), name == value))
            {
                changed = name != value;
                value = name;
            }
        }
        ImGui::EndCombo();
    }
    return changed;
}

bool ColorField(const char* label, Color& color)
{
    ImGui::ColorEdit4(label, &color.r, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_AlphaBar);
    return Finished();
}

bool Bits(const char* label, std::uint16_t& bits)
{
    ImGui::InputScalar(label, ImGuiDataType_U16, &bits, nullptr, nullptr, "%04X",
                       ImGuiInputTextFlags_CharsHexadecimal);
    return Finished();
}

constexpr const char* kSpeedModes[] = {"full", "tangential"};
constexpr const char* kFrictionMixes[] = {"product", "sqrt", "min", "max", "mean"};
constexpr const char* kPoints[] = {"first", "all"};
constexpr const char* kEmissions[] = {"rate", "perStep"};
constexpr const char* kPlacements[] = {"surface", "tutorialDrop"};
constexpr const char* kBackends[] = {"pool", "body"};

std::string Unique(const std::string& stem, std::size_t number, auto&& taken)
{
    std::string name = stem + " " + std::to_string(number);
    while (taken(name))
    {
        name += "'";
    }
    return name;
}

// Each item through `edit` (which sets its bool to ask for the item's removal), then a button that
// appends `make()`. True when an edit finished or the list changed.
template <typename T, typename Edit, typename Make>
bool EditList(std::vector<T>& items, const char* addLabel, Edit&& edit, Make&& make)
{
    bool finished = false;
    std::size_t remove = items.size();
    for (std::size_t i = 0; i < items.size(); ++i)
    {
        ImGui::PushID(static_cast<int>(i));
        bool removeThis = false;
        finished |= edit(items[i], removeThis);
        remove = removeThis ? i : remove;
        ImGui::PopID();
    }
    if (remove < items.size())
    {
        items.erase(items.begin() + static_cast<std::ptrdiff_t>(remove));
        finished = true;
    }
    if (ImGui::Button(addLabel))
    {
        items.push_back(make());
        finished = true;
    }
    return finished;
}

bool MaterialsTab(EffectsConfig& draft)
{
    return EditList(
        draft.materials, "Add material",
        [](std::string& material, bool& remove)
        {
            const bool finished = Text("##name", material);
            ImGui::SameLine();
            remove = ImGui::SmallButton("remove");
            return finished;
        },
        [&]
        {
            return Unique("material", draft.materials.size() + 1,
                          [&](const std::string& name) { return draft.FindMaterial(name).IsValid(); });
        });
}

bool ParticleTypeFields(ParticleTypeDef& type)
{
    bool finished = Text("name", type.name);
    finished |= Float("lifeBase", type.lifeBase, 0.01f, 0.0f, 1.0f);
    finished |= Float("lifeFromIntensity", type.lifeFromIntensity, 0.01f, 0.0f, 10.0f);
    finished |= Float("lifetime (s)", type.lifetime, 0.01f, 0.01f, 60.0f);
    finished |= Float("inheritA", type.inheritA, 0.01f, -5.0f, 5.0f);
    finished |= Float("inheritB", type.inheritB, 0.01f, -5.0f, 5.0f);
    finished |= Float("slipFactor", type.slipFactor, 0.01f, -5.0f, 5.0f);
    finished |= Float("normalSpeed (m/s)", type.normalSpeed, 0.05f, -50.0f, 50.0f);
    finished |= Float("spread (m/s)", type.spread, 0.05f, 0.0f, 50.0f);
    finished |= Float("gravityScale", type.gravityScale, 0.01f, -10.0f, 10.0f);
    finished |= Float("drag (1/s)", type.drag, 0.05f, 0.0f, 100.0f);
    finished |= ImGui::Checkbox("collide", &type.collide);
    finished |= Float("radius (m)", type.radius, 0.001f, 0.001f, 1.0f);
    finished |= Float("restitution", type.restitution, 0.01f, 0.0f, 1.0f);
    finished |= Float("friction", type.friction, 0.01f, 0.0f, 10.0f);
    finished |= Bits("categoryBits", type.categoryBits);
    finished |= Bits("maskBits", type.maskBits);
    finished |= EnumCombo("backend", type.backend, kBackends);
    finished |= Float("density (kg/m2)", type.density, 0.05f, 0.01f, 100.0f);
    finished |= ColorField("colorStart", type.colorStart);
    finished |= ColorField("colorEnd", type.colorEnd);
    finished |= Float("sizeStart (m)", type.sizeStart, 0.005f, 0.001f, 10.0f);
    finished |= Float("sizeEnd (m)", type.sizeEnd, 0.005f, 0.001f, 10.0f);
    finished |= Float("streak (s)", type.streak, 0.001f, 0.0f, 1.0f);
    return finished;
}

bool ParticleTypesTab(EffectsConfig& draft)
{
    return EditList(
        draft.particleTypes, "Add particle type",
        [](ParticleTypeDef& type, bool& remove)
        {
            bool finished = false;
            if (ImGui::TreeNode("type", "%s", type.name.c_str()))
            {
                finished = ParticleTypeFields(type);
                remove = ImGui::SmallButton("remove this type");
                ImGui::TreePop();
            }
            return finished;
        },
        [&]
        {
            ParticleTypeDef type =
                draft.particleTypes.empty() ? ParticleTypeDef{} : draft.particleTypes.back();
            type.name =
                Unique("type", draft.particleTypes.size() + 1,
                       [&](const std::string& name) { return draft.FindParticleType(name).IsValid(); });
            return type;
        });
}

bool RuleFields(RuleDef& rule, const EffectsConfig& draft)
{
    std::vector<std::string> typeNames;
    for (const ParticleTypeDef& type : draft.particleTypes)
    {
        typeNames.push_back(type.name);
    }
    bool finished = NameCombo("materialA", rule.materialA, draft.materials);
    finished |= NameCombo("materialB", rule.materialB, draft.materials);
    finished |= NameCombo("particleType", rule.particleType, typeNames);
    finished |= EnumCombo("speed", rule.intensity.speed, kSpeedModes);
    finished |= EnumCombo("friction mix", rule.intensity.friction, kFrictionMixes);
    finished |= EnumCombo("points", rule.intensity.points, kPoints);
    finished |= Float("impulseWeight (1/N)", rule.intensity.impulseWeight, 0.001f, 0.0f, 10.0f);
    finished |= Float("threshold", rule.threshold, 0.05f, 0.0f, 1000.0f);
    finished |= EnumCombo("emission", rule.emission, kEmissions);
    finished |= Float("ratePerIntensity", rule.ratePerIntensity, 0.5f, 0.0f, 100000.0f);
    finished |= Float("maxRate (1/s)", rule.maxRate, 1.0f, 0.0f, 1000000.0f);
    finished |= EnumCombo("placement", rule.placement, kPlacements);
    finished |= Float("scrapeEndDelay (s)", rule.scrapeEndDelay, 0.01f, 0.0f, 10.0f);
    finished |= Float("impactThreshold (m/s)", rule.impactThreshold, 0.05f, 0.0f, 100.0f);
    finished |= Float("burstPerSpeed", rule.burstPerSpeed, 0.1f, 0.0f, 1000.0f);
    finished |= Float("burstMax", rule.burstMax, 1.0f, 0.0f, 100000.0f);
    return finished;
}

bool RulesTab(EffectsConfig& draft)
{
    bool finished = EditList(
        draft.rules, "Add rule",
        [&](RuleDef& rule, bool& remove)
        {
            bool edited = false;
            if (ImGui::TreeNode("rule", "%s + %s -> %s", rule.materialA.c_str(), rule.materialB.c_str(),
                                rule.particleType.c_str()))
            {
                edited = RuleFields(rule, draft);
                remove = ImGui::SmallButton("remove this rule");
                ImGui::TreePop();
            }
            return edited;
        },
        [&]
        {
            RuleDef rule;
            rule.materialA = draft.materials.empty() ? "" : draft.materials.front();
            rule.materialB = rule.materialA;
            rule.particleType = draft.particleTypes.empty() ? "" : draft.particleTypes.front().name;
            return rule;
        });
    int capacity = static_cast<int>(draft.budget.capacity);
    ImGui::InputInt("budget capacity", &capacity, 256, 4096);
    if (Finished())
    {
        draft.budget.capacity = static_cast<std::uint32_t>(std::max(capacity, 0));
        finished = true;
    }
    int contacts = static_cast<int>(draft.budget.contacts);
    ImGui::InputInt("budget contacts", &contacts, 64, 1024);
    if (Finished())
    {
        draft.budget.contacts = static_cast<std::uint32_t>(std::max(contacts, 0));
        finished = true;
    }
    return finished;
}

} // namespace

void EffectsPanel(Session& session, EffectsEditor& editor)
{
    editor.Follow(session);
    bool finished = false;
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.55f); // room for the field names
    if (ImGui::BeginTabBar("effects"))
    {
        if (ImGui::BeginTabItem("Materials"))
        {
            finished |= MaterialsTab(editor.draft);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Particle types"))
        {
            finished |= ParticleTypesTab(editor.draft);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Rules"))
        {
            finished |= RulesTab(editor.draft);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    ImGui::PopItemWidth();
    if (finished)
    {
        editor.Apply(session);
    }
    ImGui::Separator();
    if (ImGui::Button("Revert"))
    {
        editor.Follow(session, true);
    }
    ImGui::SameLine();
    if (ImGui::Button("Save as"))
    {
        editor.Save();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputText("##path", &editor.savePath);
    if (!editor.message.empty())
    {
        const ImVec4 color =
            editor.messageIsError ? ImVec4(1.0f, 0.4f, 0.4f, 1.0f) : ImVec4(0.5f, 0.9f, 0.5f, 1.0f);
        ImGui::TextColored(color, "%s", editor.message.c_str());
    }
    for (const Diagnostic& problem : editor.problems)
    {
        ImGui::TextColored(ImVec4(1.0f, 0.4f, 0.4f, 1.0f), "%s: %s", problem.path.c_str(),
                           problem.message.c_str());
    }
}

} // namespace cfx::testbed
