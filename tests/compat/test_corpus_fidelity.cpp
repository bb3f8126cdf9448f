// The regression guard on real programs. CorpusGolden: small captures of real programs kept in
// the repository (tests/compat/captures, made by scripts/corpus-goldens.sh from the quick
// corpus) replayed in the default style and compared with their goldens (looked at when made).
// CorpusFidelity: the quick corpus (every 4th GL hack of Debian's
// xscreensaver-gl and -extra, a few frames each, recorded by scripts/corpus-captures.sh into
// the build folder before the tests run) replayed in `replica` and in the default style by
// `nprgl compare`. Nothing the program drew may be missing; at most a tenth of the programs
// may fall below their replica floor (fidelity-floors.tsv lists programs known to, with the GL
// feature nprgl does not follow yet).

#include "tests/support/ImageCompare.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

using namespace nprgl::test;

namespace {

namespace fs = std::filesystem;

// The targets (docs/compat.md: replica 0.90, missing 0.5%, measured by scripts/corpus.sh)
// less a margin: every run records new moments of programs that animate by the clock and
// pick their scenes at random, and the guard must not fail on a moment that is harder than
// the last. What it catches is what the issue was about: objects lost, colours changed.
constexpr double kReplicaFloor = 0.85;
constexpr double kMissingCeiling = 0.01;

struct Floor {
    double replica = kReplicaFloor;
    double missing = kMissingCeiling;
    std::string why;
};

// program  replica-floor  missing-ceiling  why (tab-separated; # comments).
std::map<std::string, Floor> readFloors()
{
    std::map<std::string, Floor> floors;
    std::ifstream in(std::string(NPRGL_TEST_SOURCE_DIR) + "/compat/fidelity-floors.tsv");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::string name, replica, missing, why;
        std::getline(fields, name, '\t');
        std::getline(fields, replica, '\t');
        std::getline(fields, missing, '\t');
        std::getline(fields, why);
        floors[name] = {std::stod(replica), std::stod(missing), why};
    }
    return floors;
}

double field(const std::string& json, const std::string& key)
{
    const size_t at = json.rfind("\"" + key + "\":");
    if (at == std::string::npos) return -1.0;
    return std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}

std::string compareJson(const std::string& capture, const std::vector<std::string>& style,
                        const std::string& json, std::string& err)
{
    std::vector<std::string> argv = {nprglCommand(), "compare", capture, "--json", json};
    argv.insert(argv.end(), style.begin(), style.end());
    const ProcessResult r = runProcess(argv);
    err = r.exitCode == 0 ? "" : "exit " + std::to_string(r.exitCode) + ": " + r.err;
    std::ifstream in(json);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace

TEST(CorpusFidelity, ReplicaIsThePictureAndTheDefaultStyleLosesNothing)
{
    const fs::path dir = fs::path(NPRGL_TEST_BINARY_DIR) / "corpus-quick";
    if (!fs::is_directory(dir)) {
        GTEST_SKIP() << dir << " does not exist: scripts/test.sh records it "
                     << "(scripts/corpus-captures.sh " << dir.string() << " --quick)";
    }
    std::vector<fs::path> captures;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        // A forked child's stream (NAME.PID.nprgl) is not the program's own.
        if (entry.path().extension() == ".nprgl" &&
            std::count(name.begin(), name.end(), '.') == 1) {
            captures.push_back(entry.path());
        }
    }
    std::sort(captures.begin(), captures.end());
    ASSERT_GE(captures.size(), 25u) << "the quick corpus is too small: see its manifest.tsv";
    const std::map<std::string, Floor> floors = readFloors();
    const std::string work = freshDir("corpus_fidelity");
    std::vector<std::string> below; // replica under its floor
    for (const fs::path& capture : captures) {
        const std::string name = capture.stem().string();
        SCOPED_TRACE(name);
        const auto listed = floors.find(name);
        const Floor floor = listed == floors.end() ? Floor() : listed->second;
        std::string err;
        const std::string replica =
            compareJson(capture.string(), {"--style", "replica"}, work + "/" + name + ".r.json",
                        err);
        EXPECT_TRUE(err.empty()) << err;
        const double median = field(replica, "fidelityMedian");
        const double missing = field(replica, "missing");
        const std::string defaults =
            compareJson(capture.string(), {}, work + "/" + name + ".d.json", err);
        EXPECT_TRUE(err.empty()) << err;
        const double defaultMissing = field(defaults, "missing");
        std::printf("corpus: %-16s replica %.3f missing %.4f; default missing %.4f%s%s\n",
                    name.c_str(), median, missing, defaultMissing,
                    floor.why.empty() ? "" : "; listed: ", floor.why.c_str());
        if (median < floor.replica) below.push_back(name + " " + std::to_string(median));
        EXPECT_LE(missing, floor.missing) << floor.why;
        EXPECT_LE(defaultMissing, floor.missing) << floor.why;
    }
    // A program may meet, at the moment this run recorded, a scene nprgl does not follow yet
    // (extrusion's shapes with normals away from the side shown, splodesic's back material): one
    // such program is a finding for the corpus benchmark, not a regression; a change that
    // breaks what nprgl follows puts many below.
    std::string list;
    for (const std::string& b : below) list += " " + b;
    EXPECT_LE(below.size(), captures.size() / 10) << "replica below its floor:" << list;
    if (!below.empty()) std::printf("corpus: replica below its floor:%s\n", list.c_str());
}

