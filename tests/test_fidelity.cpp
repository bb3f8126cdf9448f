// The fidelity oracle on the project's own captures: in the `replica` style every fixture
// must come out as the program drew it (nprgl compare), and the default style must lose
// nothing the program drew and keep every object's hue.

#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

using namespace nprgl::test;

namespace {

struct Summary {
    double median = -1.0, min = -1.0, missing = -1.0;
    long paletteObjects = -1, paletteFailures = -1;
    long overlayDraws = -1, overlaysShort = -1;
    std::string json;
};

// A number after "key": in compare's JSON.
double field(const std::string& json, const std::string& key)
{
    const size_t at = json.rfind("\"" + key + "\":");
    if (at == std::string::npos) return -1.0;
    return std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}

Summary compare(const std::string& capture, const std::vector<std::string>& style,
                const std::string& name)
{
    const std::string json = freshDir("fidelity_" + name) + "/out.json";
    std::vector<std::string> argv = {nprglCommand(), "compare", capture, "--json", json};
    argv.insert(argv.end(), style.begin(), style.end());
    const ProcessResult r = runProcess(argv);
    Summary s;
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::ifstream in(json);
    std::stringstream text;
    text << in.rdbuf();
    s.json = text.str();
    s.median = field(s.json, "fidelityMedian");
    s.min = field(s.json, "fidelityMin");
    s.missing = field(s.json, "missing");
    s.paletteObjects = long(field(s.json, "paletteObjects"));
    s.paletteFailures = long(field(s.json, "paletteFailures"));
    s.overlayDraws = long(field(s.json, "overlayDraws"));
    s.overlaysShort = long(field(s.json, "overlaysShort"));
    return s;
}

class FixtureFidelity : public ::testing::TestWithParam<std::string> {};

} // namespace

// Where nprgl followed the program, replica equals native up to rasterisation.
TEST_P(FixtureFidelity, ReplicaIsThePicture)
{
    const Summary s = compare(fixture(GetParam()), {"--style", "replica"}, GetParam() + "_r");
    std::printf("fidelity: %-16s replica median %.3f min %.3f missing %.4f\n",
                GetParam().c_str(), s.median, s.min, s.missing);
    EXPECT_GE(s.median, 0.97);
    EXPECT_GE(s.min, 0.95);
    EXPECT_LE(s.missing, 0.005);
}

// The default style restyles, but loses nothing the program drew and keeps each object's hue.
TEST_P(FixtureFidelity, DefaultStyleLosesNothingAndKeepsHues)
{
    const Summary s = compare(fixture(GetParam()), {}, GetParam() + "_d");
    EXPECT_LE(s.missing, 0.005);
    EXPECT_GT(s.paletteObjects, 0) << "no object judged: no test";
    EXPECT_EQ(s.json.find("\"hueKept\": false"), std::string::npos) << s.json.substr(0, 3000);
    // Every 2D draw keeps the smaller of its own contrast and 4.5:1 (issue 39's rule).
    EXPECT_EQ(s.overlaysShort, 0) << s.json.substr(0, 3000);
    EXPECT_EQ(field(s.json, "overlayFramesUnjudged"), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, FixtureFidelity,
                         ::testing::Values("arrays", "arrays_vbo", "character_morph",
                                           "character_rigid", "character_skin", "displaylist",
                                           "dlopen", "glxgears", "immediate", "overlay",
                                           "textured"));

// The frame's background is the colour its last clear of the whole window left, told by the
// native replay. demo_immediate --frame covers the window's border with a band after its
// clear (the border's commonest colour is the band's) and clears a corner through a scissor
// in yellow after the whole-window clear (the last clear, but not of the whole window).
TEST(Compare, TheBackgroundIsWhatTheFrameClearedTheWholeWindowTo)
{
    const std::string dir = freshDir("compare_clear");
    const std::string file = dir + "/framed.nprgl";
    const ProcessResult record =
        runProcess({nprglCommand(), "record", "--style", "none", "-o", file, "--",
                    demo("immediate"), "--frame", "--offscreen", "--frames", "3", "--size",
                    "160x120"});
    ASSERT_EQ(record.exitCode, 0) << record.err;
    const ProcessResult stats =
        runProcess({nprglCommand(), "replay", file, "--style", "none", "--stats"});
    ASSERT_EQ(stats.exitCode, 0) << stats.err;
    // glClearColor(0.10, 0.12, 0.16) in an 8-bit window.
    EXPECT_NE(stats.out.find("frame 3: background: cleared to 26 31 41\n"), std::string::npos)
        << stats.out;
    const Summary s = compare(file, {"--style", "replica"}, "framed");
    const std::string told = "\"clear\": [26, 31, 41], \"clearFrom\": \"stream\"";
    size_t frames = 0;
    for (size_t at = 0; (at = s.json.find("\"clear\": ", at)) != std::string::npos; ++at) {
        ++frames;
        EXPECT_EQ(s.json.compare(at, told.size(), told), 0) << s.json.substr(at, 60);
    }
    EXPECT_EQ(frames, 3u);
    EXPECT_GE(s.median, 0.97);
}

// demo_overlay draws pale text and a white frame over its dark scene. On the page that
// follows the program (dark) they keep their contrast; on a light page forced over them they
// do not, and compare says so per draw.
TEST(Compare, OverlaysKeepTheirContrastOnlyOnAPageOfTheProgramsTone)
{
    const Summary dark = compare(fixture("overlay"), {"--frames", "1-3"}, "overlay_auto");
    EXPECT_GE(dark.overlayDraws, 3 * 20) << "the HUD's glyphs, panel and bar were not judged";
    EXPECT_EQ(dark.overlaysShort, 0) << dark.json.substr(0, 3000);
    const Summary light = compare(fixture("overlay"), {"--frames", "1-3", "--set",
                                                       "paper.tone=light"}, "overlay_light");
    EXPECT_EQ(light.overlayDraws, dark.overlayDraws);
    EXPECT_GE(light.overlaysShort, 3 * 11) << "the pale title's glyphs on a light page";
    EXPECT_NE(light.json.find("\"short\": [{\"draw\": "), std::string::npos);
}

TEST(Compare, OverlaysWithoutStatsIsAUsageError)
{
    const ProcessResult r =
        runProcess({nprglCommand(), "replay", fixture("overlay"), "--overlays"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--overlays needs --stats"), std::string::npos) << r.err;
}

TEST(Compare, AFileThatIsNoCaptureExitsOneWithItsName)
{
    const std::string dir = freshDir("compare_bad");
    const std::string bad = dir + "/notes.nprgl";
    std::ofstream(bad) << "not a capture\n";
    const ProcessResult r = runProcess({nprglCommand(), "compare", bad, "--style", "replica"});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_NE(r.err.find("notes.nprgl"), std::string::npos) << r.err;
}

TEST(Compare, FramesThatSelectNothingAreAnError)
{
    const ProcessResult r = runProcess(
        {nprglCommand(), "compare", fixture("glxgears"), "--frames", "500-600"});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_NE(r.err.find("selects none of context 1's frames"), std::string::npos) << r.err;
}
