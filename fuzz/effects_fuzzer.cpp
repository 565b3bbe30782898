// libFuzzer target: the effects config reader.
//
// Any bytes must either load or be refused with diagnostics: no crash, no leak, no undefined behaviour
// (the CI build adds ASan and UBSan). A config that loads must also pass cfx::Validate, and saving it
// must give text that loads back to an equal config (the writer writes exactly what the reader reads).
#include "contactfx/scene/effects_json.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    cfx::EffectsConfig config;
    try
    {
        config = cfx::LoadEffectsString(text, "fuzz.effects.json");
    }
    catch (const cfx::InputError& error)
    {
        if (error.Diagnostics().empty())
        {
            __builtin_trap();
        }
        return 0;
    }
    if (!cfx::Validate(config).empty())
    {
        __builtin_trap();
    }
    try
    {
        if (!(cfx::LoadEffectsString(cfx::SaveEffectsString(config), "saved.effects.json") == config))
        {
            __builtin_trap(); // the round trip changed the config
        }
    }
    catch (const cfx::InputError&)
    {
        __builtin_trap(); // the writer wrote something the reader refuses
    }
    return 0;
}
