// End to end: what `nprgl info`, `dump`, `replay`, `export` and `compare` say and return on
// damaged and unclosed captures, special files, and selections that choose nothing.

#include "capture/CaptureReader.h"
#include "common/PngImage.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/stat.h>
#include <vector>

using namespace nprgl;
using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

// The fixture's frame chunks and where its index starts (the end of a killed program's file).
struct Layout {
    std::vector<capture::CaptureReader::FrameInfo> frames;
    uint64_t indexAt = 0;
};

Layout layoutOf(const std::string& path)
{
    Layout layout;
    capture::CaptureReader reader;
    std::string error;
    EXPECT_TRUE(reader.open(path, error)) << error;
    layout.frames = reader.frames();
    const std::string bytes = readAll(path);
    for (int i = 0; i < 8; ++i)
        layout.indexAt |= uint64_t(uint8_t(bytes[bytes.size() - 8 + size_t(i)])) << (8 * i);
    return layout;
}

// The byte in the middle of frame i's stored calls.
size_t insideFrame(const Layout& layout, size_t i)
{
    return size_t(layout.frames[i].offset + 48 + layout.frames[i].compressedSize / 2);
}

ProcessResult run(std::vector<std::string> args)
{
    args.insert(args.begin(), nprglCommand());
    // A bounded wait: a command blocked on a FIFO or reading /dev/zero would hang here.
    return runProcess(args, {{"NPRGL_LOG_LEVEL", ""}}, 120);
}

bool has(const std::string& text, const std::string& part)
{
    return text.find(part) != std::string::npos;
}

} // namespace

// A flipped bit in a closed capture's frame 2: every command says where, reads the others,
// and exits 1 (replay used to stop there with the frames after it unwritten).
TEST(CaptureCommands, ADamagedFrameIsSaidWithItsOffsetAndTheOthersAreRead)
{
    const std::string dir = freshDir("capture-commands");
    const Layout layout = layoutOf(fixture("displaylist"));
    ASSERT_EQ(layout.frames.size(), 3u);
    std::string bytes = readAll(fixture("displaylist"));
    bytes[insideFrame(layout, 1)] ^= 0x10;
    const std::string file = dir + "/flipped.nprgl";
    writeAll(file, bytes);
    const std::string where = file + ": offset " + std::to_string(layout.frames[1].offset) +
                              ": checksum mismatch in 'FRAM' chunk";
    const std::string summary = file + ": damaged: 2 frames read, 1 lost (context 1: 2)";

    ProcessResult info = run({"info", file});
    EXPECT_EQ(info.exitCode, 1) << info.err;
    EXPECT_TRUE(has(info.err, where)) << info.err;
    EXPECT_TRUE(has(info.err, summary)) << info.err;
    EXPECT_TRUE(has(info.out, "frames:      2")) << info.out;

    ProcessResult dump = run({"dump", file});
    EXPECT_EQ(dump.exitCode, 1) << dump.err;
    EXPECT_TRUE(has(dump.out, "== context 1 frame 3 ==")) << dump.out;
    EXPECT_TRUE(has(dump.err, summary)) << dump.err;

    ProcessResult replay = run({"replay", "--style", "none", file, "-o", dir + "/out"});
    EXPECT_EQ(replay.exitCode, 1) << replay.err;
    EXPECT_TRUE(has(replay.err, where)) << replay.err;
    EXPECT_TRUE(has(replay.err, summary)) << replay.err;
    EXPECT_TRUE(fs::exists(framePng(dir + "/out", 1)));
    EXPECT_FALSE(fs::exists(framePng(dir + "/out", 2)));
    EXPECT_TRUE(fs::exists(framePng(dir + "/out", 3)));

    ProcessResult exported = run({"export", file, "--frame", "3", "-o", dir + "/f3.obj"});
    EXPECT_EQ(exported.exitCode, 1) << exported.err;
    EXPECT_TRUE(has(exported.err, where)) << exported.err;
    EXPECT_TRUE(fs::exists(dir + "/f3.obj"));
}

