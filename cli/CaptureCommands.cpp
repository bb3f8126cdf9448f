#include "cli/CaptureCommands.h"

#include "capture/CaptureReader.h"
#include "frame/CaptureBlobs.h"
#include "frame/FrameExport.h"
#include "frame/StateTracker.h"
#include "replay/Replayer.h"
#include "replay/VideoWriter.h"
#include "shim/ConfigFile.h"
#include "stream/CallPrinter.h"
#include "stream/OpcodeMap.h"
#include "styles/Presets.h"
#include "styles/StyleSettings.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <unistd.h>

namespace nprgl::cli {

namespace {

// A bad option value: the same exit status as CLI11's own usage errors in main.cpp.
int usage(const std::string& message)
{
    std::fprintf(stderr, "nprgl: %s\n", message.c_str());
    return 2;
}

int fail(const std::string& message)
{
    std::fprintf(stderr, "nprgl: %s\n", message.c_str());
    return 1;
}

bool parseFrames(const std::string& text, FrameSet& out, std::string& error)
{
    return text.empty() || FrameSet::parse(text, out, error);
}

} // namespace

int replayCommand(const ReplayCommandOptions& options)
{
    // A replay must never record itself, whatever the environment says.
    unsetenv("NPRGL_RECORD");
    std::string error;
    StyleSettings style;
    std::string config;
    for (const std::string& s : options.settings) config += (config.empty() ? "" : ",") + s;
    std::string chain = options.style;
    if (!Presets::combine(options.preset, chain, config, error)) return usage("--preset: " + error);
    if (!StyleSettings::parse(chain, config, style, error)) return usage(error);

    ReplayOptions replay;
    replay.config.emplace();
    replay.config->style = std::move(style);
    replay.config->programName = "nprgl";
    if (!options.rules.empty()) {
        const ConfigFile rules = ConfigFile::read(options.rules);
        if (!rules.found) return fail("--rules: cannot read " + options.rules);
        for (const std::string& e : rules.errors) {
            std::fprintf(stderr, "nprgl: %s; line skipped\n", e.c_str());
        }
        replay.config->rules = rules.rules;
        replay.config->rules.normalise();
    }
    if (!parseFrames(options.frames, replay.frames, error)) return usage("--frames: " + error);
    if (!options.size.empty() &&
        std::sscanf(options.size.c_str(), "%dx%d", &replay.width, &replay.height) != 2) {
        return usage("--size: expected WxH, got '" + options.size + "'");
    }
    replay.outDir = options.outDir;
    replay.contextId = options.context;
    replay.stats = options.stats;
    // The progress bar would interleave with the per-frame figures.
    replay.progress = isatty(STDERR_FILENO) && !options.stats;
    VideoWriter video;
    if (!options.video.empty()) {
        if (!video.open(options.video, options.fps, error)) return usage("--video: " + error);
        replay.onFrame = [&video](const PngImage& image, std::string& why) {
            return video.add(image, why);
        };
    }
    if (replay.outDir.empty() && !options.stats && options.video.empty()) {
        return usage("-o DIR or --stats is required (or --video FILE)");
    }
    if (!replay.outDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(replay.outDir, ec);
        if (ec) return fail("cannot create " + replay.outDir + ": " + ec.message());
    }
    uint64_t written = 0;
    const bool replayed = Replayer::run(options.file, replay, error, &written);
    // The frames so far make a playable file even when the replay stopped early.
    std::string videoError;
    const bool encoded = video.finish(videoError);
    if (!replayed) return fail(error);
    if (!encoded) return fail(videoError);
    if (!options.video.empty()) {
        if (!video.frames()) return fail(options.video + ": no frame to write");
        std::fprintf(stderr, "nprgl: wrote %llu frames to %s at %d fps\n",
                     static_cast<unsigned long long>(video.frames()), options.video.c_str(),
                     options.fps);
    }
    if (!replay.outDir.empty()) {
        std::fprintf(stderr, "nprgl: wrote %llu frames to %s\n",
                     static_cast<unsigned long long>(written), replay.outDir.c_str());
    }
    return 0;
}

int dumpCommand(const std::string& file, const std::string& framesText, const std::string& grep)
{
    std::string error;
    FrameSet frames;
    if (!parseFrames(framesText, frames, error)) return usage("--frames: " + error);
    capture::CaptureReader reader;
    if (!reader.open(file, error)) return fail(error);
    CaptureBlobs blobs(reader);
    const OpcodeMap opcodes(reader.metadata().opcodeNames);
    std::vector<uint8_t> calls;
    const auto& list = reader.frames();
    // Calls are numbered from 0 in each context's stream, the frames left out included, so
    // a call keeps its number whatever --frames and --grep select.
    std::map<uint32_t, uint64_t> nextCall;
    for (size_t i = 0; i < list.size(); ++i) {
        const bool selected = frames.empty() || frames.contains(list[i].frameNumber);
        if (!selected && (frames.empty() || list[i].frameNumber > frames.last())) continue;
        if (!reader.readFrame(i, calls, error)) return fail(error);
        std::string out = "== context " + std::to_string(list[i].contextId) + " frame " +
                          std::to_string(list[i].frameNumber) + " ==\n";
        bool ok = CallPrinter::printFrame(calls.data(), calls.size(), &blobs, &opcodes, grep, out,
                                          error, nullptr, &nextCall[list[i].contextId]);
        if (!selected) {
            if (!ok) return fail(file + ": frame " + std::to_string(list[i].frameNumber) +
                                 " at " + std::to_string(list[i].offset) + ": " + error);
            continue;
        }
        std::fwrite(out.data(), 1, out.size(), stdout);
        if (!ok) {
            return fail(file + ": frame " + std::to_string(list[i].frameNumber) + " at " +
                        std::to_string(list[i].offset) + ": " + error);
        }
    }
    return 0;
}

namespace {

// How CallPrinter prints a frame's kUncaptured pseudo-call: "-- not captured: glA 2, glB 1 --".
const std::string kUncapturedLine = "-- not captured: ";

void noteUncaptured(const std::string& list, uint64_t frame,
                    std::map<std::string, std::vector<uint64_t>>& frames)
{
    for (size_t pos = 0; pos < list.size();) {
        size_t end = std::min(list.find(", ", pos), list.size());
        std::string entry = list.substr(pos, end - pos);
        size_t space = entry.find(' ');
        if (space != std::string::npos) {
            std::vector<uint64_t>& seen = frames[entry.substr(0, space)];
            if (seen.empty() || seen.back() != frame) seen.push_back(frame);
        }
        pos = end + 2;
    }
}

} // namespace

int infoCommand(const std::string& file)
{
    std::string error;
    capture::CaptureReader reader;
    if (!reader.open(file, error)) return fail(error);
    const capture::Metadata& m = reader.metadata();
    std::string cmd;
    for (const std::string& a : m.commandLine) cmd += (cmd.empty() ? "" : " ") + a;
    std::printf("file:        %s (%llu bytes, format version %u%s)\n", file.c_str(),
                static_cast<unsigned long long>(reader.fileBytes()), reader.version(),
                reader.recovered() ? ", recovered: the recording did not close the file" : "");
    std::printf("program:     %s\ncommand:     %s\npid:         %u\n", m.program.c_str(),
                cmd.c_str(), m.pid);
    std::printf("GL:          %s | %s | %s\nsize:        %dx%d\n", m.glVendor.c_str(),
                m.glRenderer.c_str(), m.glVersion.c_str(), m.width, m.height);
    for (const auto& [k, v] : m.extra) std::printf("%-12s %s\n", (k + ":").c_str(), v.c_str());

    std::map<uint32_t, uint64_t> perContext;
    std::map<std::string, uint64_t> calls;
    std::map<std::string, std::vector<uint64_t>> uncapturedFrames;
    if (!m.opcodeNames.empty()) {
        const OpcodeMap opcodes(m.opcodeNames);
        std::printf("commands:    %zu named in the file%s\n", m.opcodeNames.size(),
                    opcodes.unknownCount() == 0 ? ""
                        : (", " + std::to_string(opcodes.unknownCount()) +
                           " unknown to this nprgl").c_str());
    }
    const OpcodeMap opcodes(m.opcodeNames);
    CaptureBlobs blobs(reader);
    std::vector<uint8_t> data;
    uint64_t rawBytes = 0;
    const auto& list = reader.frames();
    for (size_t i = 0; i < list.size(); ++i) {
        ++perContext[list[i].contextId];
        rawBytes += list[i].rawSize;
        if (!reader.readFrame(i, data, error)) return fail(error);
        std::string text;
        if (!CallPrinter::printFrame(data.data(), data.size(), &blobs, &opcodes, "", text,
                                     error)) {
            return fail(file + ": frame " + std::to_string(list[i].frameNumber) + ": " + error);
        }
        for (size_t pos = 0; pos < text.size();) {
            size_t eol = std::min(text.find('\n', pos), text.size());
            size_t paren = text.find('(', pos);
            if (paren < eol && text.compare(pos, 2, "--") != 0) {
                ++calls[text.substr(pos, paren - pos)];
            } else if (text.compare(pos, kUncapturedLine.size(), kUncapturedLine) == 0) {
                noteUncaptured(text.substr(pos + kUncapturedLine.size(),
                                           eol - pos - kUncapturedLine.size()),
                               list[i].frameNumber, uncapturedFrames);
            }
            pos = eol + 1;
        }
    }
    std::printf("frames:      %zu", list.size());
    for (const auto& [ctx, n] : perContext) {
        std::printf("  (context %u: %llu)", ctx, static_cast<unsigned long long>(n));
    }
    std::printf("\nframe bytes: %llu uncompressed\nblobs:       %zu, %llu bytes uncompressed\n",
                static_cast<unsigned long long>(rawBytes), reader.blobCount(),
                static_cast<unsigned long long>(reader.blobBytes()));
    std::vector<std::pair<std::string, uint64_t>> sorted(calls.begin(), calls.end());
    std::sort(sorted.begin(), sorted.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    std::printf("calls by name:\n");
    for (const auto& [name, n] : sorted) {
        std::printf("  %10llu  %s\n", static_cast<unsigned long long>(n), name.c_str());
    }
    // The run's totals (CNTS), and per command the frames that lack it (format 2 on).
    std::printf("not captured:\n");
    if (reader.callCounts().empty()) std::printf("  (none)\n");
    for (const auto& [name, n] : reader.callCounts()) {
        auto it = uncapturedFrames.find(name);
        std::string frames = it == uncapturedFrames.end()
                                 ? std::string()
                                 : "  (frames " + FrameSet::describe(it->second) + ")";
        std::printf("  %10llu  %s%s\n", static_cast<unsigned long long>(n), name.c_str(),
                    frames.c_str());
    }
    return 0;
}

} // namespace nprgl::cli

namespace nprgl::cli {

int exportCommand(const std::string& file, uint64_t frame, const std::string& output,
                  const std::string& space, unsigned context)
{
    if (space != "eye" && space != "object") {
        return usage("--space: expected eye or object, got '" + space + "'");
    }
    std::string error;
    capture::CaptureReader reader;
    if (!reader.open(file, error)) return fail(error);
    const auto& frames = reader.frames();
    uint32_t ctx = context ? context : (frames.empty() ? 1 : frames.front().contextId);
    CaptureBlobs blobs(reader);
    const OpcodeMap opcodes(reader.metadata().opcodeNames);
    StateTracker tracker;
    std::vector<uint8_t> calls;
    // Every earlier frame runs too: it builds the lists, buffers and arrays frame N uses.
    for (size_t i = 0; i < frames.size(); ++i) {
        if (frames[i].contextId != ctx) continue;
        if (!reader.readFrame(i, calls, error)) return fail(error);
        if (!tracker.runFrame(calls.data(), calls.size(), &blobs, error, &opcodes)) {
            return fail(file + ": frame " + std::to_string(frames[i].frameNumber) + " at " +
                        std::to_string(frames[i].offset) + ": " + error);
        }
        if (frames[i].frameNumber != frame) continue;
        reconstruct::Reconstructor reconstructor;
        size_t objects = 0;
        if (!exportFrame(reconstructor, tracker.frameBatches(),
                         space == "eye" ? ExportSpace::Eye : ExportSpace::Object, output, error,
                         &objects)) {
            return fail(file + ": frame " + std::to_string(frame) + ": " + error);
        }
        std::fprintf(stderr, "nprgl: wrote %zu objects of frame %llu to %s\n", objects,
                     static_cast<unsigned long long>(frame), output.c_str());
        return 0;
    }
    return fail(file + ": no frame " + std::to_string(frame) + " in context " +
                std::to_string(ctx));
}

} // namespace nprgl::cli
