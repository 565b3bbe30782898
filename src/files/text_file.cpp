// Whole files in and out. Outputs are checked first (OutputFileProblem: never over a device, a directory or
// a read-only file), then written to an exclusive temporary file beside the target, flushed to disk and
// renamed over it, so that readers see the old file or the new one.
#include "contactfx/files/text_file.h"

#include "contactfx/error.h"

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
#include <utility>

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
    name.append("-").append(std::to_string(::getpid()));
    name.append("-").append(std::to_string(counter.fetch_add(1)));
    name.append("-").append(std::to_string(ticks % 1000000));
    name.append("-").append(std::to_string(attempt));
    return path.parent_path() / name;
}

[[noreturn]] void Fail(const std::filesystem::path& path, const std::string& message)
{
    throw InputError(path.string(), "", "cannot write: " + message);
}

std::string Quoted(const std::filesystem::path& path)
{
    return "\"" + path.string() + "\"";
}

std::string Strerror(int error)
{
    return std::strerror(error != 0 ? error : EIO);
}

// For a path whose folders cannot all be folders (stat said ENOTDIR): the first file on the way to
// `named`'s folder, e.g. "\"out/afile\" is not a folder" for out/afile/x.png.
std::string NotAFolderOnTheWay(const std::filesystem::path& named)
{
    struct stat info = {};
    for (std::filesystem::path up = named.parent_path(); !up.empty() && up != up.root_path();
         up = up.parent_path())
    {
        if (::stat(up.c_str(), &info) == 0 && !S_ISDIR(info.st_mode))
        {
            return Quoted(up) + " is not a folder";
        }
    }
    return "folder " + Quoted(named.parent_path()) + " does not exist";
}

} // namespace

std::filesystem::path WrittenPath(const std::filesystem::path& file)
{
    namespace fs = std::filesystem;
    constexpr int kMaxLinks = 40; // Linux's limit on links followed in one path
    std::error_code error;
    fs::path real = fs::absolute(file, error);
    for (int link = 0; !error && link <= kMaxLinks; ++link)
    {
        // weakly_canonical follows links only as far as the path exists.
        fs::path resolved = fs::weakly_canonical(real, error);
        if (error)
        {
            break;
        }
        real = std::move(resolved);
        if (!fs::is_symlink(fs::symlink_status(real, error)) || error)
        {
            return real;
        }
        // A dangling link, where weakly_canonical stopped: go on at its target.
        real = real.parent_path() / fs::read_symlink(real, error);
    }
    if (error)
    {
        std::error_code ignored;
        return fs::absolute(file, ignored);
    }
    return real;
}

namespace
{

// OutputFileProblem of `given`, whose WrittenPath is `file` (resolved once by the caller).
std::string ProblemOfWrittenFile(const std::filesystem::path& given, const std::filesystem::path& file)
{
    namespace fs = std::filesystem;
    if (!given.has_filename() || given.filename() == "." || given.filename() == "..")
    {
        return "names no file";
    }
    std::error_code error;
    const bool link = fs::is_symlink(fs::symlink_status(given, error));
    const fs::path& named = link ? file : given; // the folder as the user wrote it, or the link's target's
    struct stat info = {};
    if (::stat(file.c_str(), &info) == 0)
    {
        if (S_ISDIR(info.st_mode))
        {
            return "is a directory, not a file";
        }
        if (S_ISCHR(info.st_mode) || S_ISBLK(info.st_mode))
        {
            return "is a device, not a regular file: give a file to write";
        }
        if (S_ISFIFO(info.st_mode))
        {
            return "is a FIFO, not a regular file: give a file to write";
        }
        if (!S_ISREG(info.st_mode))
        {
            return "is not a regular file";
        }
        // Permission bits, not access(): root may write a mode 444 file, but its owner meant it to stay.
        if ((info.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0)
        {
            char mode[8];
            std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(info.st_mode & 07777));
            return std::string("is read-only (mode ") + mode + "): not replaced";
        }
        if (::access(file.c_str(), W_OK) != 0)
        {
            return "cannot be written: " + Strerror(errno);
        }
    }
    else if (errno == ENOTDIR)
    {
        return NotAFolderOnTheWay(named);
    }
    else if (errno != ENOENT)
    {
        return "cannot be written: " + Strerror(errno);
    }
    const fs::path folder = file.parent_path().empty() ? fs::path(".") : file.parent_path();
    const fs::path shown = named.parent_path().empty() ? fs::path(".") : named.parent_path();
    struct stat folderInfo = {};
    if (::stat(folder.c_str(), &folderInfo) != 0)
    {
        return errno == ENOTDIR ? NotAFolderOnTheWay(named) : "folder " + Quoted(shown) + " does not exist";
    }
    if (!S_ISDIR(folderInfo.st_mode))
    {
        return Quoted(shown) + " is not a folder";
    }
    if ((folderInfo.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 ||
        ::access(folder.c_str(), W_OK | X_OK) != 0)
    {
        return "folder " + Quoted(shown) + " is not writable";
    }
    return {};
}

} // namespace

std::string OutputFileProblem(const std::filesystem::path& given)
{
    return ProblemOfWrittenFile(given, WrittenPath(given));
}

void WriteTextFileAtomically(const std::filesystem::path& path, std::string_view contents)
{
    const std::filesystem::path target = WrittenPath(path);
    if (const std::string problem = ProblemOfWrittenFile(path, target); !problem.empty())
    {
        throw InputError(path.string(), "", problem);
    }
    std::filesystem::path temporary;
    std::FILE* file = nullptr;
    for (int attempt = 0; attempt < 16 && file == nullptr; ++attempt)
    {
        temporary = TemporaryPathBeside(target, attempt);
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
    if (struct stat existing = {}; ::stat(target.c_str(), &existing) == 0)
    {
        ok = ok && ::fchmod(::fileno(file), existing.st_mode & 07777) == 0; // the replaced file's mode
    }
    ok = ok && std::fflush(file) == 0;
    ok = ok && ::fsync(::fileno(file)) == 0;
    const int writeError = errno;
    ok = (std::fclose(file) == 0) && ok;
    if (!ok)
    {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        Fail(path, std::strerror(writeError != 0 ? writeError : EIO));
    }

    std::error_code error;
    std::filesystem::rename(temporary, target, error);
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
    const std::string tooLong = "longer than " + std::to_string(kMaxTextFileBytes >> 20) +
                                " MiB: not read (no scene or effects config is)";
    if (std::filesystem::is_regular_file(path, error) &&
        std::filesystem::file_size(path, error) > kMaxTextFileBytes)
    {
        throw InputError(name, "", tooLong);
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
        if (text.size() + count > kMaxTextFileBytes) // a device or a pipe that does not end
        {
            throw InputError(name, "", tooLong);
        }
        text.append(buffer, count);
    }
    if (std::ferror(file.get()))
    {
        throw InputError(name, "", "read error");
    }
    return text;
}

} // namespace cfx
