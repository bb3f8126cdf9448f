// End to end: outline accuracy against demo_shapes' ray-cast silhouettes. Each outline style
// runs alone, so the program's shading stays and outline pixels are the pixels that differ
// from the native frame. Precision: share of outline pixels within 1.5 px of a truth pixel;
// recall: share of truth pixels within 1.5 px of an outline pixel (docs/benchmarks.md,
// "Outline accuracy"). Set NPRGL_KEEP_TEST_FILES=1 to keep the overlays (truth in red).

#include "common/PngImage.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace nprgl;
using namespace nprgl::test;

namespace {

const std::vector<int> kFrames = {1, 40, 80}; // 0, 19.5 and 39.5 degrees of the default step
constexpr int kSize = 512;
// Per channel, as bench/outline_metrics.py --tolerance: above llvmpipe's rounding, below ink.
constexpr int kTolerance = 24;

struct AccuracyCase {
    std::string name, style;
    std::vector<std::string> settings; // --set values
    // Floors: the measured minimum over the frames minus about 0.05 (docs/benchmarks.md).
    double minPrecision = 0, minRecall = 0;
    bool optional = false; // skipped, not failed, when the style is not registered
};

void PrintTo(const AccuracyCase& c, std::ostream* os) { *os << c.name; }

// Wireframe's lines are 4 px wide, half outside the silhouette, and perpixel's band widens
// where the surface turns slowly: both lose precision within 1.5 px by design (the docs).
const std::vector<AccuracyCase> kCases = {
    {"wireframe", "wireframe", {}, 0.62, 0.94},
    {"perpixel", "perpixel", {}, 0.67, 0.84},
    {"edges", "edges", {}, 0.89, 0.95},
    {"strokes_depth", "strokes", {"strokes.visibility=depth"}, 0.83, 0.94, true},
    {"strokes_query", "strokes", {"strokes.visibility=query"}, 0.82, 0.94, true},
};

using Mask = std::vector<uint8_t>;

// Pixels within 1.5 px (the 8 neighbours and the pixel itself) of a set pixel.
Mask dilate(const Mask& m, int w, int h)
{
    Mask rows(m.size(), 0), out(m.size(), 0);
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            rows[i] = m[i] | (x > 0 ? m[i - 1] : 0) | (x + 1 < w ? m[i + 1] : 0);
        }
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            out[i] = rows[i] | (y > 0 ? rows[i - w] : 0) | (y + 1 < h ? rows[i + w] : 0);
        }
    }
    return out;
}

struct Score {
    size_t outlinePixels = 0, truthPixels = 0;
    double precision = 0, recall = 0;
};

Score score(const Mask& outline, const Mask& truth, int w, int h)
{
    const Mask nearTruth = dilate(truth, w, h), nearOutline = dilate(outline, w, h);
    size_t precise = 0, found = 0;
    Score s;
    for (size_t i = 0; i < outline.size(); ++i) {
        s.outlinePixels += outline[i];
        s.truthPixels += truth[i];
        precise += outline[i] & nearTruth[i];
        found += truth[i] & nearOutline[i];
    }
    // An empty outline has no precise pixels: a style drawing nothing scores 0, not NaN.
    s.precision = s.outlinePixels ? double(precise) / s.outlinePixels : 0.0;
    s.recall = s.truthPixels ? double(found) / s.truthPixels : 0.0;
    return s;
}

bool readPng(const std::string& path, PngImage& image)
{
    std::string error;
    if (PngImage::read(path, image, error)) return true;
    ADD_FAILURE() << error;
    return false;
}

std::vector<std::string> shapesArgs(const std::string& dir)
{
    std::string frames;
    for (int f : kFrames) frames += (frames.empty() ? "" : ",") + std::to_string(f);
    return {binDir() + "/demo_shapes", "--offscreen", "--size",
            std::to_string(kSize) + "x" + std::to_string(kSize), "--frames",
            std::to_string(kFrames.back()), "--save-dir", dir, "--save-frames", frames};
}

std::string framePath(const std::string& dir, int frame, const char* suffix = "")
{
    return dir + "/shapes_" + std::to_string(frame) + suffix + ".png";
}

