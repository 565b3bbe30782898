#include "panels.h"

#include "sound_panel.h"

#include <imgui.h>

namespace cfx::testbed
{

void WrappedText(const std::array<float, 3>& colour, const std::string& text)
{
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(colour[0], colour[1], colour[2], 1.0f));
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
}

void WrappedTooltip(std::string_view text)
{
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(35.0f * ImGui::GetFontSize());
    ImGui::TextUnformatted(text.data(), text.data() + text.size());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

void StepTimeWindow::Record(const Simulation::StepTimes& times)
{
    m_times[m_next] = times;
    m_next = (m_next + 1) % kCount;
    m_count = std::min(m_count + 1, kCount);
}

Simulation::StepTimes StepTimeWindow::Mean() const
{
    Simulation::StepTimes mean;
    if (m_count == 0)
    {
        return mean;
    }
    for (std::size_t i = 0; i < m_count; ++i)
    {
        mean.worldMs += m_times[i].worldMs;
        mean.effectsMs += m_times[i].effectsMs;
    }
    mean.worldMs /= static_cast<double>(m_count);
    mean.effectsMs /= static_cast<double>(m_count);
    return mean;
}

void DrawPanels(Session& session, PanelState& state, int windowWidth, int windowHeight, int width)
{
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(windowWidth - width), 0.0f));
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(width), static_cast<float>(windowHeight)));
    constexpr ImGuiWindowFlags kFixed =
        ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse;
    if (ImGui::Begin("contactfx testbed", nullptr, kFixed))
    {
        if (ImGui::CollapsingHeader("Scenes", ImGuiTreeNodeFlags_DefaultOpen))
        {
            ScenesPanel(session, state.toggles, state.sceneError);
        }
        if (ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen))
        {
            StatisticsPanel(session, state.times, state.frameMs);
        }
        if (ImGui::CollapsingHeader("Events", ImGuiTreeNodeFlags_DefaultOpen))
        {
            EventsPanel(session);
        }
        // The column is narrow and does not scroll sideways: these panels' messages wrap at its edge (a
        // trial found messages, problems and the sound line cut off there). Not the tables above: their
        // names would wrap at every column edge.
        ImGui::PushTextWrapPos(0.0f);
        if (ImGui::CollapsingHeader("Sound"))
        {
            SoundPanel(session);
        }
        if (ImGui::CollapsingHeader("Effects"))
        {
            EffectsPanel(session, state.editor);
        }
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

} // namespace cfx::testbed
