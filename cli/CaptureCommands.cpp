#include "cli/CaptureCommands.h"

#include "capture/CaptureReader.h"
#include "capture/ReadReport.h"
#include "cli/CommandReport.h"
#include "frame/FrameExport.h"
#include "frame/StateTracker.h"
#include "replay/CaptureBlobs.h"
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

// "1-3, 7" for the frames of one context, to say what a selection could have chosen.
std::string framesOf(const capture::CaptureReader& reader, uint32_t context)
{
    std::vector<uint64_t> numbers;
    for (const auto& f : reader.frames())
        if (f.contextId == context) numbers.push_back(f.frameNumber);
    return numbers.empty() ? "none" : FrameSet::describe(numbers);
}

// "context 1: 1-3; context 2: 1-2".
std::string describeFrames(const capture::CaptureReader& reader)
{
    std::vector<capture::CaptureReader::FrameId> ids;
    for (const auto& f : reader.frames()) ids.push_back({f.contextId, f.frameNumber});
    return capture::ReadReport::describe(ids);
}

std::string contextsOf(const capture::CaptureReader& reader)
{
    std::vector<uint64_t> ids;
    for (const auto& f : reader.frames())
        if (std::find(ids.begin(), ids.end(), f.contextId) == ids.end()) ids.push_back(f.contextId);
    std::sort(ids.begin(), ids.end());
    return ids.empty() ? "none" : FrameSet::describe(ids);
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
        if (!rules.found) {
            return fail("--rules: " + options.rules + ": " +
                        (rules.refused.empty() ? std::string("no such file") : rules.refused));
        }
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
    if (options.overlays && !options.stats) return usage("--overlays needs --stats");
    replay.overlays = options.overlays;
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
    capture::CaptureReader reader;
    if (!openCapture(options.file, reader, error)) return fail(error);
    capture::ReadReport report(reader);
    // Nothing to replay is a failure, said before any work is done.
    const uint32_t context = options.context ? options.context : Replayer::defaultContext(reader);
    size_t inContext = 0, selected = 0, toRead = 0;
    for (const auto& f : reader.frames()) {
        if (f.contextId != context) continue;
        ++inContext;
        selected += replay.frames.empty() || replay.frames.contains(f.frameNumber);
        toRead += replay.frames.empty() || f.frameNumber <= replay.frames.last();
    }
    if (reader.frames().empty()) {
        finish(report, 0);
        return fail(options.file + ": no frame to replay");
    }
    if (inContext == 0) {
        return fail(options.file + ": --context " + std::to_string(options.context) +
                    ": no such context (the capture has context " + contextsOf(reader) + ")");
    }
    if (selected == 0) {
        return fail(options.file + ": --frames " + options.frames + " selects none of context " +
                    std::to_string(context) + "'s frames (" + framesOf(reader, context) + ")");
    }
    uint64_t written = 0;
    const bool ran = Replayer::run(reader, replay, error, &written, &report);
    // The frames so far make a playable file even when the replay stopped early.
    std::string videoError;
    const bool encoded = video.finish(videoError);
    if (ran && !encoded) return fail(videoError);
    if (!options.video.empty() && video.frames()) {
        std::fprintf(stderr, "nprgl: wrote %llu frames to %s at %d fps\n",
                     static_cast<unsigned long long>(video.frames()), options.video.c_str(),
                     options.fps);
    }
    if (!replay.outDir.empty()) {
        std::fprintf(stderr, "nprgl: wrote %llu frames to %s\n",
                     static_cast<unsigned long long>(written), replay.outDir.c_str());
    }
    if (!ran) {
        finish(report);
        return fail(error);
    }
    const int status = finish(report, toRead - report.unreadable());
    if (!replay.outDir.empty() && written == 0) {
        return fail(options.file + ": no frame could be replayed");
    }
    if (!options.video.empty() && video.frames() == 0) {
        return fail(options.video + ": no frame to write");
    }
    return status;
}

