#include "panels.h"

#include <imgui.h>

namespace cfx::testbed
{

void ScenesPanel(Session& session, DrawToggles& toggles, std::string& error)
{
    for (const SceneEntry* entry : session.Listed())
    {
        const bool current = entry == &session.Entry();
        const bool file = FindScene(entry->name) != entry; // the scene file: listed first
        const std::string label = std::string(entry->name) + (file ? "  (file)" : "");
        if (ImGui::Selectable(label.c_str(), current) && !current)
        {
            try
            {
                session.Open(*entry);
                error.clear();
            }
            catch (const InputError& problem)
            {
                error = problem.what();
            }
        }
        if (ImGui::IsItemHovered())
        {
            WrappedTooltip(entry->title);
        }
    }
    ImGui::TextWrapped("%s", std::string(session.Entry().title).c_str());
    for (const Diagnostic& warning : session.Warnings())
    {
        WrappedText(kWarningColour, warning.ToString());
    }
    if (!error.empty())
    {
        WrappedText(kErrorColour, error);
    }

    ImGui::Separator();
    ImGui::Checkbox("Pause (p)", &session.paused);
    ImGui::SameLine();
    if (ImGui::Button("Step (o)"))
    {
        session.paused = true;
        session.stepOnce = true;
    }
    ImGui::SameLine();
    if (ImGui::Button("Restart (r)"))
    {
        RestartScene(session, error);
    }
    if (session.Sim().GetCar())
    {
        ImGui::Checkbox("Follow the car (f)", &session.followCar);
        ImGui::SameLine();
        bool fourWheel = session.FourWheelDrive();
        if (ImGui::Checkbox("4WD (4)", &fourWheel))
        {
            session.ToggleFourWheelDrive();
        }
        ImGui::TextWrapped("%s", session.Manual() ? "Driving: keys a / d, s brakes"
                                 : session.Entry().drive.empty()
                                     ? "Driving: no script (a, s, d drive)"
                                     : "Driving: the scene's script (a, s, d take over)");
    }
    ImGui::Checkbox("Shapes", &toggles.shapes);
    ImGui::SameLine();
    ImGui::Checkbox("Joints", &toggles.joints);
    ImGui::SameLine();
    ImGui::Checkbox("Particles", &toggles.particles);
    ImGui::Checkbox("Events##rings", &toggles.events); // not the Events panel's header
    ImGui::SameLine();
    ImGui::Checkbox("Scale bar", &toggles.scaleBar);
    if (ImGui::TreeNode("Debug drawing"))
    {
        DebugLayers& debug = toggles.debug;
        ImGui::Checkbox("Contact points by intensity", &debug.manifoldPoints);
        ImGui::TextWrapped("Blue: 0, green: the rule's threshold, red: twice it; a white ring: above it.");
        ImGui::Checkbox("Normals", &debug.normals);
        ImGui::SameLine();
        ImGui::Checkbox("Normal impulses", &debug.impulses);
        ImGui::Checkbox("Rule names", &debug.ruleNames);
        ImGui::SameLine();
        ImGui::Checkbox("Particle velocities", &debug.velocities);
        ImGui::TreePop();
    }
    if (ImGui::TreeNode("Keys"))
    {
        for (const KeyBinding& binding : KeyBindings())
        {
            if (binding.name != nullptr)
            {
                ImGui::TextWrapped("%-9s %s", binding.name, binding.meaning);
            }
        }
        ImGui::TreePop();
    }
}

} // namespace cfx::testbed
