// The project's own scenes (scenes/ in the checkout), for the tests that load them.
#pragma once

#include <filesystem>

inline const std::filesystem::path kScenesDir = std::filesystem::path(CONTACTFX_SOURCE_DIR) / "scenes";