int dumpCommand(const std::string& file, const std::string& framesText, const std::string& grep)
{
    std::string error;
    FrameSet frames;
    if (!parseFrames(framesText, frames, error)) return usage("--frames: " + error);
    capture::CaptureReader reader;
    if (!openCapture(file, reader, error)) return fail(error);
    capture::ReadReport report(reader);
    CaptureBlobs blobs(reader);
    const OpcodeMap opcodes(reader.metadata().opcodeNames);
    std::vector<uint8_t> calls;
    const auto& list = reader.frames();
    // Calls are numbered from 0 in each context's stream, the frames left out included, so
    // a call keeps its number whatever --frames and --grep select (after a lost frame the
    // numbers go on without its calls).
    std::map<uint32_t, uint64_t> nextCall;
    uint64_t printed = 0;
    for (size_t i = 0; i < list.size(); ++i) {
        const bool selected = frames.empty() || frames.contains(list[i].frameNumber);
        if (!selected && list[i].frameNumber > frames.last()) continue;
        if (!reader.readFrame(i, calls, error)) {
            if (selected) {
                say(error + "; frame " + std::to_string(list[i].frameNumber) + " skipped");
                report.frameLost(i);
            }
            continue;
        }
        std::string out = "== context " + std::to_string(list[i].contextId) + " frame " +
                          std::to_string(list[i].frameNumber) + " ==\n";
        bool ok = CallPrinter::printFrame(calls.data(), calls.size(), &blobs, &opcodes, grep, out,
                                          error, nullptr, &nextCall[list[i].contextId]);
        if (!selected) continue; // numbered only; said if it is selected
        std::fwrite(out.data(), 1, out.size(), stdout);
        if (!ok) {
            // A call that does not decode (a damaged chunk whose checksum held, a lost blob):
            // the frame is printed up to it.
            std::fflush(stdout);
            say(file + ": frame " + std::to_string(list[i].frameNumber) + " at " +
                std::to_string(list[i].offset) + ": " + error + "; the rest of it skipped");
            report.frameLost(i);
            continue;
        }
        ++printed;
    }
    const int status = finish(report, printed);
    if (printed == 0) {
        return fail(list.empty() ? file + ": no frame to print"
                    : report.unreadable() > 0
                        ? file + ": no frame could be read"
                        : file + ": --frames " + framesText + " selects none of the capture's " +
                              "frames (" + describeFrames(reader) + ")");
    }
    return status;
}


int exportCommand(const std::string& file, uint64_t frame, const std::string& output,
                  const std::string& space, unsigned context)
{
    if (space != "eye" && space != "object") {
        return usage("--space: expected eye or object, got '" + space + "'");
    }
    std::string error;
    capture::CaptureReader reader;
    if (!openCapture(file, reader, error)) return fail(error);
    capture::ReadReport report(reader);
    const auto& frames = reader.frames();
    uint32_t ctx = context ? context : (frames.empty() ? 1 : frames.front().contextId);
    CaptureBlobs blobs(reader);
    const OpcodeMap opcodes(reader.metadata().opcodeNames);
    StateTracker tracker;
    std::vector<uint8_t> calls;
    uint64_t read = 0;
    // Every earlier frame runs too: it builds the lists, buffers and arrays frame N uses.
    for (size_t i = 0; i < frames.size(); ++i) {
        if (frames[i].contextId != ctx) continue;
        if (!reader.readFrame(i, calls, error)) {
            // The frames after a lost one are built on state it may have made.
            say(error + "; frame " + std::to_string(frames[i].frameNumber) + " skipped");
            report.frameLost(i);
            if (frames[i].frameNumber != frame) continue;
            finish(report, read);
            return fail(file + ": frame " + std::to_string(frame) + " could not be read");
        }
        ++read;
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
        return finish(report, read);
    }
    finish(report, read);
    return fail(file + ": no frame " + std::to_string(frame) + " in context " +
                std::to_string(ctx) + " (its frames: " + framesOf(reader, ctx) + ")");
}

} // namespace nprgl::cli
