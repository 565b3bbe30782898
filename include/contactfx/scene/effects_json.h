// contactfx_scene: effects configuration files.
//
// An effects config JSON holds an EffectsConfig: materials, particle types, pair rules, the particle
// budget. Field names are the struct members' names (docs/effects-config.md). Missing fields take the
// struct's defaults, except required ones (IsRequired: names, a rule's materials and particle type), which
// are errors; unknown fields and keys repeated in one object are errors (a typo must not silently do
// nothing), and so is a sound rule for a material pair without a pair rule. Every problem is
// reported with file, JSON path, expected and found, and line and column for malformed JSON.
#pragma once

#include "contactfx/config.h"
#include "contactfx/error.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cfx
{

/// Reads and validates an effects config. Throws InputError with every problem.
EffectsConfig LoadEffectsFile(const std::filesystem::path& path);
/// Same from text; `fileName` is used in diagnostics only.
EffectsConfig LoadEffectsString(std::string_view json, std::string_view fileName);
/// Every problem of the file, or an empty list; never throws for bad content.
std::vector<Diagnostic> ValidateEffectsFile(const std::filesystem::path& path);

/// The config as JSON text, every field written (but `burstParticleType`, written only when set, so that
/// configs saved before it read the same). Throws InputError (file "<api>", Validate's problems) for
/// a config that is not valid (a NaN, a value out of its range): what is saved always loads again.
std::string SaveEffectsString(const EffectsConfig& config);
/// Writes atomically (temporary file, then rename). Throws InputError naming the path on failure, or as
/// SaveEffectsString for an invalid config (nothing is written then).
void SaveEffectsFile(const EffectsConfig& config, const std::filesystem::path& path);

} // namespace cfx
