// No allocation per step in the sound layer: once the demo has run its first second, neither
// SoundVoices::Step nor SoundSynth::Render allocates (the synthesizer's output buffer is the caller's and is
// reserved here).
#include "allocation_counter.h"
#include "contactfx/sound_synth.h"
#include "harness/scenes.h"
#include "harness/simulation.h"

#include <filesystem>
#include <gtest/gtest.h>

namespace cfx::test
{

TEST(SoundAllocation, NoneInTheDemoAfterItsFirstSecond)
{
    const SceneEntry& tutorial = *FindScene("tutorial");
    Simulation simulation(
        SceneSimulationDef(tutorial, std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes"));
    SoundVoices voices(simulation.GetEffects().Config());
    SoundSynth synth(simulation.GetEffects().Config());
    std::vector<std::int16_t> samples;
    samples.reserve(48000 * 21);
    long allocations = 0;
    std::uint64_t started = 0;
    for (int step = 0; step < 1200; ++step)
    {
        StepScene(tutorial, simulation);
        const long before = Allocations();
        voices.Step(simulation.GetEffects().Events(), simulation.Dt());
        synth.Render(voices.Voices(), voices.Time(), samples);
        if (step >= 60)
        {
            allocations += Allocations() - before;
        }
        started += voices.Changes().size();
    }
    EXPECT_GT(started, 10u); // voices came and went
    EXPECT_EQ(allocations, 0);
}

} // namespace cfx::test
