// A deterministic mutation run over real captures: each input, closed and as a killed
// program leaves it (cut before its index), is copied with a flipped bit, inserted or deleted
// bytes, or cut short (a fixed seed picks which and where), and `nprgl info`, `dump` and
// `replay` (headless, two frames) run on every copy with a bounded wait. It fails on a crash
// (a signal or a sanitizer report), a hang, or a silent loss: a copy that reads fewer frames
// than its original with exit status 0 and no line on stderr naming the file.
// Writes only inside --out (default: a fresh folder under $TMPDIR); keeps the copies that
// failed there.
// Usage: mutate_captures [--count N] [--seed S] [--out DIR] [--nprgl PATH] CAPTURE...

#include "tests/support/Process.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace nprgl::test;
namespace fs = std::filesystem;

namespace {

// A command may take this long on one copy before it counts as hung (a guard, far above what
// any of them needs on these small files).
constexpr int kHangSeconds = 60;

struct Base {
    std::string name; // e.g. displaylist.closed
    std::string bytes;
};

struct Outcome {
    int exitCode = 0;
    bool hung = false;
    bool crashed = false;
    bool named = false;     // stderr has a line naming the file, other than notClosed
    bool notClosed = false; // stderr says the recording did not close the file
    long frames = -1;   // frames the command read or wrote (-1: it did not say)
};

uint64_t load64(const std::string& s, size_t at)
{
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= uint64_t(uint8_t(s[at + size_t(i)])) << (8 * i);
    return v;
}

long countOf(const std::string& text, const std::string& part)
{
    long n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

long numberAfter(const std::string& text, const std::string& label)
{
    const size_t at = text.find(label);
    return at == std::string::npos ? -1 : std::atol(text.c_str() + at + label.size());
}

Outcome run(const std::string& nprgl, const std::string& command, const std::string& file,
            const std::string& scratch)
{
    std::vector<std::string> args = {nprgl, command, file};
    if (command == "replay") {
        fs::remove_all(scratch);
        args.insert(args.end(), {"--style", "none", "--frames", "1-2", "-o", scratch});
    }
    ProcessResult r = runProcess(args, {{"NPRGL_LOG_LEVEL", ""}}, kHangSeconds);
    Outcome o;
    o.exitCode = r.exitCode;
    o.hung = r.hung;
    o.crashed = r.exitCode >= 128 || r.exitCode < 0 ||
                r.err.find("ERROR: AddressSanitizer") != std::string::npos ||
                r.err.find("runtime error:") != std::string::npos ||
                r.err.find("ERROR: LeakSanitizer") != std::string::npos;
    const std::string note = file + ": not closed by its recording";
    for (size_t at = r.err.find(file + ": "); at != std::string::npos;
         at = r.err.find(file + ": ", at + 1)) {
        if (r.err.compare(at, note.size(), note) == 0) o.notClosed = true;
        else o.named = true;
    }
    if (command == "info") o.frames = numberAfter(r.out, "frames:      ");
    if (command == "dump") o.frames = countOf(r.out, "== context ");
    if (command == "replay") o.frames = numberAfter(r.err, "nprgl: wrote ");
    return o;
}

std::string mutate(const std::string& original, std::mt19937_64& rng, std::string& kind)
{
    std::string m = original;
    const size_t size = m.size();
    switch (rng() % 4) {
    case 0: {
        const size_t at = rng() % size;
        m[at] = char(uint8_t(m[at]) ^ uint8_t(1u << (rng() % 8)));
        kind = "flip";
        break;
    }
    case 1: {
        std::string bytes(1 + rng() % 16, '\0');
        for (char& c : bytes) c = char(rng() & 0xff);
        m.insert(rng() % (size + 1), bytes);
        kind = "insert";
        break;
    }
    case 2: {
        const size_t at = rng() % size;
        m.erase(at, 1 + rng() % 16);
        kind = "delete";
        break;
    }
    default:
        m.resize(rng() % size);
        kind = "truncate";
    }
    return m;
}

} // namespace

int main(int argc, char** argv)
{
    long count = 1000;
    uint64_t seed = 1;
    std::string out, nprgl = nprglCommand();
    std::vector<std::string> inputs;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool value = i + 1 < argc;
        if (arg == "--count" && value) count = std::atol(argv[++i]);
        else if (arg == "--seed" && value) seed = std::strtoull(argv[++i], nullptr, 10);
        else if (arg == "--out" && value) out = argv[++i];
        else if (arg == "--nprgl" && value) nprgl = argv[++i];
        else if (arg.rfind("--", 0) == 0) {
            std::fprintf(stderr, "usage: mutate_captures [--count N] [--seed S] [--out DIR] "
                                 "[--nprgl PATH] CAPTURE...\n");
            return 2;
        } else inputs.push_back(arg);
    }
    if (inputs.empty() || count <= 0) {
        std::fprintf(stderr, "mutate_captures: no captures given\n");
        return 2;
    }
    if (out.empty()) {
        std::string pattern = (fs::temp_directory_path() / "nprgl-mutate-XXXXXX").string();
        if (!mkdtemp(pattern.data())) return 2;
        out = pattern;
    }
    fs::create_directories(out + "/failures");