// The issue's two cases: ten bytes inserted into a closed capture (read as "the recording did
// not close the file, frames: 0") and a flipped bit in an unclosed one (read as a prefix with
// no word). Both are damage, said with the offset; the frames after it are read.
TEST(CaptureCommands, InsertedBytesAndAFlipInAnUnclosedFileAreDamageNotAnEarlyEnd)
{
    const std::string dir = freshDir("capture-commands");
    const Layout layout = layoutOf(fixture("displaylist"));
    const std::string good = readAll(fixture("displaylist"));

    const std::string inserted = dir + "/inserted.nprgl";
    const size_t at = size_t(layout.frames[1].offset);
    writeAll(inserted, good.substr(0, at) + "0123456789" + good.substr(at));
    ProcessResult info = run({"info", inserted});
    EXPECT_EQ(info.exitCode, 1) << info.err;
    EXPECT_FALSE(has(info.out, "did not close")) << info.out;
    EXPECT_TRUE(has(info.out, "recovered: damaged")) << info.out;
    EXPECT_TRUE(has(info.out, "frames:      3")) << info.out;
    EXPECT_TRUE(has(info.err, inserted + ": offset " + std::to_string(at) + ": ")) << info.err;
    EXPECT_TRUE(has(info.err, inserted + ": damaged: 3 frames read, no frame lost")) << info.err;

    std::string unclosed = good.substr(0, size_t(layout.indexAt));
    const std::string open = dir + "/unclosed.nprgl";
    writeAll(open, unclosed);
    info = run({"info", open});
    EXPECT_EQ(info.exitCode, 0) << info.err;
    EXPECT_TRUE(has(info.err, open + ": not closed by its recording")) << info.err;
    EXPECT_TRUE(has(info.out, "frames:      3")) << info.out;
    ProcessResult replay = run({"replay", "--style", "none", open, "-o", dir + "/open"});
    EXPECT_EQ(replay.exitCode, 0) << replay.err;

    unclosed[insideFrame(layout, 0)] ^= 0x01;
    const std::string flipped = dir + "/unclosed-flipped.nprgl";
    writeAll(flipped, unclosed);
    info = run({"info", flipped});
    EXPECT_EQ(info.exitCode, 1) << info.err;
    EXPECT_TRUE(has(info.err, flipped + ": offset " + std::to_string(layout.frames[0].offset) +
                                  ": checksum mismatch"))
        << info.err;
    EXPECT_TRUE(has(info.out, "frames:      2")) << info.out;
    // Frame 1 is the first: no gap in the numbering shows it, and no index lists it.
    EXPECT_TRUE(has(info.err, "frames lost in the damaged bytes cannot be counted")) << info.err;
}

// A file with no readable frame, and selections that choose nothing: exit 1 with the reason
// (they used to end with "wrote 0 frames" and exit 0).
TEST(CaptureCommands, NothingProducedIsAFailureWithItsReason)
{
    const std::string dir = freshDir("capture-commands");
    const std::string file = fixture("displaylist");
    ProcessResult r = run({"replay", file, "--frames", "7-9", "-o", dir + "/a"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, file + ": --frames 7-9 selects none of context 1's frames (1-3)"))
        << r.err;
    r = run({"replay", file, "--context", "5", "-o", dir + "/b"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, "--context 5: no such context (the capture has context 1)")) << r.err;
    r = run({"replay", file, "--frames", "9", "--stats"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    r = run({"dump", file, "--frames", "4-"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, "--frames 4- selects none of the capture's frames (context 1: 1-3)"))
        << r.err;
    r = run({"export", file, "--frame", "9", "-o", dir + "/x.obj"});
    EXPECT_EQ(r.exitCode, 1) << r.err;

    // Every frame damaged: an unclosed file whose frame chunks all fail their checksum.
    const Layout layout = layoutOf(file);
    std::string bytes = readAll(file).substr(0, size_t(layout.indexAt));
    for (size_t i = 0; i < layout.frames.size(); ++i) bytes[insideFrame(layout, i)] ^= 0x08;
    const std::string none = dir + "/none.nprgl";
    writeAll(none, bytes);
    r = run({"replay", none, "-o", dir + "/c"});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, none + ": no frame to replay")) << r.err;
    r = run({"dump", none});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, none + ": no frame to print")) << r.err;
}

