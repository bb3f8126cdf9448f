#include "cli/InfoCommand.h"

#include "cli/CommandReport.h"
#include "common/FrameSet.h"
#include "replay/CaptureBlobs.h"
#include "stream/CallPrinter.h"
#include "stream/OpcodeMap.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

namespace nprgl::cli {

namespace {

// How CallPrinter prints a frame's kUncaptured pseudo-call: "-- not captured: glA 2, glB 1 --".
const std::string kUncapturedLine = "-- not captured: ";

// What info says, gathered once and then written as text or JSON.
struct CaptureInfo {
    std::string state; // closed, not closed, damaged
    std::map<uint32_t, uint64_t> framesPerContext;
    uint64_t framesRead = 0;
    uint64_t rawBytes = 0;
    std::map<std::string, uint64_t> calls;
    std::map<std::string, std::vector<uint64_t>> uncapturedFrames;
    // Frames whose chunk the index points at but that do not read: where and why.
    std::vector<capture::CaptureReader::Damage> frameDamage;
};

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

// Decodes every frame to count its calls by name; a frame that does not read is said and
// noted in the report.
void gather(const std::string& file, const capture::CaptureReader& reader,
            capture::ReadReport& report, CaptureInfo& info)
{
    const OpcodeMap opcodes(reader.metadata().opcodeNames);
    CaptureBlobs blobs(reader);
    std::vector<uint8_t> data;
    std::string error;
    const auto& list = reader.frames();
    for (size_t i = 0; i < list.size(); ++i) {
        if (!reader.readFrame(i, data, error)) {
            say(error + "; frame " + std::to_string(list[i].frameNumber) + " not counted");
            report.frameLost(i);
            info.frameDamage.push_back({list[i].offset, list[i].compressedSize, error});
            continue;
        }
        std::string text;
        if (!CallPrinter::printFrame(data.data(), data.size(), &blobs, &opcodes, "", text,
                                     error)) {
            say(file + ": frame " + std::to_string(list[i].frameNumber) + " at " +
                std::to_string(list[i].offset) + ": " + error + "; not counted");
            report.frameLost(i);
            info.frameDamage.push_back({list[i].offset, list[i].compressedSize, error});
            continue;
        }
        ++info.framesPerContext[list[i].contextId];
        ++info.framesRead;
        info.rawBytes += list[i].rawSize;
        for (size_t pos = 0; pos < text.size();) {
            size_t eol = std::min(text.find('\n', pos), text.size());
            size_t paren = text.find('(', pos);
            if (paren < eol && text.compare(pos, 2, "--") != 0) {
                ++info.calls[text.substr(pos, paren - pos)];
            } else if (text.compare(pos, kUncapturedLine.size(), kUncapturedLine) == 0) {
                noteUncaptured(text.substr(pos + kUncapturedLine.size(),
                                           eol - pos - kUncapturedLine.size()),
                               list[i].frameNumber, info.uncapturedFrames);
            }
            pos = eol + 1;
        }
    }
    info.state = report.damaged() ? "damaged" : reader.recovered() ? "not closed" : "closed";
}

std::string uncapturedFramesOf(const CaptureInfo& info, const std::string& name)
{
    auto it = info.uncapturedFrames.find(name);
    return it == info.uncapturedFrames.end() ? std::string() : FrameSet::describe(it->second);
}

void printText(const std::string& file, const capture::CaptureReader& reader,
               const CaptureInfo& info)
{
    const capture::Metadata& m = reader.metadata();
    std::string cmd;
    for (const std::string& a : m.commandLine) cmd += (cmd.empty() ? "" : " ") + a;
    std::printf("file:        %s (%llu bytes, format version %u%s)\n", file.c_str(),
                static_cast<unsigned long long>(reader.fileBytes()), reader.version(),
                !reader.recovered()        ? ""
                : !reader.damage().empty() ? ", recovered: damaged, read by scanning"
                                           : ", recovered: the recording did not close the file");
    std::printf("program:     %s\ncommand:     %s\npid:         %u\n", m.program.c_str(),
                cmd.c_str(), m.pid);
    std::printf("GL:          %s | %s | %s\nsize:        %dx%d\n", m.glVendor.c_str(),
                m.glRenderer.c_str(), m.glVersion.c_str(), m.width, m.height);
    for (const auto& [k, v] : m.extra) std::printf("%-12s %s\n", (k + ":").c_str(), v.c_str());
    if (!m.opcodeNames.empty()) {
        const OpcodeMap opcodes(m.opcodeNames);
        std::printf("commands:    %zu named in the file%s\n", m.opcodeNames.size(),
                    opcodes.unknownCount() == 0 ? ""
                        : (", " + std::to_string(opcodes.unknownCount()) +
                           " unknown to this nprgl").c_str());
    }
    std::printf("frames:      %llu", static_cast<unsigned long long>(info.framesRead));
    for (const auto& [ctx, n] : info.framesPerContext) {
        std::printf("  (context %u: %llu)", ctx, static_cast<unsigned long long>(n));
    }
    std::printf("\nframe bytes: %llu uncompressed\nblobs:       %zu, %llu bytes uncompressed\n",
                static_cast<unsigned long long>(info.rawBytes), reader.blobCount(),
                static_cast<unsigned long long>(reader.blobBytes()));
    std::vector<std::pair<std::string, uint64_t>> sorted(info.calls.begin(), info.calls.end());
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const auto& a, const auto& b) { return a.second > b.second; });
    std::printf("calls by name:\n");
    for (const auto& [name, n] : sorted) {
        std::printf("  %10llu  %s\n", static_cast<unsigned long long>(n), name.c_str());
    }
    // The run's totals (CNTS), and per command the frames that lack it (format 2 on).
    std::printf("not captured:\n");
    if (reader.callCounts().empty()) std::printf("  (none)\n");
    for (const auto& [name, n] : reader.callCounts()) {
        const std::string frames = uncapturedFramesOf(info, name);
        std::printf("  %10llu  %s%s\n", static_cast<unsigned long long>(n), name.c_str(),
                    frames.empty() ? "" : ("  (frames " + frames + ")").c_str());
    }
}

