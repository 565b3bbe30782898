#include "preset_command.h"

#include "cli_common.h"
#include "contactfx/presets.h"
#include "contactfx/scene/effects_json.h"
#include "outputs.h"

#include <iostream>
#include <memory>

namespace cfx::cli
{

void RegisterPresetCommand(CLI::App& app, int& result)
{
    struct Options
    {
        std::string name;
        std::string out;
    };
    auto options = std::make_shared<Options>();
    CLI::App* command = app.add_subcommand("preset", "Print a built-in effects configuration as JSON");
    command->add_option("name", options->name, "default or tutorial")
        ->required()
        ->check(CLI::IsMember({"default", "tutorial"}));
    command->add_option("--out", options->out, "Write to this file instead of standard output")
        ->check(NamesAFile());
    command->callback(
        [command, options, &result]
        {
            result = Guarded(*command,
                             [&]
                             {
                                 const EffectsConfig config =
                                     options->name == "tutorial" ? TutorialPreset() : DefaultPreset();
                                 if (options->out.empty())
                                 {
                                     std::cout << SaveEffectsString(config);
                                 }
                                 else
                                 {
                                     // Checked and written like every output (outputs.h): never over a
                                     // device, a read-only file or a directory.
                                     OutputFiles outputs;
                                     const OutputFiles::Handle out = outputs.Add("--out", options->out);
                                     outputs.Prepare();
                                     outputs.Write(out, SaveEffectsString(config));
                                     outputs.Commit();
                                 }
                                 return kExitOk;
                             });
        });
}

} // namespace cfx::cli
