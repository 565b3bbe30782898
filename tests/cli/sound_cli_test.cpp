// --audio and --voices of demo, run and render, through the binary: the WAV read back against the voices
// file (heard within 20 ms of each start, silent where no voice sounds), byte-identical for the same flags,
// an .mp4 with an audio stream as long as its video, and bad `sound` values named by their JSON path.
#include "cli/cli_support.h"

#include <cmath>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <vector>

namespace cfx::test
{

namespace
{

constexpr double kRate = 48000.0;

struct Wav
{
    std::uint32_t sampleRate = 0;
    std::uint16_t channels = 0;
    std::uint16_t bits = 0;
    std::vector<std::int16_t> samples;
};

std::uint32_t Le(const std::string& bytes, std::size_t at, int count)
{
    std::uint32_t value = 0;
    for (int i = count - 1; i >= 0; --i)
    {
        value = value << 8 | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(i)]);
    }
    return value;
}

// A canonical 44-byte-header PCM WAV, as contactfx writes it; empty samples when it is not one.
Wav ReadWav(const std::filesystem::path& file)
{
    const std::string bytes = FileText(file);
    Wav wav;
    if (bytes.size() < 44 || bytes.compare(0, 4, "RIFF") != 0 || bytes.compare(8, 8, "WAVEfmt ") != 0 ||
        bytes.compare(36, 4, "data") != 0 || Le(bytes, 40, 4) != bytes.size() - 44 ||
        Le(bytes, 4, 4) != bytes.size() - 8)
    {
        ADD_FAILURE() << file << " is not a complete PCM WAV";
        return wav;
    }
    wav.channels = static_cast<std::uint16_t>(Le(bytes, 22, 2));
    wav.sampleRate = Le(bytes, 24, 4);
    wav.bits = static_cast<std::uint16_t>(Le(bytes, 34, 2));
    for (std::size_t at = 44; at + 1 < bytes.size(); at += 2)
    {
        wav.samples.push_back(static_cast<std::int16_t>(Le(bytes, at, 2)));
    }
    return wav;
}

// RMS of [from, to) s in dBFS (-inf for digital silence).
double LevelDb(const std::vector<std::int16_t>& samples, double from, double to)
{
    const auto first = static_cast<std::size_t>(std::max(0.0, std::round(from * kRate)));
    const auto last = std::min(samples.size(), static_cast<std::size_t>(std::round(to * kRate)));
    double sum = 0.0;
    for (std::size_t i = first; i < last; ++i)
    {
        sum += static_cast<double>(samples[i]) * samples[i];
    }
    const double rms = last > first ? std::sqrt(sum / static_cast<double>(last - first)) / 32768.0 : 0.0;
    return 20.0 * std::log10(rms);
}

struct VoiceSpan
{
    double start = -1.0;
    double stop = -1.0;
    int starts = 0;
    int stops = 0;
};

std::map<std::uint32_t, VoiceSpan> ReadVoices(const std::filesystem::path& file)
{
    std::map<std::uint32_t, VoiceSpan> voices;
    std::istringstream lines(FileText(file));
    for (std::string line; std::getline(lines, line);)
    {
        const nlohmann::json object = nlohmann::json::parse(line);
        EXPECT_EQ(object.size(), 6u) << line;
        const std::string kind = object.at("kind");
        EXPECT_TRUE(kind == "scrape" || kind == "impact" || kind == "particle_hits") << line;
        const double loudness = object.at("loudness");
        EXPECT_TRUE(loudness >= 0.0 && loudness <= 1.0) << line;
        // A material pair, or for particle hits the particle type's name.
        const bool isPair = std::string(object.at("pair")).find('+') != std::string::npos;
        EXPECT_EQ(isPair, kind != "particle_hits") << line;
        VoiceSpan& span = voices[object.at("voice").get<std::uint32_t>()];
        if (object.at("type") == "voice_started")
        {
            span.start = object.at("time");
            ++span.starts;
        }
        else
        {
            EXPECT_EQ(object.at("type"), "voice_stopped") << line;
            span.stop = object.at("time");
            ++span.stops;
        }
    }
    return voices;
}

// Whether any voice other than `except` sounds somewhere in [from, to).
bool AnotherSounds(const std::map<std::uint32_t, VoiceSpan>& voices, std::uint32_t except, double from,
                   double to)
{
    for (const auto& [id, span] : voices)
    {
        if (id != except && span.start < to && span.stop > from)
        {
            return true;
        }
    }
    return false;
}

} // namespace

