#include "outputs.h"

#include "contactfx/error.h"
#include "contactfx/files/text_file.h"
#include "harness/command_line.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <map>
#include <pthread.h>
#include <set>
#include <sys/stat.h>
#include <unistd.h>
#include <utility>

namespace cfx::cli
{

namespace
{

namespace fs = std::filesystem;

std::string Quoted(const fs::path& path)
{
    return "\"" + path.string() + "\"";
}

std::string Strerror(int error)
{
    return std::strerror(error != 0 ? error : EIO);
}

fs::path Beside(const fs::path& real, const char* what)
{
    static std::atomic<unsigned> counter{0};
    return real.parent_path() / ("." + real.filename().string() + what + std::to_string(::getpid()) + "-" +
                                 std::to_string(counter.fetch_add(1)));
}

// SIGINT, SIGTERM, SIGHUP while outputs are pending: stop at the next write or Check, which unwinds and
// removes the temporary files. A command blocked (opening a FIFO) or busy (one huge frame) that has not
// unwound kGraceSeconds later, or a second signal, stops it at once: the handler removes the temporary
// files itself (unlink and write are all a signal handler may call), says so and exits 1.
volatile std::sig_atomic_t g_signal = 0;
int g_handlersInstalled = 0; // InstallInterruptHandlers' one, and one per prepared OutputFiles
// Prepared OutputFiles alive: with none, a signal has nothing to remove and nothing to unwind for.
volatile std::sig_atomic_t g_preparedOutputs = 0;
constexpr int kSignals[4] = {SIGINT, SIGTERM, SIGHUP, SIGALRM};
struct sigaction g_previous[4];
constexpr unsigned kGraceSeconds = 1;
// The temporary files of the prepared outputs and their owners, for the handler; changed only while
// signals are only noted (SignalsNoted).
std::vector<std::pair<const void*, const char*>> g_temporaries;

// Above 0 while g_temporaries changes (Prepare creating the temporary files, an OutputFiles going) or an
// OutputFiles renames its outputs into place: a signal then only notes itself, whichever thread it lands
// on (blocking signals would hold them on one thread only), and the code that set it checks afterwards.
volatile std::sig_atomic_t g_onlyNoted = 0;
// Set once an OutputFiles has put its outputs in place: a signal from then on has nothing to undo.
volatile std::sig_atomic_t g_committed = 0;

class SignalsNoted
{
public:
    SignalsNoted() { g_onlyNoted = g_onlyNoted + 1; }
    ~SignalsNoted() { g_onlyNoted = g_onlyNoted - 1; }
    SignalsNoted(const SignalsNoted&) = delete;
    SignalsNoted& operator=(const SignalsNoted&) = delete;
};

void Say(const char* text)
{
    const ssize_t ignored = ::write(STDERR_FILENO, text, std::strlen(text));
    static_cast<void>(ignored);
}

// "contactfx: error: interrupted by Interrupt" and `ending`, as a signal handler may write it.
void SayInterrupted(int signal, const char* ending)
{
    Say("contactfx: error: interrupted by ");
    Say(signal == SIGINT ? "Interrupt" : signal == SIGTERM ? "Terminated" : "Hangup");
    Say(ending);
}

// Takes `owner`'s temporary files off the handler's list (they are renamed, or being removed).
void Unlist(const void* owner)
{
    std::erase_if(g_temporaries, [&](const auto& entry) { return entry.first == owner; });
}

extern "C" void OnSignal(int signal)
{
    if (g_committed != 0)
    {
        // The outputs are all in place (the signal waited while they were put there): nothing to undo.
        SayInterrupted(g_signal != 0 ? g_signal : signal, " after its outputs were written\n");
        ::_exit(1);
    }
    if (g_onlyNoted != 0)
    {
        if (signal != SIGALRM && g_signal == 0)
        {
            g_signal = signal;
        }
        return;
    }
    if (signal != SIGALRM && g_preparedOutputs == 0)
    {
        g_signal = signal; // stops at once
    }
    else if (signal != SIGALRM && g_signal == 0)
    {
        g_signal = signal;
        ::alarm(kGraceSeconds);
        return;
    }
    for (const auto& [owner, temporary] : g_temporaries)
    {
        ::unlink(temporary);
    }
    SayInterrupted(g_signal, ": no output written\n");
    ::_exit(1);
}

void InstallHandlers()
{
    if (g_handlersInstalled++ > 0)
    {
        return;
    }
    g_signal = 0;
    g_onlyNoted = 0;
    g_committed = 0;
    for (int i = 0; i < 4; ++i)
    {
        struct sigaction action
        {
        };
        action.sa_handler = &OnSignal;
        action.sa_flags = SA_RESTART; // reads and writes elsewhere go on; the loops check the flag
        sigfillset(&action.sa_mask);  // one handler at a time: the second signal waits for the first
        ::sigaction(kSignals[i], &action, &g_previous[i]);
    }
}

void RestoreHandlers()
{
    if (g_preparedOutputs == 0)
    {
        ::alarm(0); // the command unwound in time: no stop from the handler
    }
    if (--g_handlersInstalled > 0)
    {
        return;
    }
    for (int i = 0; i < 4; ++i)
    {
        ::sigaction(kSignals[i], &g_previous[i], nullptr);
    }
}

} // namespace

void InstallInterruptHandlers()
{
    InstallHandlers();
}

OutputFiles::OutputFiles() = default;

OutputFiles::~OutputFiles()
{
    {
        const SignalsNoted noted;
        Unlist(this);
    }
    if (!m_committed)
    {
        RemoveTemporaries();
    }
    if (m_prepared)
    {
        g_preparedOutputs = g_preparedOutputs - 1;
        RestoreHandlers();
    }
}

void OutputFiles::AddInput(const fs::path& file)
{
    if (!file.empty())
    {
        m_inputs.push_back(file);
    }
}

OutputFiles::Handle OutputFiles::Add(const std::string& flag, const fs::path& file,
                                     const std::string& extension)
{
    Output output;
    output.flag = flag;
    output.extension = extension;
    output.target = file;
    output.real = WrittenPath(file);
    m_outputs.push_back(std::move(output));
    return m_outputs.size() - 1;
}

OutputFiles::Handle OutputFiles::AddScratch(const std::string& flag, const fs::path& file)
{
    const Handle handle = Add(flag, file);
    m_outputs[handle].scratch = true;
    return handle;
}

void OutputFiles::Refuse(Diagnostic problem)
{
    m_refused.push_back(std::move(problem));
}

void OutputFiles::Prepare()
{
    std::vector<Diagnostic> problems = m_refused;
    auto refuse = [&](const Output& output, const std::string& message) {
        problems.push_back(Diagnostic{output.target.string(), output.flag, message});
    };

    // Inputs by path and, when they exist, by identity (hard links, other spellings).
    std::map<std::string, fs::path> inputPaths;
    std::map<std::pair<dev_t, ino_t>, fs::path> inputIds;
    for (const fs::path& input : m_inputs)
    {
        inputPaths.emplace(WrittenPath(input).string(), input);
        struct stat info = {};
        if (::stat(input.c_str(), &info) == 0)
        {
            inputIds.emplace(std::make_pair(info.st_dev, info.st_ino), input);
        }
    }
    std::map<std::string, const Output*> seen;
    std::map<std::pair<dev_t, ino_t>, const Output*> seenIds;
    for (const Output& output : m_outputs)
    {
        if (output.scratch)
        {
            continue; // beside another output, whose checks cover its folder
        }
        const std::string misnamed =
            output.extension.empty() ? "" : ExtensionProblem(output.target.string(), output.extension);
        if (!misnamed.empty())
        {
            problems.push_back(Diagnostic{kCommandLine, output.flag, misnamed});
            continue;
        }
        const std::string problem = OutputFileProblem(output.target);
        if (!problem.empty())
        {
            refuse(output, problem);
            continue;
        }
        const fs::path* input = nullptr;
        if (auto found = inputPaths.find(output.real.string()); found != inputPaths.end())
        {
            input = &found->second;
        }
        struct stat info = {};
        const bool exists = ::stat(output.real.c_str(), &info) == 0;
        if (input == nullptr && exists)
        {
            if (auto found = inputIds.find({info.st_dev, info.st_ino}); found != inputIds.end())
            {
                input = &found->second;
            }
        }
        if (input != nullptr)
        {
            refuse(output, "is the input file " + Quoted(*input) + " of this command: not overwritten");
            continue;
        }
        // The same file by path, or an existing one by identity (a hard link under another name).
        const Output* other = nullptr;
        if (auto [found, inserted] = seen.emplace(output.real.string(), &output); !inserted)
        {
            other = found->second;
        }
        else if (exists)
        {
            if (auto [same, added] = seenIds.emplace(std::make_pair(info.st_dev, info.st_ino), &output);
                !added)
            {
                other = same->second;
            }
        }
        if (other != nullptr)
        {
            refuse(output, "is also the output of " + other->flag + " (" + Quoted(other->target) +
                               "): give each output its own file");
        }
    }
    if (!problems.empty())
    {
        throw InputError(std::move(problems));
    }

    m_prepared = true;
    InstallHandlers();
    g_preparedOutputs = g_preparedOutputs + 1;
    {
        // A signal while the temporary files are made is noted, and the check below unwinds: they are
        // removed with the object (RemoveTemporaries), those not yet listed for the handler too.
        const SignalsNoted noted;
        for (std::size_t index = 0; index < m_outputs.size(); ++index)
        {
            CreateTemporary(m_outputs[index]);
            if (m_testHook)
            {
                m_testHook(FileStep::prepared, index);
            }
        }
    }
    CheckInterrupted();
}

void OutputFiles::CreateTemporary(Output& output)
{
    // A file that replaces another has its mode from the start: what it holds while the command runs
    // is no more readable than what it replaces (Commit sets the mode again, in case it changed).
    struct stat existing = {};
    const bool replaces = !output.scratch && ::stat(output.real.c_str(), &existing) == 0;
    const mode_t mode = replaces ? (existing.st_mode & 07777) : 0666;
    int descriptor = -1;
    for (int attempt = 0; attempt < 16 && descriptor < 0; ++attempt)
    {
        output.temporary = Beside(output.real, ".tmp-");
        descriptor =
            ::open(output.temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, replaces ? 0600 : mode);
        if (descriptor < 0 && errno != EEXIST)
        {
            const int error = errno;
            output.temporary.clear();
            Fail(output, "cannot write: " + Strerror(error));
        }
    }
    if (descriptor < 0)
    {
        output.temporary.clear();
        Fail(output, "cannot write: no free temporary file name");
    }
    if (replaces)
    {
        ::fchmod(descriptor, mode);
    }
    ::close(descriptor);
    // Its name stays in this buffer until the object goes (cleared, never reallocated).
    g_temporaries.emplace_back(this, output.temporary.c_str());
}

const fs::path& OutputFiles::Temporary(Handle output) const
{
    return m_outputs.at(output).temporary;
}

const fs::path& OutputFiles::Target(Handle output) const
{
    return m_outputs.at(output).target;
}

void OutputFiles::Fail(const Output& output, const std::string& message) const
{
    throw InputError(output.target.string(), output.flag, message);
}

void OutputFiles::CheckInterrupted() const
{
    if (g_signal != 0)
    {
        throw std::runtime_error(std::string("interrupted by ") + ::strsignal(g_signal) +
                                 ": no output written");
    }
}

void OutputFiles::Write(Handle handle, std::string_view bytes)
{
    CheckInterrupted();
    Output& output = m_outputs.at(handle);
    CloseStream(output, false);
    PutBytes(output, "wb", 0, bytes);
}

void OutputFiles::PutBytes(const Output& output, const char* mode, std::uint64_t offset,
                           std::string_view bytes) const
{
    std::FILE* file = std::fopen(output.temporary.c_str(), mode);
    if (file == nullptr)
    {
        Fail(output, "cannot write: " + Strerror(errno));
    }
    errno = 0;
    bool ok = offset == 0 || ::fseeko(file, static_cast<off_t>(offset), SEEK_SET) == 0;
    ok = ok && std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
    ok = ok && std::fflush(file) == 0;
    const int error = errno;
    ok = std::fclose(file) == 0 && ok;
    if (!ok)
    {
        Fail(output, "cannot write: " + Strerror(error != 0 ? error : errno));
    }
}

void OutputFiles::Append(Handle handle, std::string_view bytes)
{
    Output& output = m_outputs.at(handle);
    if (output.stream == nullptr)
    {
        CheckInterrupted();
        output.stream = std::fopen(output.temporary.c_str(), "ab"); // after WriteAt: on at the end
        if (output.stream == nullptr)
        {
            Fail(output, "cannot write: " + Strerror(errno));
        }
        std::setvbuf(output.stream, nullptr, _IOFBF, 1 << 16);
    }
    errno = 0;
    if (std::fwrite(bytes.data(), 1, bytes.size(), output.stream) != bytes.size())
    {
        const int error = errno;
        CloseStream(output, false);
        Fail(output, "cannot write: " + Strerror(error));
    }
}

void OutputFiles::WriteAt(Handle handle, std::uint64_t offset, std::string_view bytes)
{
    Output& output = m_outputs.at(handle);
    CloseStream(output, true); // Append() reopens it at the end
    PutBytes(output, "r+b", offset, bytes);
}

void OutputFiles::CloseStream(Output& output, bool check)
{
    if (output.stream == nullptr)
    {
        return;
    }
    errno = 0;
    bool ok = std::fflush(output.stream) == 0;
    const int error = errno;
    ok = std::fclose(output.stream) == 0 && ok;
    output.stream = nullptr;
    if (check && !ok)
    {
        Fail(output, "cannot write: " + Strerror(error != 0 ? error : errno));
    }
}

void OutputFiles::Commit()
{
    for (Output& output : m_outputs)
    {
        CheckInterrupted(); // syncing thousands of frames takes a while: an interrupt stops it at once
        CloseStream(output, true);
        if (output.scratch)
        {
            ::unlink(output.temporary.c_str());
            output.temporary.clear();
            continue;
        }
        // On disk before it replaces anything: after a crash, the old file or the whole new one.
        const int descriptor = ::open(output.temporary.c_str(), O_RDONLY | O_CLOEXEC);
        if (descriptor < 0 || ::fsync(descriptor) != 0)
        {
            const int error = errno;
            if (descriptor >= 0)
            {
                ::close(descriptor);
            }
            Fail(output, "cannot write: " + Strerror(error));
        }
        ::close(descriptor);
        // Something may have taken the target's place while the command ran.
        const std::string problem = OutputFileProblem(output.target);
        if (!problem.empty())
        {
            Fail(output, problem);
        }
    }
    // Rename in order; on failure put back what was replaced (kept as hard links) and remove what was new.
    // The last moment an interrupt leaves everything as it was; from here on a signal is only noted (on any
    // thread: blocking signals would hold them on this one only) until every output is in place (or every
    // replaced file is back), and then stops the command with a message that says so: never a part of the
    // outputs written, never backups left behind.
    const SignalsNoted noted;
    CheckInterrupted();
    std::vector<fs::path> backups(m_outputs.size());
    std::size_t done = 0;
    for (; done < m_outputs.size(); ++done)
    {
        Output& output = m_outputs[done];
        if (output.scratch)
        {
            continue; // removed above
        }
        struct stat existing = {};
        if (::stat(output.real.c_str(), &existing) == 0)
        {
            ::chmod(output.temporary.c_str(), existing.st_mode & 07777); // the replaced file's mode
            const fs::path backup = Beside(output.real, ".old-");
            if (::link(output.real.c_str(), backup.c_str()) == 0)
            {
                backups[done] = backup;
            }
        }
        if (m_testHook)
        {
            m_testHook(FileStep::renaming, done);
        }
        if (::rename(output.temporary.c_str(), output.real.c_str()) != 0)
        {
            const int error = errno;
            if (!backups[done].empty())
            {
                ::unlink(backups[done].c_str());
            }
            for (std::size_t i = done; i-- > 0;)
            {
                if (m_outputs[i].scratch)
                {
                    continue;
                }
                if (!backups[i].empty())
                {
                    ::rename(backups[i].c_str(), m_outputs[i].real.c_str());
                }
                else
                {
                    ::unlink(m_outputs[i].real.c_str());
                }
                m_outputs[i].temporary.clear(); // renamed: nothing of it left to remove
            }
            Fail(output, "cannot write: " + Strerror(error));
        }
        output.temporary.clear();
    }
    for (const fs::path& backup : backups)
    {
        if (!backup.empty())
        {
            ::unlink(backup.c_str());
        }
    }
    m_committed = true;
    Unlist(this); // renamed
    g_committed = 1;
    if (g_signal != 0)
    {
        throw std::runtime_error(std::string("interrupted by ") + ::strsignal(g_signal) +
                                 " after its outputs were written");
    }
}

void OutputFiles::RemoveTemporaries()
{
    for (Output& output : m_outputs)
    {
        CloseStream(output, false);
        if (!output.temporary.empty())
        {
            ::unlink(output.temporary.c_str());
            output.temporary.clear();
        }
    }
}

} // namespace cfx::cli
