// The program's textures as drawings: TextureAbstraction on the CPU, and the toon style
// drawing a textured sphere with them (AbstractTextures) in-process through the style harness.
#include "styles/textures/AbstractTextures.h"
#include "styles/textures/TextureAbstraction.h"
#include "tests/support/Process.h"
#include "tests/support/StyleHarness.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdlib>
#include <regex>
#include <set>
#include <tuple>

using namespace nprgl;
using namespace nprgl::styles;
using namespace nprgl::test;

namespace {

// A 64 x 64 texture: a warm left half and a cool right half, each with a noisy grain of
// +-24 levels (a fixed pattern), and an alpha ramp along the rows.
TextureImage grainyHalves()
{
    TextureImage image;
    image.width = 64;
    image.height = 64;
    image.channels = 4;
    image.pixels.resize(64 * 64 * 4);
    uint32_t seed = 12345;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            seed = seed * 1664525u + 1013904223u;
            const int grain = int(seed >> 24) % 49 - 24;
            const bool left = x < 32;
            uint8_t* p = &image.pixels[size_t(y * 64 + x) * 4];
            p[0] = uint8_t(std::clamp((left ? 200 : 40) + grain, 0, 255));
            p[1] = uint8_t(std::clamp((left ? 120 : 90) + grain, 0, 255));
            p[2] = uint8_t(std::clamp((left ? 60 : 190) + grain, 0, 255));
            p[3] = uint8_t(128 + y * 2);
        }
    }
    return image;
}

using Texel = std::tuple<int, int, int>;

Texel texel(const TextureImage& image, int x, int y)
{
    const uint8_t* p = &image.pixels[size_t(y * image.width + x) * 4];
    return {p[0], p[1], p[2]};
}

// The colours of columns [x0, x1) away from the rows' wrap-around seam.
std::set<Texel> coloursIn(const TextureImage& image, int x0, int x1)
{
    std::set<Texel> out;
    for (int y = 0; y < image.height; ++y) {
        for (int x = x0; x < x1; ++x)
            out.insert(texel(image, x, y));
    }
    return out;
}

} // namespace

TEST(TextureAbstraction, RegionsBecomeFlatAndTheirBorderStays)
{
    const TextureImage in = grainyHalves();
    ASSERT_GT(coloursIn(in, 4, 28).size(), 40u); // the grain: no test without it
    const TextureImage out = TextureAbstraction::abstracted(in, 0.0f);
    ASSERT_EQ(out.width, 64);
    ASSERT_EQ(out.pixels.size(), in.pixels.size());
    // Each half is one or two palette colours, never the other half's.
    const std::set<Texel> left = coloursIn(out, 4, 28), right = coloursIn(out, 36, 60);
    EXPECT_LE(left.size(), 2u);
    EXPECT_LE(right.size(), 2u);
    for (const Texel& c : left)
        EXPECT_EQ(right.count(c), 0u);
    // Up to the border column on either side: the smoothing does not cross the edge.
    for (int y = 0; y < 64; ++y) {
        EXPECT_GT(std::get<0>(texel(out, 31, y)), 150) << "row " << y;
        EXPECT_LT(std::get<0>(texel(out, 32, y)), 90) << "row " << y;
    }
    // The whole texture has no more colours than the palette.
    EXPECT_LE(coloursIn(out, 0, 64).size(), size_t(TextureAbstraction::kPaletteSize));
}

TEST(TextureAbstraction, AlphaIsTheProgramsAndDetailOneIsItsTexture)
{
    const TextureImage in = grainyHalves();
    const TextureImage flat = TextureAbstraction::abstracted(in, 0.0f);
    for (size_t i = 3; i < in.pixels.size(); i += 4)
        ASSERT_EQ(flat.pixels[i], in.pixels[i]);
    EXPECT_EQ(TextureAbstraction::abstracted(in, 1.0f).pixels, in.pixels);
    // Halfway: between the flat colour and the program's texel.
    const TextureImage half = TextureAbstraction::abstracted(in, 0.5f);
    for (size_t i = 0; i < in.pixels.size(); i += 4) {
        const int expected = (int(flat.pixels[i]) + int(in.pixels[i])) / 2;
        ASSERT_LE(std::abs(int(half.pixels[i]) - expected), 1) << "texel " << i / 4;
    }
}