TEST(CliSound, TheDemosAudioRisesAtEachVoiceAndIsSilentWithout)
{
    const std::filesystem::path dir = ScratchDir("sound_demo");
    const double seconds = 12.0;
    const CliResult result = RunCli("demo --seconds 12 --audio " + (dir / "demo.wav").string() +
                                    " --voices " + (dir / "voices.jsonl").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    EXPECT_NE(result.output.find("voices: "), std::string::npos) << result.output;
    const Wav wav = ReadWav(dir / "demo.wav");
    EXPECT_EQ(wav.sampleRate, 48000u);
    EXPECT_EQ(wav.channels, 1u);
    EXPECT_EQ(wav.bits, 16u);
    ASSERT_EQ(wav.samples.size(), static_cast<std::size_t>(seconds * kRate)); // as long as the simulation

    const std::map<std::uint32_t, VoiceSpan> voices = ReadVoices(dir / "voices.jsonl");
    ASSERT_GT(voices.size(), 5u);
    int fromSilence = 0;
    for (const auto& [id, span] : voices)
    {
        EXPECT_EQ(span.starts, 1) << "voice " << id;
        EXPECT_EQ(span.stops, 1) << "voice " << id;
        EXPECT_GE(span.stop, span.start) << "voice " << id;
        if (span.start >= seconds - 0.02)
        {
            continue; // started as the run ended: never heard
        }
        // Heard within 20 ms of its start.
        const double after = LevelDb(wav.samples, span.start, span.start + 0.02);
        EXPECT_GT(after, -60.0) << "voice " << id << " at " << span.start << " s";
        if (!AnotherSounds(voices, id, span.start - 0.02, span.start))
        {
            ++fromSilence;
            EXPECT_LT(LevelDb(wav.samples, span.start - 0.02, span.start), -60.0) << "voice " << id;
            EXPECT_GT(after, LevelDb(wav.samples, span.start - 0.02, span.start) + 20.0) << "voice " << id;
        }
    }
    EXPECT_GT(fromSilence, 0);

    // Silent (below -60 dBFS) in every 10 ms window where no voice sounds.
    int silentWindows = 0;
    for (double t = 0.0; t + 0.01 <= seconds; t += 0.01)
    {
        if (!AnotherSounds(voices, 0, t, t + 0.01))
        {
            ++silentWindows;
            EXPECT_LT(LevelDb(wav.samples, t, t + 0.01), -60.0) << "at " << t << " s";
        }
    }
    EXPECT_GT(silentWindows, 10);
}

TEST(CliSound, TheSameFlagsGiveTheSameBytes)
{
    const std::filesystem::path dir = ScratchDir("sound_same");
    for (const char* name : {"a", "b"})
    {
        const std::string base = (dir / name).string();
        ASSERT_EQ(
            RunCli("run --scene rockslide --seconds 3 --audio " + base + ".wav --voices " + base + ".jsonl")
                .exitCode,
            0);
    }
    EXPECT_GT(FileText(dir / "a.wav").size(), 44u + 3 * 48000 * 2 - 1);
    EXPECT_EQ(FileText(dir / "a.wav"), FileText(dir / "b.wav"));
    EXPECT_EQ(FileText(dir / "a.jsonl"), FileText(dir / "b.jsonl"));
    // Another seed: other noise, other physics.
    ASSERT_EQ(
        RunCli("run --scene rockslide --seconds 3 --seed 2 --audio " + (dir / "c.wav").string()).exitCode, 0);
    EXPECT_NE(FileText(dir / "a.wav"), FileText(dir / "c.wav"));
}

TEST(CliSound, TheDemosVideoHasAnAudioStreamAsLongAsItsVideo)
{
    if (RunCommand("command -v ffprobe").exitCode != 0 || RunCommand("command -v ffmpeg").exitCode != 0)
    {
        GTEST_SKIP() << "ffmpeg or ffprobe is not installed: no video to check";
    }
    const std::filesystem::path dir = ScratchDir("sound_video");
    const std::filesystem::path video = dir / "demo.mp4";
    const CliResult result = RunCli("render --demo --seconds 1.5 --fps 10 --width 64 --height 48 --out " +
                                    video.string() + " --audio " + (dir / "demo.wav").string());
    ASSERT_EQ(result.exitCode, 0) << result.output;
    const CliResult probe =
        RunCommand("ffprobe -v error -show_entries stream=codec_type,duration,sample_rate "
                   "-of default=noprint_wrappers=1 " +
                   video.string());
    ASSERT_EQ(probe.exitCode, 0) << probe.output;
    // codec_type=video / duration=..., then codec_type=audio / sample_rate=48000 / duration=...
    std::map<std::string, double> durations;
    std::istringstream lines(probe.output);
    std::string type;
    for (std::string line; std::getline(lines, line);)
    {
        if (line.rfind("codec_type=", 0) == 0)
        {
            type = line.substr(11);
        }
        else if (line.rfind("duration=", 0) == 0)
        {
            durations[type] = std::stod(line.substr(9));
        }
        else if (line.rfind("sample_rate=", 0) == 0)
        {
            EXPECT_EQ(line, "sample_rate=48000");
        }
    }
    ASSERT_EQ(durations.count("video"), 1u) << probe.output;
    ASSERT_EQ(durations.count("audio"), 1u) << probe.output;
    EXPECT_NEAR(durations["video"], 1.5, 0.05);
    EXPECT_NEAR(durations["audio"], durations["video"], 0.05); // within half a frame
    // --audio is the same sound, as long as the video.
    EXPECT_EQ(ReadWav(dir / "demo.wav").samples.size(), 72000u);
    std::vector<std::string> left;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
    {
        left.push_back(entry.path().filename().string());
    }
    std::sort(left.begin(), left.end());
    EXPECT_EQ(left, (std::vector<std::string>{"demo.mp4", "demo.wav"})); // no scratch file left
}

TEST(CliSound, BadSoundValuesAreNamedByTheirJsonPathAndWriteNothing)
{
    const std::filesystem::path dir = ScratchDir("sound_bad");
    nlohmann::json config = nlohmann::json::parse(FileText(Scene("default.effects.json")));
    config["sound"]["maxVoices"] = 0;
    config["sound"]["rules"] = {{{"materialA", "steel"}, {"materialB", "concrete"}, {"release", -1}}};
    WriteTestFile(dir / "bad.effects.json", config.dump());
    const CliResult result =
        RunCli("run --scene grinder --seconds 1 --effects " + (dir / "bad.effects.json").string() +
               " --audio " + (dir / "a.wav").string());
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(
        result.output.find("bad.effects.json: sound.maxVoices: expected an integer in [1, 4096], found 0"),
        std::string::npos)
        << result.output;
    EXPECT_NE(
        result.output.find("bad.effects.json: sound.rules[0].release: expected a number between 0 and 10"),
        std::string::npos)
        << result.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.wav"));
}

TEST(CliSound, AudioAndVoicesOutputsAreCheckedBeforeTheRun)
{
    const std::filesystem::path dir = ScratchDir("sound_outputs");
    CliResult result = RunCli("demo --seconds 1 --audio " + (dir / "missing" / "a.wav").string());
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find("--audio: folder"), std::string::npos) << result.output;
    result = RunCli("demo --seconds 1 --audio " + (dir / "x.wav").string() + " --voices " +
                    (dir / "x.wav").string());
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find("is also the output of --audio"), std::string::npos) << result.output;
    result = RunCli("demo --seconds 86400 --audio " + (dir / "long.wav").string());
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.output.find("--audio: a WAV file holds at most"), std::string::npos) << result.output;
    EXPECT_TRUE(std::filesystem::is_empty(dir));
}

// --audio writes a WAV: a name that says otherwise (a WAV called .mp3) is refused before the run, by
// every command that takes it.
TEST(CliSound, AudioThatIsNotAWavIsRefused)
{
    const std::filesystem::path dir = ScratchDir("sound_extension");
    const std::string mp3 = (dir / "a.mp3").string();
    for (const std::string& command : std::vector<std::string>{
             "demo --seconds 0.2", "run --scene grinder --seconds 0.2",
             "render --demo --seconds 0.2 --width 48 --height 32 --out " + (dir / "f.png").string()})
    {
        const CliResult result = RunCli(command + " --audio " + mp3);
        EXPECT_EQ(result.exitCode, 1) << command << "\n" << result.output;
        EXPECT_NE(result.output.find("--audio: expected a .wav file, found \"" + mp3 + "\""),
                  std::string::npos)
            << command << "\n"
            << result.output;
        EXPECT_TRUE(std::filesystem::is_empty(dir)) << command;
    }
    // Any case of .wav is a WAV.
    const CliResult upper = RunCli("demo --seconds 0.2 --audio " + (dir / "A.WAV").string());
    EXPECT_EQ(upper.exitCode, 0) << upper.output;
}

} // namespace cfx::test
