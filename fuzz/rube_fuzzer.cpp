// libFuzzer target: the RUBE scene reader.
//
// Any bytes must either load or be refused with diagnostics: no crash, no Box2D assert, no leak, no
// undefined behaviour (the CI build adds ASan and UBSan). Properties checked beyond "does not crash":
// ValidateRubeString and LoadRubeString agree, a refused input has at least one diagnostic, and a scene
// that loads can be stepped and saved, and what is saved loads again unless stepping drove a value out of
// the reader's range.
#include "contactfx/scene/rube.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    cfx::SceneCounts counts;
    const bool valid = cfx::ValidateRubeString(text, "fuzz.json", &counts).empty();
    try
    {
        cfx::Scene scene = cfx::LoadRubeString(text, "fuzz.json");
        if (!valid || static_cast<std::size_t>(counts.bodies) != scene.bodies.size())
        {
            __builtin_trap(); // Validate refused (or miscounted) what Load accepted
        }
        for (int i = 0; i < 3; ++i)
        {
            scene.world->Step(1.0f / 60.0f, 8, 3);
        }
        try
        {
            cfx::LoadRubeString(cfx::SaveRubeString(scene), "saved.json");
        }
        catch (const cfx::InputError&)
        {
            // A world that blew up while stepping cannot be saved (non-finite values), or it saves values
            // beyond the reader's coordinate bound: refused with diagnostics, which is the contract.
        }
    }
    catch (const cfx::InputError& error)
    {
        if (valid || error.Diagnostics().empty())
        {
            __builtin_trap(); // Load refused what Validate accepted, or refused without saying why
        }
    }
    return 0;
}