TEST(TextureAbstraction, TheSameImageGivesTheSameBytes)
{
    const TextureImage in = grainyHalves();
    EXPECT_EQ(TextureAbstraction::abstracted(in, 0.3f).pixels,
              TextureAbstraction::abstracted(in, 0.3f).pixels);
}

TEST(TextureAbstraction, ClearTexelsTakeNoPaletteColour)
{
    // Three quarters clear magenta (never seen), a quarter opaque grey: the palette has no
    // magenta in it, so the visible grey keeps its colour.
    TextureImage in;
    in.width = in.height = 32;
    in.channels = 4;
    in.pixels.resize(32 * 32 * 4);
    for (int i = 0; i < 32 * 32; ++i) {
        const bool seen = i % 4 == 0;
        uint8_t* p = &in.pixels[size_t(i) * 4];
        p[0] = seen ? 128 : 255;
        p[1] = seen ? 128 : 0;
        p[2] = seen ? 128 : 255;
        p[3] = seen ? 255 : 0;
    }
    std::vector<glm::vec4> texels;
    for (int i = 0; i < 32 * 32; ++i) {
        const uint8_t* p = &in.pixels[size_t(i) * 4];
        texels.push_back(glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f);
    }
    for (const glm::vec3& c : TextureAbstraction::palette(texels)) {
        EXPECT_NEAR(c.g, 0.5f, 0.02f) << "a palette colour from clear texels";
    }
    const TextureImage out = TextureAbstraction::abstracted(in, 0.0f);
    for (int i = 0; i < 32 * 32; i += 4) {
        EXPECT_NEAR(out.pixels[size_t(i) * 4 + 1], 128, 8) << "texel " << i;
    }
}

// A soft glow drawn with additive blending (a luminance blip, as a radar's or a particle's):
// its black surround adds nothing, so it must stay black, and its core stays the lightest. A
// palette mean of the dark end would lighten the whole surround into a visible disc.
TEST(TextureAbstraction, AGlowsBlackSurroundAndWhiteCoreStay)
{
    TextureImage in;
    in.width = in.height = 64;
    in.channels = 4;
    in.pixels.resize(64 * 64 * 4);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const float r = std::hypot(float(x) - 31.5f, float(y) - 31.5f) / 20.0f;
            const float fall = std::max(0.0f, 1.0f - r);
            const uint8_t v = uint8_t(std::lround(255.0f * fall * fall * fall));
            uint8_t* p = &in.pixels[size_t(y * 64 + x) * 4];
            p[0] = p[1] = p[2] = v;
            p[3] = 255;
        }
    }
    ASSERT_EQ(texel(in, 0, 0), Texel(0, 0, 0));
    const TextureImage out = TextureAbstraction::abstracted(in, 0.0f);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            if (std::hypot(float(x) - 31.5f, float(y) - 31.5f) < 22.0f) continue;
            ASSERT_EQ(texel(out, x, y), Texel(0, 0, 0)) << "the surround at " << x << "," << y;
        }
    }
    // The core keeps the lightest colour the smoothing left of its peak.
    int lightest = 0;
    for (size_t i = 0; i < out.pixels.size(); i += 4)
        lightest = std::max<int>(lightest, out.pixels[i]);
    EXPECT_EQ(std::get<0>(texel(out, 31, 31)), lightest);
    EXPECT_GE(lightest, 180) << "the core";
}

TEST(TextureAbstraction, NoImageNoAbstraction)
{
    TextureImage grey = TextureImage::grey(8, 8, 100); // one channel: not an RGBA texture
    EXPECT_TRUE(TextureAbstraction::abstracted(grey, 0.0f).empty());
    EXPECT_TRUE(TextureAbstraction::abstracted(TextureImage{}, 0.0f).empty());
}

namespace {

constexpr int kSize = 96;

class Drawings : public ::testing::Test {
protected:
    void SetUp() override { AbstractTextures::setWait(true); }

