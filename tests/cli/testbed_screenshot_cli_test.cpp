// contactfx-testbed --screenshot writes a PNG: a name that says otherwise is refused before any window
// opens (so no display is needed), on one line, and nothing is written.
#include "cli/cli_support.h"

#include <gtest/gtest.h>

namespace cfx::test
{

TEST(CliTestbedScreenshot, ANameThatIsNotAPngIsRefused)
{
    const std::filesystem::path dir = ScratchDir("testbed_screenshot_name");
    for (const char* name : {"tb.jpg", "tb", "tb.png.txt"})
    {
        const std::string shot = (dir / name).string();
        const CliResult result =
            RunCommand(std::string(CONTACTFX_BINARY_DIR) +
                       "/bin/contactfx-testbed --scene grinder --frames 2 --screenshot " + shot);
        EXPECT_EQ(result.exitCode, 1) << result.output;
        EXPECT_EQ(result.output,
                  "contactfx-testbed: error: <command line>: --screenshot: expected a .png file, found \"" +
                      shot + "\"\n");
        EXPECT_TRUE(std::filesystem::is_empty(dir)) << name;
    }
}

} // namespace cfx::test
