#include "panels.h"

#include <deque>
#include <imgui.h>

namespace cfx::testbed
{

void StatisticsPanel(const Session& session, const StepTimeWindow& times, float frameMs)
{
    const Simulation& simulation = session.Sim();
    const Effects& effects = simulation.GetEffects();
    const EffectsConfig& config = effects.Config();
    const EffectsStats& stats = effects.Stats();
    const Simulation::StepTimes mean = times.Mean();

    ImGui::Text("t = %.2f s, step %llu, %.0f Hz", static_cast<double>(simulation.Time()),
                static_cast<unsigned long long>(simulation.Steps()),
                static_cast<double>(1.0f / simulation.Dt()));
    ImGui::Text("ms per step: world %.3f, effects %.3f", mean.worldMs, mean.effectsMs);
    ImGui::Text("ms per frame: %.1f", static_cast<double>(frameMs));

    constexpr ImGuiTableFlags kTable =
        ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
    if (ImGui::BeginTable("rules", 5, kTable))
    {
        // The numbers fit their headers; the rule's name takes the rest of the width.
        ImGui::TableSetupColumn("rule", ImGuiTableColumnFlags_WidthStretch);
        ImGui::TableSetupColumn("contacts", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("made", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("intensity", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("impacts", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < config.rules.size(); ++i)
        {
            const RuleDef& rule = config.rules[i];
            const RuleStats& counts = stats.rules[i];
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(
                PairName(rule).c_str()); // as the CLI, the events and the stats file name it
            ImGui::TableNextColumn();
            ImGui::Text("%u", counts.contacts);
            ImGui::TableNextColumn();
            ImGui::Text("%llu", static_cast<unsigned long long>(counts.spawned));
            ImGui::TableNextColumn();
            ImGui::Text("%.2f", static_cast<double>(counts.intensityMaxLastStep));
            ImGui::TableNextColumn();
            ImGui::Text("%llu", static_cast<unsigned long long>(counts.impacts));
        }
        ImGui::EndTable();
    }

    // Live particles by type, counted from the pool itself.
    std::vector<std::uint32_t> live(config.particleTypes.size(), 0);
    const ParticleView view = effects.Particles();
    for (std::uint32_t i = 0; i < view.count; ++i)
    {
        ++live[view.type[view.Slot(i)]];
    }
    if (ImGui::BeginTable("types", 3, kTable))
    {
        ImGui::TableSetupColumn("particles");
        ImGui::TableSetupColumn("live");
        ImGui::TableSetupColumn("made");
        ImGui::TableHeadersRow();
        for (std::size_t i = 0; i < config.particleTypes.size(); ++i)
        {
            const Color& color = config.particleTypes[i].colorStart;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::ColorButton("##color", ImVec4(color.r, color.g, color.b, 1.0f),
                               ImGuiColorEditFlags_NoTooltip,
                               ImVec2(ImGui::GetTextLineHeight(), ImGui::GetTextLineHeight()));
            ImGui::SameLine();
            ImGui::TextUnformatted(config.particleTypes[i].name.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%u", live[i]);
            ImGui::TableNextColumn();
            ImGui::Text("%llu", static_cast<unsigned long long>(stats.spawnedByType[i]));
        }
        ImGui::EndTable();
    }
    ImGui::Text("live %u of %u, recycled %llu, inside solids %llu", stats.live, config.budget.capacity,
                static_cast<unsigned long long>(stats.recycled),
                static_cast<unsigned long long>(stats.spawnedInsideSolid));
}

} // namespace cfx::testbed

namespace cfx::testbed
{

void EventsPanel(const Session& session)
{
    const std::deque<LoggedEvent>& entries = session.Events().Entries();
    // Wrapped, never cut off at the panel's edge.
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("scrapes and impacts as they happen; rings mark the last half second");
    ImGui::PopStyleColor();
    ImGui::BeginChild("events", ImVec2(0.0f, 160.0f), true);
    for (auto it = entries.rbegin(); it != entries.rend(); ++it)
    {
        const bool impact = it->event.type == EffectEventType::impact;
        ImGui::PushStyleColor(ImGuiCol_Text,
                              impact ? ImVec4(1.0f, 0.45f, 0.35f, 1.0f) : ImVec4(0.8f, 0.85f, 0.9f, 1.0f));
        ImGui::TextWrapped("%s", it->text.c_str());
        ImGui::PopStyleColor();
    }
    ImGui::EndChild();
}

} // namespace cfx::testbed