class OutlineAccuracy : public ::testing::TestWithParam<AccuracyCase> {
protected:
    // The native frames and the truth are the same for every style: rendered once.
    static void SetUpTestSuite()
    {
        nativeDir_ = freshDir("accuracy_native");
        std::vector<std::string> args = shapesArgs(nativeDir_);
        args.insert(args.end(), {"--truth", nativeDir_});
        ProcessResult r = runProcess(args);
        nativeError_ = r.exitCode == 0 ? "" : "native demo_shapes failed: " + r.err;
        ProcessResult list = runProcess({binDir() + "/nprgl", "styles"});
        styles_ = list.out;
    }

    static std::string nativeDir_, nativeError_, styles_;
};

std::string OutlineAccuracy::nativeDir_, OutlineAccuracy::nativeError_, OutlineAccuracy::styles_;

} // namespace

TEST_P(OutlineAccuracy, OutlinesLieOnTheAnalyticSilhouettes)
{
    const AccuracyCase& c = GetParam();
    ASSERT_EQ(nativeError_, "");
    // A style still being written may not be registered yet, nor its parameters.
    if (styles_.find("\n" + c.style + " [") == std::string::npos) {
        if (c.optional) GTEST_SKIP() << c.style << " is not registered";
        FAIL() << c.style << " is not registered:\n" << styles_;
    }
    for (const std::string& setting : c.settings) {
        const std::string key = setting.substr(0, setting.find('='));
        const std::string value = setting.substr(setting.find('=') + 1);
        const size_t at = styles_.find("    " + key + " ");
        const size_t end = styles_.find('\n', at);
        if (at == std::string::npos
            || styles_.substr(at, end - at).find(value) == std::string::npos) {
            GTEST_SKIP() << setting << " is not available";
        }
    }

    const std::string dir = freshDir("accuracy_" + c.name);
    std::vector<std::string> args = {binDir() + "/nprgl", "--style", c.style};
    for (const std::string& setting : c.settings) args.insert(args.end(), {"--set", setting});
    args.push_back("--");
    const std::vector<std::string> app = shapesArgs(dir);
    args.insert(args.end(), app.begin(), app.end());
    ProcessResult r = runProcess(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;

    for (int frame : kFrames) {
        PngImage native, styled, truth;
        if (!readPng(framePath(nativeDir_, frame), native)
            || !readPng(framePath(dir, frame), styled)
            || !readPng(framePath(nativeDir_, frame, "_truth"), truth)) {
            return;
        }
        ASSERT_EQ(styled.rgba.size(), native.rgba.size());
        ASSERT_EQ(truth.rgba.size(), native.rgba.size());
        const int w = native.width, h = native.height;
        Mask outline(size_t(w) * h), silhouette(size_t(w) * h);
        PngImage overlay = styled;
        for (size_t i = 0; i < outline.size(); ++i) {
            int difference = 0;
            for (int ch = 0; ch < 3; ++ch) {
                difference = std::max(difference,
                                      std::abs(styled.rgba[i * 4 + ch] - native.rgba[i * 4 + ch]));
            }
            outline[i] = difference > kTolerance;
            silhouette[i] = truth.rgba[i * 4] >= 128;
            if (silhouette[i]) {
                overlay.rgba[i * 4] = 255;
                overlay.rgba[i * 4 + 1] = overlay.rgba[i * 4 + 2] = 0;
            }
        }
        std::string error;
        const std::string overlayPath = dir + "/overlay_" + std::to_string(frame) + ".png";
        overlay.write(overlayPath, error);

        const Score s = score(outline, silhouette, w, h);
        std::printf("%-14s frame %2d: precision %.3f recall %.3f (%zu outline, %zu truth px)\n",
                    c.name.c_str(), frame, s.precision, s.recall, s.outlinePixels,
                    s.truthPixels);
        RecordProperty("precision_" + std::to_string(frame), std::to_string(s.precision));
        RecordProperty("recall_" + std::to_string(frame), std::to_string(s.recall));
        EXPECT_GT(s.truthPixels, 1500u) << "frame " << frame;
        EXPECT_GE(s.precision, c.minPrecision) << "frame " << frame << ", see " << overlayPath;
        EXPECT_GE(s.recall, c.minRecall) << "frame " << frame << ", see " << overlayPath;
    }
}

INSTANTIATE_TEST_SUITE_P(Styles, OutlineAccuracy, ::testing::ValuesIn(kCases),
                         [](const auto& p) { return p.param.name; });
