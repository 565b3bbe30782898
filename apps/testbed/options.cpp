#include "options.h"

#include "contactfx/error.h"
#include "harness/scenes.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <unistd.h>

namespace cfx::testbed
{

namespace
{

constexpr const char* kCommandLine = "<command line>";

void CheckWritable(const std::string& path, const char* flag)
{
    const std::filesystem::path file(path);
    std::error_code error;
    if (file.filename().empty() || std::filesystem::is_directory(file, error))
    {
        throw InputError(kCommandLine, flag, "expected a file name, found the folder " + path);
    }
    const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
    if (!std::filesystem::is_directory(folder, error))
    {
        throw InputError(kCommandLine, flag,
                         "cannot write " + path + ": folder " + folder.string() + " does not exist");
    }
    if (access(folder.c_str(), W_OK) != 0)
    {
        throw InputError(kCommandLine, flag,
                         "cannot write " + path + ": folder " + folder.string() + " is not writable");
    }
}

// A screenshot is a PNG, whatever it is called: a name that says otherwise is refused.
void CheckPngName(const std::string& path)
{
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".png")
    {
        throw InputError(kCommandLine, "--screenshot", "expected a .png file, found \"" + path + "\"");
    }
}

} // namespace

void CheckOptions(const Options& options, bool framesGiven)
{
    if (FindScene(options.scene) == nullptr)
    {
        throw InputError(kCommandLine, "--scene",
                         "unknown scene \"" + options.scene + "\" (registered: " + SceneNames() + ")");
    }
    if (framesGiven && options.frames < 1)
    {
        throw InputError(kCommandLine, "--frames",
                         "expected a whole number >= 1, found " + std::to_string(options.frames));
    }
    if (!options.screenshot.empty())
    {
        if (!framesGiven)
        {
            throw InputError(kCommandLine, "--screenshot", "needs --frames N (the frame to save)");
        }
        CheckWritable(options.screenshot, "--screenshot");
        CheckPngName(options.screenshot);
    }
}

} // namespace cfx::testbed
