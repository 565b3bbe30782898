// The live effects editor. Widgets edit a draft; when an edit is finished (a field left, a combo or
// checkbox changed) and the draft is valid, it replaces the simulation's effects at once. An invalid
// draft is never applied: its problems are listed, field by field, until they are fixed.
#include "contactfx/config_fields.h"
#include "contactfx/scene/effects_json.h"
#include "field_widgets.h"
#include "panels.h"

#include <algorithm>
#include <imgui.h>
#include <imgui_stdlib.h>
#include <span>
#include <variant>

namespace cfx::testbed
{

namespace
{

// Each widget helper returns true when an edit of it is finished.
bool Finished()
{
    return ImGui::IsItemDeactivatedAfterEdit();
}

bool Text(const char* label, std::string& value)
{
    ImGui::InputText(label, &value);
    return Finished();
}

// `emptyName` (not null): the field may be empty, shown and offered as that.
bool NameCombo(const char* label, std::string& value, const std::vector<std::string>& names,
               const char* emptyName = nullptr)
{
    bool changed = false;
    if (ImGui::BeginCombo(label, value.empty() && emptyName != nullptr ? emptyName : value.c_str()))
    {
        if (emptyName != nullptr && ImGui::Selectable(emptyName, value.empty()))
        {
            changed = !value.empty();
            value.clear();
        }
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

std::vector<std::string> ParticleTypeNames(const EffectsConfig& draft)
{
    std::vector<std::string> names;
    for (const ParticleTypeDef& type : draft.particleTypes)
    {
        names.push_back(type.name);
    }
    return names;
}

// A number typed straight in (one click puts the cursor in the field), or stepped by its - and + buttons
// (ctrl: ten steps); kept in the field's range. Typing is applied when the field is left, a button at once.
bool Number(const char* label, float& value, const FieldRange& range, float step)
{
    const DragBounds bounds = DragBoundsOf(range, step);
    const bool typing = ImGui::GetIO().WantTextInput;
    const bool changed = ImGui::InputFloat(label, &value, bounds.speed, 10.0f * bounds.speed, kNumberFormat);
    value = std::clamp(value, bounds.low, bounds.high);
    return Finished() || (changed && !typing);
}

// One widget per field of the table, labelled with its name and unit and bounded by its range.
template <typename S>
bool EditFields(S& value, std::span<const Field<S>> fields, const EffectsConfig& draft,
                const char* prefix = "")
{
    bool finished = false;
    for (const Field<S>& field : fields)
    {
        const std::string label = LabelOf(prefix, field.name, field.unit);
        std::visit(
            [&](auto member)
            {
                using M = decltype(member);
                if constexpr (std::is_same_v<M, float S::*>)
                {
                    finished |= Number(label.c_str(), value.*member, field.range, field.step);
                }
                else if constexpr (std::is_same_v<M, std::optional<float> S::*>)
                {
                    // A checkbox sets or clears the bound; the number is edited while it is set.
                    std::optional<float>& bound = value.*member;
                    bool set = bound.has_value();
                    if (ImGui::Checkbox(("##set " + label).c_str(), &set))
                    {
                        bound = set ? std::optional<float>(std::clamp(0.0f, field.range.min, field.range.max))
                                    : std::nullopt;
                        finished = true;
                    }
                    ImGui::SameLine();
                    if (bound)
                    {
                        finished |= Number(label.c_str(), *bound, field.range, field.step);
                    }
                    else
                    {
                        ImGui::TextDisabled("%s: absent", label.c_str());
                    }
                }
                else if constexpr (std::is_same_v<M, bool S::*>)
                {
                    finished |= ImGui::Checkbox(label.c_str(), &(value.*member));
                }
                else if constexpr (std::is_same_v<M, std::string S::*>)
                {
                    if (field.text == TextRule::material)
                    {
                        finished |= NameCombo(label.c_str(), value.*member, draft.materials);
                    }
                    else if (field.text == TextRule::particleType)
                    {
                        finished |= NameCombo(label.c_str(), value.*member, ParticleTypeNames(draft));
                    }
                    else if (field.text == TextRule::optionalParticleType)
                    {
                        finished |= NameCombo(label.c_str(), value.*member, ParticleTypeNames(draft),
                                              "(the rule's particleType)");
                    }
                    else
                    {
                        finished |= Text(label.c_str(), value.*member);
                    }
                }
                else if constexpr (std::is_same_v<M, std::uint16_t S::*>)
                {
                    ImGui::InputScalar(label.c_str(), ImGuiDataType_U16, &(value.*member), nullptr, nullptr,
                                       "%04X", ImGuiInputTextFlags_CharsHexadecimal);
                    finished |= Finished();
                }
                else if constexpr (std::is_same_v<M, std::uint32_t S::*>)
                {
                    int number = static_cast<int>(value.*member);
                    const int step = static_cast<int>(field.step);
                    ImGui::InputInt(label.c_str(), &number, step, step * 16);
                    if (Finished())
                    {
                        const int low = static_cast<int>(field.range.min);
                        const int high = static_cast<int>(field.range.max);
                        value.*member = static_cast<std::uint32_t>(std::clamp(number, low, high));
                        finished = true;
                    }
                }
                else if constexpr (std::is_same_v<M, Color S::*>)
                {
                    ImGui::ColorEdit4(label.c_str(), &(value.*member).r,
                                      ImGuiColorEditFlags_Float | ImGuiColorEditFlags_AlphaBar);
                    finished |= Finished();
                }
                else if constexpr (std::is_same_v<M, ChoiceMember<S>>)
                {
                    const int index = member.get(value);
                    const bool known = index >= 0 && static_cast<std::size_t>(index) < field.choices.size();
                    const std::string shown =
                        known ? std::string(field.choices[static_cast<std::size_t>(index)])
                              : std::string("?");
                    if (ImGui::BeginCombo(label.c_str(), shown.c_str()))
                    {
                        for (std::size_t i = 0; i < field.choices.size(); ++i)
                        {
                            const std::string name(field.choices[i]);
                            if (ImGui::Selectable(name.c_str(), static_cast<int>(i) == index))
                            {
                                finished |= static_cast<int>(i) != index;
                                member.set(value, static_cast<int>(i));
                            }
                        }
                        ImGui::EndCombo();
                    }
                }
                else if constexpr (std::is_same_v<M, IntensityModel S::*>)
                {
                    ImGui::PushID(label.c_str());
                    finished |= EditFields(value.*member, IntensityFields(), draft,
                                           (std::string(field.name) + ".").c_str());
                    ImGui::PopID();
                }
            },
            field.member);
        if (ImGui::IsItemHovered() && !field.doc.empty())
        {
            WrappedTooltip(field.doc);
        }
    }
    return finished;
}

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

bool ParticleTypesTab(EffectsConfig& draft)
{
    return EditList(
        draft.particleTypes, "Add particle type",
        [&](ParticleTypeDef& type, bool& remove)
        {
            bool finished = false;
            if (ImGui::TreeNode("type", "%s", type.name.c_str()))
            {
                finished = EditFields(type, ParticleTypeFields(), draft);
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
                edited = EditFields(rule, RuleFields(), draft);
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
    return finished;
}

// The `sound` section's fields, then its sound rules (docs/sound.md).
bool SoundTab(EffectsConfig& draft)
{
    bool finished = EditFields(draft.sound, SoundFields(), draft);
    ImGui::TextDisabled("sound rules (a pair rule without one takes the defaults)");
    finished |= EditList(
        draft.sound.rules, "Add sound rule",
        [&](SoundRuleDef& rule, bool& remove)
        {
            bool edited = false;
            if (ImGui::TreeNode("sound rule", "%s + %s", rule.materialA.c_str(), rule.materialB.c_str()))
            {
                edited = EditFields(rule, SoundRuleFields(), draft);
                remove = ImGui::SmallButton("remove this sound rule");
                ImGui::TreePop();
            }
            return edited;
        },
        [&] { return EffectsEditor::NewSoundRule(draft); });
    return finished;
}

bool AssignmentsTab(EffectsConfig& draft)
{
    return EditList(
        draft.assignments, "Add assignment",
        [&](MaterialAssignment& assignment, bool& remove)
        {
            bool edited = false;
            if (ImGui::TreeNode("assignment", "%s", assignment.material.c_str()))
            {
                edited = EditFields(assignment, AssignmentFields(), draft);
                remove = ImGui::SmallButton("remove this assignment");
                ImGui::TreePop();
            }
            return edited;
        },
        [&]
        {
            MaterialAssignment assignment;
            assignment.material = draft.materials.empty() ? "" : draft.materials.front();
            return assignment;
        });
}

} // namespace

void EffectsPanel(Session& session, EffectsEditor& editor)
{
    editor.Follow(session);
    bool finished = false;
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.4f); // room for the field names and units
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
        if (ImGui::BeginTabItem("Assignments"))
        {
            finished |= AssignmentsTab(editor.draft);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Budget"))
        {
            finished |= EditFields(editor.draft.budget, BudgetFields(), editor.draft);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Sound"))
        {
            finished |= SoundTab(editor.draft);
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
        editor.Save(session);
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputText("##path", &editor.savePath);
    if (!editor.message.empty())
    {
        WrappedText(editor.messageIsError ? kErrorColour : kDoneColour, editor.message);
    }
    for (const Diagnostic& problem : editor.problems)
    {
        WrappedText(kErrorColour, problem.path + ": " + problem.message);
    }
}

} // namespace cfx::testbed