    // A sphere mapped with `texture` (longitude, latitude), facing a head-light.
    PngImage render(const std::string& config, GLuint texture)
    {
        const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6));
        reconstruct::Batch sphere = sphereBatch(mv, 1.8f, 48, 24, glm::vec4(1.0f));
        for (reconstruct::Vertex& v : sphere.vertices) {
            v.texcoord = {std::atan2(v.normal.z, v.normal.x) / 6.2831853f + 0.5f,
                          std::acos(std::clamp(v.normal.y, -1.0f, 1.0f)) / 3.14159265f};
        }
        const glm::mat4 projection = glm::perspective(glm::radians(40.0f), 1.0f, 1.0f, 20.0f);
        auto scene = harness.makeScene({sphere}, projection, glm::vec3(0, 0, 1));
        for (auto& o : scene.objects)
            o.texture = texture;
        scene.frame = frame;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest," + config, image, error))
            << error;
        return image;
    }
    // A texture of `channels` bytes per texel in `format`, repeated, sampled nearest.
    GLuint texture(GLint internalFormat, GLenum format, int channels, const TextureImage& rgba)
    {
        std::vector<uint8_t> bytes;
        for (size_t i = 0; i < rgba.pixels.size(); i += 4) {
            if (channels == 4) {
                bytes.insert(bytes.end(), &rgba.pixels[i], &rgba.pixels[i] + 4);
            } else {
                bytes.push_back(rgba.pixels[i]);                        // luminance: red
                if (channels == 2) bytes.push_back(rgba.pixels[i + 3]); // and alpha
            }
        }
        return harness.nearestTexture(internalFormat, rgba.width, rgba.height, format,
                                      bytes.data());
    }
    // The share of neighbouring pixels in the sphere's middle that differ: the grain makes
    // most of them differ, flat regions only those along region and band borders.
    static double grain(const PngImage& image)
    {
        int pairs = 0, differ = 0;
        for (int y = kSize / 3; y < 2 * kSize / 3; ++y) {
            for (int x = kSize / 3; x < 2 * kSize / 3; ++x) {
                const uint8_t* p = &image.rgba[size_t(y * kSize + x) * 4];
                ++pairs;
                differ += p[0] != p[4] || p[1] != p[5] || p[2] != p[6];
            }
        }
        return double(differ) / pairs;
    }

    StyleHarness harness{kSize, kSize};
    uint64_t frame = 0; // the scenes'
};

} // namespace

TEST_F(Drawings, ToonDrawsTheTextureAbstracted)
{
    ASSERT_TRUE(harness.ok());
    const GLuint grainy = texture(GL_RGBA8, GL_RGBA, 4, grainyHalves());
    harness.setTextureContent([&](GLuint t) { return t == grainy ? 0x1234u : 0u; });
    const double program = grain(render("toon.texture_detail=1", grainy));
    const double drawn = grain(render("toon.texture_detail=0", grainy));
    EXPECT_GT(program, 0.15) << "the program's grain is not drawn: no test";
    EXPECT_LT(drawn, 0.05) << "the grain is still there";
    // Without a content hash (rendered into, copied) the program's texture is drawn.
    harness.setTextureContent({});
    EXPECT_GT(grain(render("toon.texture_detail=0", grainy)), 0.15);
    glDeleteTextures(1, &grainy);
}

// glGetTexImage gives a luminance texture's L in red alone: read so, a grey texture's
// abstraction came out red (neverball's ball).
TEST_F(Drawings, ALuminanceTextureStaysGrey)
{
    ASSERT_TRUE(harness.ok());
    for (int channels : {1, 2}) {
        const GLuint grey =
            channels == 1 ? texture(GL_LUMINANCE8, GL_LUMINANCE, 1, grainyHalves())
                          : texture(GL_LUMINANCE8_ALPHA8, GL_LUMINANCE_ALPHA, 2, grainyHalves());
        harness.setTextureContent([&](GLuint t) { return t == grey ? 0x77u : 0u; });
        const PngImage image = render("toon.texture_detail=0", grey);
        int coloured = 0, lit = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) {
            const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
            lit += r + g + b > 60;
            coloured += std::max({r, g, b}) - std::min({r, g, b}) > 12;
        }
        EXPECT_GT(lit, 1000) << channels << " channels";
        EXPECT_EQ(coloured, 0) << channels << " channels: the grey texture drew coloured";
        glDeleteTextures(1, &grey);
    }
}