// FIFOs, devices and directories given as a capture are refused at once with the right
// reason (a FIFO used to block every command forever).
TEST(CaptureCommands, SpecialFilesAreRefusedAtOnce)
{
    const std::string dir = freshDir("capture-commands");
    const std::string fifo = dir + "/pipe.nprgl";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {fifo, "is a FIFO (named pipe), not a capture file"},
        {"/dev/zero", "is a character device, not a capture file"},
        {"/dev/urandom", "is a character device, not a capture file"},
        {dir, "is a directory, not a capture file"},
        {fixture("displaylist") + "/x.nprgl", "cannot open: Not a directory"},
    };
    for (const auto& [path, reason] : cases) {
        for (std::vector<std::string> args :
             {std::vector<std::string>{"info", path}, {"dump", path},
              {"replay", path, "-o", dir + "/out"}, {"export", path, "--frame", "1", "-o",
                                                     dir + "/x.obj"},
              {"compare", path}}) {
            ProcessResult r = run(args);
            SCOPED_TRACE(args[0] + " " + path);
            EXPECT_FALSE(r.hung);
            EXPECT_EQ(r.exitCode, 1) << r.err;
            EXPECT_TRUE(has(r.err, "nprgl: " + path + ": " + reason)) << r.err;
        }
    }
}

namespace {

const std::vector<std::string> kProgram = {demo("immediate"), "--offscreen", "--frames", "2",
                                           "--size", "32x32"};

ProcessResult record(const std::vector<std::string>& options)
{
    std::vector<std::string> args = {nprglCommand(), "record", "--style", "none"};
    args.insert(args.end(), options.begin(), options.end());
    args.push_back("--");
    args.insert(args.end(), kProgram.begin(), kProgram.end());
    return runProcess(args, {{"NPRGL_LOG_LEVEL", ""}}, 120);
}

// The program alone with the library preloaded and NPRGL_RECORD set: the shim's recorder.
ProcessResult recordByEnvironment(const std::string& file, const std::string& force = "")
{
    return runProcess(kProgram,
                      {{"LD_PRELOAD", preloadValue()}, {"NPRGL_RECORD", file},
                       {"NPRGL_STYLE", "none"}, {"NPRGL_RECORD_FORCE", force},
                       {"NPRGL_RECORD_PID", ""}, {"NPRGL_LOG_LEVEL", ""}},
                      120);
}

int framesIn(const std::string& file)
{
    capture::CaptureReader reader;
    std::string error;
    return reader.open(file, error) ? int(reader.frames().size()) : -1;
}

} // namespace

// `nprgl record -o notes.txt` used to replace the text file with a capture (and, run as root,
// NPRGL_RECORD could overwrite a system file): a file that is not a capture is never
// overwritten; a capture only with --force, or by the variable under a new name beside it.
TEST(CaptureCommands, RecordingNeverOverwritesWhatIsNotOurs)
{
    const std::string dir = freshDir("capture-commands");
    const std::string notes = dir + "/notes.txt";
    writeAll(notes, "my notes\n");
    ProcessResult r = record({"-o", notes});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, "nprgl: cannot record to " + notes +
                               ": it exists and is not an nprgl capture"))
        << r.err;
    EXPECT_FALSE(has(r.err, "recording to")) << "the program started: " << r.err;
    EXPECT_EQ(readAll(notes), "my notes\n");
    // The shim: the program runs as it would, unrecorded, and says why.
    r = recordByEnvironment(notes);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(has(r.err, "not recording: " + notes + " exists and is not an nprgl capture"))
        << r.err;
    EXPECT_EQ(readAll(notes), "my notes\n");

    const std::string capture = dir + "/run.nprgl";
    r = record({"-o", capture});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const std::string first = readAll(capture);
    r = record({"-o", capture});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_TRUE(has(r.err, capture + " is a capture already; --force replaces it")) << r.err;
    EXPECT_EQ(readAll(capture), first);
    r = record({"--force", "-o", capture});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(framesIn(capture), 2);
    EXPECT_NE(readAll(capture), first); // a new recording (another start time and pid)

    const std::string kept = readAll(capture);
    r = recordByEnvironment(capture);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(has(r.err, capture + " is a capture already: recording to " + dir +
                               "/run.1.nprgl instead"))
        << r.err;
    EXPECT_EQ(readAll(capture), kept);
    EXPECT_EQ(framesIn(dir + "/run.1.nprgl"), 2);
    r = recordByEnvironment(capture, "1");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(readAll(capture), kept);
    EXPECT_FALSE(fs::exists(dir + "/run.2.nprgl"));
}

