#include "contactfx/scene/text_file.h"

#include "contactfx/error.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <system_error>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#define CONTACTFX_HAVE_FSYNC 1
#endif

namespace cfx
{

namespace
{

std::filesystem::path TemporaryPathBeside(const std::filesystem::path& path, int attempt)
{
    static std::atomic<unsigned> counter{0};
    const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
    std::string name(".");
    name.append(path.filename().string()).append(".tmp");
#if defined(CONTACTFX_HAVE_FSYNC)
    name.append("-").append(std::to_string(::getpid()));
#endif
    name.append("-").append(std::to_string(counter.fetch_add(1)));
    name.append("-").append(std::to_string(ticks % 1000000));
    name.append("-").append(std::to_string(attempt));
    return path.parent_path() / name;
}

[[noreturn]] void Fail(const std::filesystem::path& path, const std::string& message)
{
    throw InputError(path.string(), "", "cannot write: " + message);
}

} // namespace

void WriteTextFileAtomically(const std::filesystem::path& path, std::string_view contents)
{
    if (!path.has_filename())
    {
        Fail(path, "the path names no file");
    }
    std::filesystem::path temporary;
    std::FILE* file = nullptr;
    for (int attempt = 0; attempt < 16 && file == nullptr; ++attempt)
    {
        temporary = TemporaryPathBeside(path, attempt);
        file = std::fopen(temporary.string().c_str(), "wbx"); // C11 exclusive mode: never reuse a file
        if (file == nullptr && errno != EEXIST)
        {
            Fail(path, std::strerror(errno));
        }
    }
    if (file == nullptr)
    {
        Fail(path, "no free temporary file name");
    }

    bool ok = std::fwrite(contents.data(), 1, contents.size(), file) == contents.size();
    ok = ok && std::fflush(file) == 0;
#if defined(CONTACTFX_HAVE_FSYNC)
    ok = ok && ::fsync(::fileno(file)) == 0;
#endif
    const int writeError = errno;
    ok = (std::fclose(file) == 0) && ok;
    if (!ok)
    {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        Fail(path, std::strerror(writeError != 0 ? writeError : EIO));
    }

    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error)
    {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        Fail(path, error.message());
    }
}

std::string ReadTextFile(const std::filesystem::path& path)
{
    const std::string name = path.string();
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
    {
        throw InputError(name, "", "cannot read: it is a directory");
    }
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"), &std::fclose);
    if (!file)
    {
        throw InputError(name, "", std::string("cannot open for reading: ") + std::strerror(errno));
    }
    std::string text;
    char buffer[1 << 16];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, file.get())) > 0)
    {
        text.append(buffer, count);
    }
    if (std::ferror(file.get()))
    {
        throw InputError(name, "", "read error");
    }
    return text;
}

} // namespace cfx
