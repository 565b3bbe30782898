#include "help_command.h"

#include "cli_common.h"
#include "usage.h"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace cfx::cli
{

namespace
{

// `words` name a command and its subcommands, outermost first ("bench particles"); none: the program.
int ShowHelp(const CLI::App& app, const std::vector<std::string>& words)
{
    const CLI::App* command = &app;
    for (const std::string& word : words)
    {
        const CLI::App* named = FindCommand(*command, word);
        if (named == nullptr)
        {
            return ReportUnknownCommand(*command, word);
        }
        command = named;
    }
    std::cout << HelpText(*command);
    return kExitOk;
}

} // namespace

void RegisterHelpCommand(CLI::App& app, int& result)
{
    auto words = std::make_shared<std::vector<std::string>>();
    CLI::App* help = app.add_subcommand("help", "Show the commands, or one command's options: help COMMAND");
    help->add_option("command", *words, "A command, e.g. run (or bench particles)");
    help->callback([&app, words, &result] { result = ShowHelp(app, *words); });
}

} // namespace cfx::cli