namespace {

std::vector<std::string> keptCaptures()
{
    std::vector<std::string> names;
    const fs::path dir = fs::path(NPRGL_TEST_SOURCE_DIR) / "compat" / "captures";
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (entry.path().extension() == ".nprgl") names.push_back(entry.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

} // namespace

class CorpusGolden : public ::testing::TestWithParam<std::string> {};

// The last recorded frame of a kept capture of a real program, in the default style, is its
// golden (within the tolerance of the style goldens: a channel 24 apart on at most 0.5% of the
// pixels). A change of the default look is rebased with scripts/corpus-goldens.sh, and every
// changed picture looked at.
TEST_P(CorpusGolden, DefaultStyleFrameMatchesItsGolden)
{
    const std::string name = GetParam();
    const std::string dir = std::string(NPRGL_TEST_SOURCE_DIR) + "/compat";
    const std::string capture = dir + "/captures/" + name + ".nprgl";
    const ProcessResult info = runProcess({nprglCommand(), "info", capture});
    ASSERT_EQ(info.exitCode, 0) << info.err;
    const size_t at = info.out.find("recorded_frames:");
    ASSERT_NE(at, std::string::npos) << info.out;
    const size_t dash = info.out.find('-', at);
    ASSERT_NE(dash, std::string::npos) << info.out;
    const int last = std::atoi(info.out.c_str() + dash + 1);
    ASSERT_GT(last, 0) << info.out;
    const std::string out = freshDir("corpus_golden_" + name);
    const ProcessResult r = runProcess({nprglCommand(), "replay", capture, "-o", out, "--frames",
                                        std::to_string(last)},
                                       {{"NPRGL_STYLE", ""}, {"NPRGL_CONFIG", ""},
                                        {"NPRGL_PRESET", ""}});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    char frame[64];
    std::snprintf(frame, sizeof frame, "/frame_%010d.png", last);
    const std::string golden = dir + "/golden/" + name + ".png";
    ASSERT_TRUE(fs::exists(golden)) << golden << ": run scripts/corpus-goldens.sh";
    const ImageDiff diff = compareImages(golden, out + frame, 24);
    ASSERT_TRUE(diff.comparable) << diff.error;
    nprgl::PngImage image;
    std::string error;
    ASSERT_TRUE(nprgl::PngImage::read(golden, image, error)) << error;
    EXPECT_LE(diff.differingPixels, size_t(image.width) * image.height / 200)
        << name << " in the default style differs from " << golden << " (see " << out << frame
        << ")";
}

INSTANTIATE_TEST_SUITE_P(Kept, CorpusGolden, ::testing::ValuesIn(keptCaptures()),
                         [](const auto& p) {
                             std::string n = p.param;
                             for (char& c : n) {
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             }
                             return n;
                         });

TEST(CorpusGolden, TwentyFiveProgramsAreKept)
{
    EXPECT_GE(keptCaptures().size(), 25u) << "tests/compat/captures: scripts/corpus-goldens.sh";
}
