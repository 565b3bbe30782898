// The real RUBE scenes of ../shared/rube-samples: optional test inputs. A clone of the repository alone
// configures, builds and passes; tests that need these files are reported as skipped, with the reason.
#pragma once

#include <filesystem>
#include <gtest/gtest.h>

namespace cfx::test
{

/// ../shared/rube-samples beside the checkout (CMake cache variable CONTACTFX_SHARED_DIR).
inline std::filesystem::path RubeSamplesDir()
{
    return std::filesystem::path(CONTACTFX_SHARED_DIR) / "rube-samples";
}

inline bool HaveRubeSamples()
{
    std::error_code error;
    return std::filesystem::is_directory(RubeSamplesDir(), error);
}

} // namespace cfx::test

/// Skips the current test, saying why, when the real RUBE samples are not there.
#define CONTACTFX_REQUIRE_RUBE_SAMPLES()                                                                     \
    do                                                                                                       \
    {                                                                                                        \
        if (!::cfx::test::HaveRubeSamples())                                                                 \
        {                                                                                                    \
            GTEST_SKIP() << "the real RUBE scenes are not here (" << ::cfx::test::RubeSamplesDir().string()  \
                         << " does not exist); the project's own scenes were tested instead";                \
        }                                                                                                    \
    } while (false)