// A texture whose content keeps changing (a video) is drawn as the program's: an abstraction
// per frame would read it back every frame and flicker.
TEST_F(Drawings, ATextureThatKeepsChangingIsTheProgramsOwn)
{
    ASSERT_TRUE(harness.ok());
    harness.keepChain(true);
    const GLuint grainy = texture(GL_RGBA8, GL_RGBA, 4, grainyHalves());
    uint64_t content = 1;
    harness.setTextureContent([&](GLuint t) { return t == grainy ? content : 0u; });
    std::vector<double> grains;
    for (int n = 0; n < 4; ++n, ++content) {
        grains.push_back(grain(render("toon.texture_detail=0", grainy)));
    }
    EXPECT_LT(grains[0], 0.05); // abstracted while it is new...
    EXPECT_LT(grains[1], 0.05); // ... and after one change
    EXPECT_GT(grains[2], 0.15) << "the second change makes it the program's";
    EXPECT_GT(grains[3], 0.15);
    // Once its content holds still, it is a drawing again (a name reused for a new level's
    // texture is not left for good).
    --content;
    frame = AbstractTextures::kChangingFrames + 1;
    EXPECT_LT(grain(render("toon.texture_detail=0", grainy)), 0.05);
    glDeleteTextures(1, &grainy);
}

// A program that reuses a name for a new texture now and then (a new level) gets each one
// abstracted.
TEST_F(Drawings, ANameReusedNowAndThenIsADrawingEachTime)
{
    ASSERT_TRUE(harness.ok());
    harness.keepChain(true);
    const GLuint grainy = texture(GL_RGBA8, GL_RGBA, 4, grainyHalves());
    uint64_t content = 1;
    harness.setTextureContent([&](GLuint t) { return t == grainy ? content : 0u; });
    for (int level = 0; level < 4; ++level, ++content) {
        frame = uint64_t(level) * (AbstractTextures::kChangingFrames + 1);
        EXPECT_LT(grain(render("toon.texture_detail=0", grainy)), 0.05) << "level " << level;
    }
    glDeleteTextures(1, &grainy);
}

// Nothing silent: the run's report says how many of the program's textures were drawn as
// drawings and how many were left as the program's, by reason; and none at texture_detail 1.
TEST(DrawingsReport, CountsTheTexturesDrawnAsDrawings)
{
    const std::string dir = freshDir("drawings_report");
    const ProcessResult abstracted =
        runProcess({nprglCommand(), "replay", fixture("textured"), "-o", dir + "/default"},
                   {{"NPRGL_STYLE", ""}, {"NPRGL_CONFIG", ""}, {"NPRGL_PRESET", ""}});
    ASSERT_EQ(abstracted.exitCode, 0) << abstracted.err;
    EXPECT_TRUE(std::regex_search(
        abstracted.err,
        std::regex("context [0-9]+: textures as drawings: [1-9][0-9]* abstracted; left as the "
                   "program's: 0 of unknown content, 0 changing, 0 too large\n")))
        << abstracted.err;
    const ProcessResult kept =
        runProcess({nprglCommand(), "replay", fixture("textured"), "-o", dir + "/detail1", "--set",
                    "toon.texture_detail=1"},
                   {{"NPRGL_STYLE", ""}, {"NPRGL_CONFIG", ""}, {"NPRGL_PRESET", ""}});
    ASSERT_EQ(kept.exitCode, 0) << kept.err;
    EXPECT_EQ(kept.err.find("textures as drawings"), std::string::npos) << kept.err;
}

// replay --stats tells the same per frame, as the run's counts stand at its end: the fixture
// uploads its textures in frame 1, so every frame shows them all.
TEST(DrawingsReport, ReplayStatsCountThemPerFrame)
{
    const ProcessResult stats =
        runProcess({nprglCommand(), "replay", fixture("textured"), "--stats"},
                   {{"NPRGL_STYLE", ""}, {"NPRGL_CONFIG", ""}, {"NPRGL_PRESET", ""}});
    ASSERT_EQ(stats.exitCode, 0) << stats.err;
    for (const char* frame : {"1", "2", "3"}) {
        EXPECT_TRUE(std::regex_search(
            stats.out, std::regex(std::string("frame ") + frame +
                                  ": textures as drawings: [1-9][0-9]* abstracted; left as the "
                                  "program's: 0 of unknown content, 0 changing, 0 too large\n")))
            << stats.out;
    }
    const ProcessResult kept =
        runProcess({nprglCommand(), "replay", fixture("textured"), "--stats", "--set",
                    "toon.texture_detail=1"},
                   {{"NPRGL_STYLE", ""}, {"NPRGL_CONFIG", ""}, {"NPRGL_PRESET", ""}});
    ASSERT_EQ(kept.exitCode, 0) << kept.err;
    EXPECT_EQ(kept.out.find("textures as drawings"), std::string::npos) << kept.out;
}