    // Each input closed (as given) and unclosed: cut where its index starts.
    std::vector<Base> bases;
    for (const std::string& input : inputs) {
        const std::string bytes = readAll(input);
        const std::string stem = fs::path(input).stem().string();
        if (bytes.size() < 64) {
            std::fprintf(stderr, "mutate_captures: %s is too short\n", input.c_str());
            return 2;
        }
        bases.push_back({stem + ".closed", bytes});
        const uint64_t indexAt = load64(bytes, bytes.size() - 8);
        if (indexAt > 16 && indexAt < bytes.size()) {
            bases.push_back({stem + ".unclosed", bytes.substr(0, size_t(indexAt))});
        }
    }
    const std::vector<std::string> commands = {"info", "dump", "replay"};
    std::map<std::string, std::vector<Outcome>> reference;
    for (const Base& base : bases) {
        const std::string path = out + "/" + base.name + ".nprgl";
        writeAll(path, base.bytes);
        for (const std::string& command : commands) {
            Outcome o = run(nprgl, command, path, out + "/replay");
            if (o.exitCode != 0 || o.frames < 0) {
                std::fprintf(stderr, "mutate_captures: %s %s fails on the original (%d)\n",
                             command.c_str(), path.c_str(), o.exitCode);
                return 2;
            }
            reference[base.name].push_back(o);
        }
    }

    std::mt19937_64 rng(seed);
    std::map<std::string, long> tally; // "kind outcome" -> count
    long failures = 0;
    for (long i = 0; i < count; ++i) {
        const Base& base = bases[size_t(rng() % bases.size())];
        std::string kind;
        const std::string bytes = mutate(base.bytes, rng, kind);
        const std::string path = out + "/mutant.nprgl";
        writeAll(path, bytes);
        std::string worst = bytes == base.bytes ? "unchanged" : "said";
        std::string why;
        bool quiet = true;
        for (size_t c = 0; c < commands.size(); ++c) {
            const Outcome o = run(nprgl, commands[c], path, out + "/replay");
            const Outcome& ref = reference[base.name][c];
            quiet = quiet && !o.named && !o.notClosed && o.exitCode == 0;
            if (o.crashed || o.hung) {
                worst = o.hung ? "HUNG" : "CRASHED";
                why = commands[c] + (o.hung ? " hung" : " crashed (" +
                                                            std::to_string(o.exitCode) + ")");
                break;
            }
            if (bytes != base.bytes && o.exitCode == 0 && !o.named && o.frames < ref.frames &&
                o.notClosed) {
                // A cut at a chunk boundary: the same file as a recording stopped earlier
                // leaves, and said as such; nothing in the file can tell them apart.
                worst = "said only as not closed (a clean cut)";
                continue;
            }
            if (bytes != base.bytes && o.exitCode == 0 && !o.named && o.frames < ref.frames) {
                worst = "SILENT LOSS";
                why = commands[c] + " read " + std::to_string(o.frames) + " frames of " +
                      std::to_string(ref.frames) + " and said nothing";
                break;
            }
        }
        if (worst == "said" && quiet) worst = "read whole, nothing said";
        ++tally[kind + " " + worst];
        if (worst == "HUNG" || worst == "CRASHED" || worst == "SILENT LOSS") {
            ++failures;
            const std::string keep = out + "/failures/" + std::to_string(i) + "-" + base.name +
                                     "-" + kind + ".nprgl";
            writeAll(keep, bytes);
            std::printf("mutant %ld (%s of %s): %s: %s; kept as %s\n", i, kind.c_str(),
                        base.name.c_str(), worst.c_str(), why.c_str(), keep.c_str());
        }
    }
    fs::remove(out + "/mutant.nprgl");
    fs::remove_all(out + "/replay");
    std::printf("mutate_captures: %ld mutants of %zu captures (seed %llu), 3 commands each:\n",
                count, bases.size(), static_cast<unsigned long long>(seed));
    for (const auto& [what, n] : tally) std::printf("  %6ld  %s\n", n, what.c_str());
    std::printf("mutate_captures: %ld failures (crash, hang or silent loss)\n", failures);
    return failures == 0 ? 0 : 1;
}
