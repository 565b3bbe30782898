// contactfx bench particles / demo / debris: how fast the particles and the effects layer are.
#pragma once

#include <CLI/CLI.hpp>

namespace cfx::cli
{

/// Registers `bench` with its subcommands `particles`, `demo` and `debris`; each sets `result` to its exit
/// code.
void RegisterBenchCommand(CLI::App& app, int& result);

} // namespace cfx::cli