// A FIFO, a device or a directory as the recording: refused at once by the command, before
// the program starts; the shim runs the program unrecorded (a FIFO used to hang it at start).
TEST(CaptureCommands, RecordingToASpecialFileIsRefusedAtOnce)
{
    const std::string dir = freshDir("capture-commands");
    const std::string fifo = dir + "/pipe.nprgl";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    for (const auto& [path, reason] : std::vector<std::pair<std::string, std::string>>{
             {fifo, "is a FIFO (named pipe)"},
             {"/dev/null", "is a character device"},
             {dir, "is a directory"}}) {
        SCOPED_TRACE(path);
        ProcessResult r = record({"-o", path});
        EXPECT_FALSE(r.hung);
        EXPECT_EQ(r.exitCode, 1) << r.err;
        EXPECT_TRUE(has(r.err, "nprgl: cannot record to " + path + ": it " + reason)) << r.err;
        r = recordByEnvironment(path);
        EXPECT_FALSE(r.hung);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        EXPECT_TRUE(has(r.err, "not recording: " + path + " " + reason)) << r.err;
    }
}

// `nprgl info --json` is for scripts: one object with what the text says, and the damage with
// its offsets and the frames lost.
TEST(CaptureCommands, InfoAsJsonSaysWhatTheTextSays)
{
    ProcessResult text = run({"info", fixture("glxgears")});
    ASSERT_EQ(text.exitCode, 0) << text.err;
    ProcessResult json = run({"info", "--json", fixture("glxgears")});
    ASSERT_EQ(json.exitCode, 0) << json.err;
    const nlohmann::json whole = nlohmann::json::parse(json.out);
    EXPECT_EQ(whole["state"], "closed");
    EXPECT_TRUE(has(text.out, "frames:      " + std::to_string(whole["frames"].get<int>())))
        << text.out;
    EXPECT_TRUE(has(text.out, "program:     " + whole["program"].get<std::string>()));
    ASSERT_TRUE(whole["calls"].contains("glClear")) << json.out.substr(0, 2000);
    const std::string clears = std::to_string(whole["calls"]["glClear"].get<int>());
    EXPECT_TRUE(has(text.out, std::string(10 - clears.size(), ' ') + clears + "  glClear"))
        << text.out;
    EXPECT_EQ(whole["contexts"].size(), 1u);
    EXPECT_TRUE(whole["damage"].empty());

    const std::string dir = freshDir("info-json");
    const Layout layout = layoutOf(fixture("displaylist"));
    std::string bytes = readAll(fixture("displaylist"));
    bytes[insideFrame(layout, 1)] ^= 0x10;
    const std::string file = dir + "/flipped.nprgl";
    writeAll(file, bytes);
    ProcessResult damaged = run({"info", "--json", file});
    EXPECT_EQ(damaged.exitCode, 1) << damaged.err;
    const nlohmann::json d = nlohmann::json::parse(damaged.out);
    EXPECT_EQ(d["state"], "damaged");
    EXPECT_EQ(d["frames"], 2);
    ASSERT_EQ(d["damage"].size(), 1u) << damaged.out;
    EXPECT_EQ(d["damage"][0]["offset"], layout.frames[1].offset);
    ASSERT_EQ(d["framesLost"].size(), 1u) << damaged.out;
    EXPECT_EQ(d["framesLost"][0]["frame"], 2);
}
