// The sound panel (sound_panel.h).
//
// The panel follows the simulation from outside, as an application would: it feeds SoundVoices with the
// events the session logged since the last frame, grouped by the step that reported them, with the time
// between those steps as dt, then steps it on to the simulation's time. Voices therefore change once per
// frame at the most, which is what a meter needs. The events' fixtures are read (for their bodies) after
// the frame's steps; the testbed destroys fixtures only when it opens a scene, which clears the log.
//
// Live playback (CONTACTFX_TESTBED_SDL_AUDIO, defined when CMake found SDL2): SoundSynth renders up to the
// simulated time each frame and the samples are queued on an SDL audio device, at most a quarter second
// ahead; without SDL2, or without a device, the panel shows the voices only.
#include "sound_panel.h"

#include "contactfx/sound_synth.h"

#include <imgui.h>
#include <memory>
#include <string>
#include <vector>

#ifdef CONTACTFX_TESTBED_SDL_AUDIO
#include <SDL.h>
#endif

namespace cfx::testbed
{

namespace
{

constexpr const char* kKinds[] = {"scrape", "impact", "hits"};

struct PanelSound
{
    EffectsConfig config;
    const Simulation* simulation = nullptr;
    std::unique_ptr<SoundVoices> voices;
    std::unique_ptr<SoundSynth> synth;
    float time = 0.0f; ///< s, simulated time the voices have reached
    bool play = false;
    std::string problem; ///< why playback is off
#ifdef CONTACTFX_TESTBED_SDL_AUDIO
    SDL_AudioDeviceID device = 0;
#endif
    std::vector<std::int16_t> samples;
};

void Reset(PanelSound& sound, const Session& session)
{
    sound.simulation = &session.Sim();
    sound.config = session.Sim().GetEffects().Config();
    sound.voices = std::make_unique<SoundVoices>(sound.config);
    sound.synth = std::make_unique<SoundSynth>(sound.config);
    sound.time = session.Sim().Time();
    sound.samples.clear();
    // The synthesizer's clock starts at 0: bring it to now silently.
    sound.synth->Render({}, sound.time, sound.samples);
    sound.samples.clear();
}

void Follow(PanelSound& sound, const Session& session)
{
    const Simulation& simulation = session.Sim();
    if (sound.voices == nullptr || sound.simulation != &simulation || simulation.Time() < sound.time ||
        !(simulation.GetEffects().Config() == sound.config))
    {
        Reset(sound, session);
    }
    std::vector<EffectEvent> step;
    float stepTime = sound.time;
    auto flush = [&]
    {
        if (stepTime > sound.time)
        {
            sound.voices->Step(step, stepTime - sound.time);
            sound.time = stepTime;
        }
        step.clear();
    };
    for (const LoggedEvent& entry : session.Events().Entries())
    {
        if (entry.time <= sound.time)
        {
            continue;
        }
        if (entry.time != stepTime)
        {
            flush();
            stepTime = entry.time;
        }
        step.push_back(entry.event);
    }
    flush();
    stepTime = simulation.Time();
    flush();
}

void Playback(PanelSound& sound)
{
#ifdef CONTACTFX_TESTBED_SDL_AUDIO
    ImGui::Checkbox("play through the audio device", &sound.play);
    if (sound.play && sound.device == 0 && sound.problem.empty())
    {
        SDL_AudioSpec want{};
        want.freq = SoundSynth::kSampleRate;
        want.format = AUDIO_S16SYS;
        want.channels = 1;
        want.samples = 1024;
        if (SDL_InitSubSystem(SDL_INIT_AUDIO) != 0 ||
            (sound.device = SDL_OpenAudioDevice(nullptr, 0, &want, nullptr, 0)) == 0)
        {
            sound.problem = std::string("no audio device: ") + SDL_GetError();
        }
        else
        {
            SDL_PauseAudioDevice(sound.device, 0);
        }
    }
    sound.synth->Render(sound.voices->Voices(), sound.voices->Time(), sound.samples);
    if (sound.play && sound.device != 0)
    {
        constexpr Uint32 kMostQueued = SoundSynth::kSampleRate / 4 * sizeof(std::int16_t);
        if (SDL_GetQueuedAudioSize(sound.device) > kMostQueued)
        {
            SDL_ClearQueuedAudio(sound.device); // fell behind (a pause, a slow frame): start from now
        }
        SDL_QueueAudio(sound.device, sound.samples.data(),
                       static_cast<Uint32>(sound.samples.size() * sizeof(std::int16_t)));
    }
    else if (sound.device != 0)
    {
        SDL_ClearQueuedAudio(sound.device);
    }
    sound.samples.clear();
    if (!sound.problem.empty())
    {
        ImGui::TextDisabled("%s", sound.problem.c_str());
    }
#else
    (void)sound;
    ImGui::TextDisabled("built without SDL2: no live playback (contactfx run --audio FILE.wav writes it)");
#endif
}

} // namespace

void SoundPanel(const Session& session)
{
    static PanelSound sound;
    Follow(sound, session);
    const SoundStats& stats = sound.voices->Stats();
    ImGui::TextDisabled("voices from the events: hysteresis, merge window, cooldown, cap (docs/sound.md)");
    ImGui::Text("%zu of at most %u sounding; started %llu scrape, %llu impact; cut %llu",
                sound.voices->Voices().size(), sound.config.sound.maxVoices,
                static_cast<unsigned long long>(stats.scrapeVoices),
                static_cast<unsigned long long>(stats.impactVoices),
                static_cast<unsigned long long>(stats.voicesCut));
    constexpr ImGuiTableFlags kTable =
        ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp;
    ImGui::PushTextWrapPos(-1.0f); // a table's names stay on one line (the panel's messages wrap)
    if (ImGui::BeginTable("voices", 4, kTable))
    {
        ImGui::TableSetupColumn("voice");
        ImGui::TableSetupColumn("kind");
        ImGui::TableSetupColumn("pair");
        ImGui::TableSetupColumn("loudness");
        ImGui::TableHeadersRow();
        for (const SoundVoice& voice : sound.voices->Voices())
        {
            const std::string name = VoiceName(voice, sound.config);
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::Text("#%u", voice.id);
            ImGui::TableNextColumn();
            ImGui::Text("%s%s", kKinds[static_cast<int>(voice.kind)], voice.releasing ? " (release)" : "");
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name.c_str());
            ImGui::TableNextColumn();
            char label[16];
            std::snprintf(label, sizeof label, "%.2f", static_cast<double>(voice.loudness));
            ImGui::ProgressBar(voice.loudness, ImVec2(-1.0f, 0.0f), label);
        }
        ImGui::EndTable();
    }
    ImGui::PopTextWrapPos();
    Playback(sound);
}

} // namespace cfx::testbed