void printJson(const std::string& file, const capture::CaptureReader& reader,
               const capture::ReadReport& report, const CaptureInfo& info)
{
    using json = nlohmann::ordered_json; // keys in the order written here
    const capture::Metadata& m = reader.metadata();
    json contexts = json::array();
    for (const auto& [ctx, n] : info.framesPerContext) {
        contexts.push_back({{"id", ctx}, {"frames", n}});
    }
    json notCaptured = json::array();
    for (const auto& [name, n] : reader.callCounts()) {
        notCaptured.push_back(
            {{"name", name}, {"count", n}, {"frames", uncapturedFramesOf(info, name)}});
    }
    json damage = json::array();
    for (const auto* list : {&reader.damage(), &info.frameDamage}) {
        for (const auto& d : *list) {
            damage.push_back({{"offset", d.offset}, {"bytes", d.size}, {"message", d.message}});
        }
    }
    json lost = json::array();
    for (const auto& f : report.lostFrames()) {
        lost.push_back({{"context", f.contextId}, {"frame", f.frameNumber}});
    }
    json extra = json::object();
    for (const auto& [k, v] : m.extra) extra[k] = v;
    const OpcodeMap opcodes(m.opcodeNames);
    const json out = {
        {"file", file},
        {"bytes", reader.fileBytes()},
        {"formatVersion", reader.version()},
        {"state", info.state},
        {"program", m.program},
        {"commandLine", m.commandLine},
        {"pid", m.pid},
        {"gl", {{"vendor", m.glVendor}, {"renderer", m.glRenderer}, {"version", m.glVersion}}},
        {"size", {m.width, m.height}},
        {"extra", extra},
        {"commandsNamed", m.opcodeNames.size()},
        {"commandsUnknown", m.opcodeNames.empty() ? 0 : opcodes.unknownCount()},
        {"frames", info.framesRead},
        {"contexts", contexts},
        {"frameBytes", info.rawBytes},
        {"blobs", {{"count", reader.blobCount()}, {"bytes", reader.blobBytes()}}},
        {"calls", info.calls},
        {"notCaptured", notCaptured},
        {"damage", damage},
        {"framesLost", lost},
    };
    // Replacement characters for bytes that are not UTF-8 (a program's name is the file's).
    const std::string text = out.dump(2, ' ', false, json::error_handler_t::replace);
    std::printf("%s\n", text.c_str());
}

} // namespace

int infoCommand(const std::string& file, bool json)
{
    std::string error;
    capture::CaptureReader reader;
    if (!openCapture(file, reader, error)) {
        say(error);
        return 1;
    }
    capture::ReadReport report(reader);
    CaptureInfo info;
    gather(file, reader, report, info);
    if (json) {
        printJson(file, reader, report, info);
    } else {
        printText(file, reader, info);
    }
    std::fflush(stdout);
    return finish(report, info.framesRead);
}

} // namespace nprgl::cli
