// The shading styles (thesis chapter 3) rendered in-process through the style harness.
// Pictures go to /tmp/shading/ for looking at them.

#include "styles/textures/HalftoneScreens.h"
#include "styles/textures/HatchTexture.h"
#include "styles/textures/StippleTexture.h"
#include "tests/support/Process.h"
#include "tests/support/StyleHarness.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>

using namespace nprgl;
using namespace nprgl::test;

namespace {

constexpr int kSize = 128;
constexpr float kFov = 40.0f;
const glm::vec3 kCentre(0.0f, 0.0f, -6.0f);
constexpr float kRadius = 1.5f;
// From the upper right and a little in front: the terminator crosses the visible sphere.
const glm::vec3 kLight = glm::normalize(glm::vec3(1.0f, 0.6f, 0.6f));

glm::mat4 perspective() { return glm::perspective(glm::radians(kFov), 1.0f, 1.0f, 20.0f); }

void save(const PngImage& image, const std::string& name)
{
    std::filesystem::create_directories("/tmp/shading");
    std::string error;
    image.write("/tmp/shading/" + name + ".png", error);
}

// The analytic sphere behind pixel (x, y) (top row first): its L·n, or nothing when the
// pixel misses the sphere or lies within `rim` pixels of its outline.
std::optional<float> sphereLight(int x, int y, float rim = 2.0f)
{
    const float t = std::tan(glm::radians(kFov) / 2.0f);
    const glm::vec3 dir = glm::normalize(glm::vec3((2.0f * (x + 0.5f) / kSize - 1.0f) * t,
                                                   (1.0f - 2.0f * (y + 0.5f) / kSize) * t, -1.0f));
    const float b = glm::dot(dir, kCentre);
    const float miss = std::sqrt(std::max(0.0f, glm::dot(kCentre, kCentre) - b * b));
    // Keep `rim` pixels (world units at the sphere's distance) away from the outline.
    const float pixelSize = 2.0f * t * -kCentre.z / kSize;
    if (miss > kRadius - rim * pixelSize) return std::nullopt;
    const float disc = kRadius * kRadius - miss * miss;
    const glm::vec3 p = dir * (b - std::sqrt(disc));
    return glm::dot(glm::normalize(p - kCentre), kLight);
}

struct Rgb {
    int r, g, b;
    bool operator<(const Rgb& o) const { return std::tie(r, g, b) < std::tie(o.r, o.g, o.b); }
};

Rgb pixel(const PngImage& image, int x, int y)
{
    const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
    return {p[0], p[1], p[2]};
}

float luminance(const Rgb& c) { return (0.299f * c.r + 0.587f * c.g + 0.114f * c.b) / 255.0f; }

bool near(const Rgb& a, const Rgb& b, int tolerance = 2)
{
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
           std::abs(a.b - b.b) <= tolerance;
}

// Distinct colours of a set, counting those within one 8-bit step (interpolated vertex
// colours round either way) as one.
size_t distinct(const std::set<Rgb>& colours)
{
    std::vector<Rgb> kept;
    for (const Rgb& c : colours) {
        bool seen = false;
        for (const Rgb& k : kept) seen = seen || near(c, k, 1);
        if (!seen) kept.push_back(c);
    }
    return kept.size();
}

// Calls f(colour, L·n) for every pixel well inside the sphere.
void forSphere(const PngImage& image, const std::function<void(const Rgb&, float)>& f,
               float rim = 2.0f)
{
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (auto ln = sphereLight(x, y, rim)) f(pixel(image, x, y), *ln);
        }
    }
}

class Shading : public ::testing::Test {
protected:
    PngImage render(const std::string& chain, const std::string& config, const std::string& name,
                    glm::vec4 color = glm::vec4(0.8f, 0.1f, 0.1f, 1.0f), GLuint texture = 0)
    {
        auto mv = glm::translate(glm::mat4(1.0f), kCentre);
        reconstruct::Batch sphere = sphereBatch(mv, kRadius, 48, 24, color);
        for (reconstruct::Vertex& v : sphere.vertices) {
            // Longitude / latitude texcoords for the detail-texture tests.
            v.texcoord = {std::atan2(v.normal.z, v.normal.x) / 6.2831853f + 0.5f,
                          std::acos(std::clamp(v.normal.y, -1.0f, 1.0f)) / 3.14159265f};
        }
        auto scene = harness.makeScene({sphere}, perspective(), kLight);
        for (auto& o : scene.objects) o.texture = texture;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, chain, config, image, error)) << error;
        save(image, name);
        return image;
    }

    // A 64 x 64 RGBA checkerboard of 8-texel squares, as a program would bind it.
    GLuint checkerTexture()
    {
        const styles::GlFunctions& gl = harness.gl();
        std::vector<uint8_t> texels(64 * 64 * 4);
        for (int y = 0; y < 64; ++y) {
            for (int x = 0; x < 64; ++x) {
                const bool dark = ((x / 8) + (y / 8)) % 2;
                uint8_t* t = &texels[size_t(y * 64 + x) * 4];
                t[0] = dark ? 40 : 255;
                t[1] = dark ? 60 : 255;
                t[2] = dark ? 200 : 255;
                t[3] = 255;
            }
        }
        GLuint id = 0;
        glGenTextures(1, &id);
        gl.BindTexture(GL_TEXTURE_2D, id);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                      texels.data());
        gl.BindTexture(GL_TEXTURE_2D, 0);
        return id;
    }

    // A GL_ALPHA texture, opaque everywhere (text and sprites are uploaded so): no colour.
    GLuint alphaTexture()
    {
        const std::vector<uint8_t> texels(16 * 16, 255);
        return nearestTexture(GL_ALPHA, 16, 16, GL_ALPHA, texels.data());
    }

    GLuint nearestTexture(GLint internalFormat, int width, int height, GLenum format,
                          const uint8_t* texels)
    {
        return harness.nearestTexture(internalFormat, width, height, format, texels);
    }

    StyleHarness harness{kSize, kSize};
};

// The toon band colours of the red test sphere with default scales.
const Rgb kDiffuse{204, 26, 26};

// The red sphere of the toon tests (radius 1.5, 6 in front of the eye), in `colour`.
styles::Scene sphereScene(StyleHarness& harness, const glm::vec4& colour,
                          glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.5f, 1.0f)))
{
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6));
    return harness.makeScene({sphereBatch(mv, 1.5f, 48, 24, colour)}, perspective(), light);
}

} // namespace

TEST(Toon, SphereShowsOnlyItsBandColours)
{
    StyleHarness harness(128, 128);
    ASSERT_TRUE(harness.ok());
    auto scene = sphereScene(harness, glm::vec4(0.8f, 0.1f, 0.1f, 1.0f));
    PngImage image;
    std::string error;
    ASSERT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
    image.write(std::string("/tmp/toon_sphere.png"), error);
    // Inside the sphere (well away from its rim) only the three band colours occur.
    std::set<uint32_t> colours;
    for (int y = 40; y < 88; ++y) {
        for (int x = 40; x < 88; ++x) {
            const uint8_t* p = &image.rgba[(size_t(y) * 128 + x) * 4];
            colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
        }
    }
    EXPECT_GE(colours.size(), 2u);
    EXPECT_LE(colours.size(), 3u);
}

// The lit band shows the material's own colour, as GL shows it lit head-on, also under two
// lights: pymol's head-light (diffuse 0.45) and its second light from the upper right (0.48)
// sum to nearly twice one light over most of a stick, and the sum, weighted against the
// brightest light alone, put most of the surface in the highlight band: its carbon green
// (0.2, 1, 0.2) came out pale (163, 255, 163). The light term is now 1 where the lights
// together light the surface most, so the highlight is a cap, as with one light.
TEST(Toon, TwoLightsOfOneStrengthKeepTheLitBandTheMaterialsColour)
{
    StyleHarness harness(128, 128);
    ASSERT_TRUE(harness.ok());
    const glm::vec4 green(0.2f, 1.0f, 0.2f, 1.0f);
    auto bands = [&](bool second, const char* name) {
        auto scene = sphereScene(harness, green);
        styles::SceneLights& lights = scene.objects[0].lights;
        lights.count = second ? 2 : 1;
        lights.lights[0].position = glm::vec4(0.348f, 0.348f, 0.870f, 0.0f);
        lights.lights[0].weight = 1.0f;
        lights.lights[1].position = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f);
        lights.lights[1].weight = 0.45f / 0.48f; // against the brightest, as StateTracker::litBy
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
        image.write(std::string("/tmp/toon_two_lights_") + name + ".png", error);
        // Over the sphere: pixels in the lit band (the material's colour) and in the highlight.
        std::pair<int, int> n{0, 0};
        for (int y = 0; y < 128; ++y) {
            for (int x = 0; x < 128; ++x) {
                const Rgb p = pixel(image, x, y);
                n.first += p.r == 51 && p.g == 255 && p.b == 51;
                n.second += p.r == 163 && p.g == 255 && p.b == 163;
            }
        }
        return n;
    };
    const auto one = bands(false, "one");
    const auto two = bands(true, "two");
    ASSERT_GT(one.first, 1000) << "no lit band with one light: no test";
    EXPECT_GT(two.first, 3 * two.second) << "the highlight covers the lit band";
    EXPECT_LT(two.second, 2 * one.second) << "the second light widened the highlight";
}

// A projection that mirrors y (glOrtho(0, w, h, 0, ...) and its perspective kin: the top-down
// view of 2D-minded programs, xscreensaver's voronoi) turns the faces' window winding around,
// as a mirroring modelview does. The lit side stays lit: the picture is the unmirrored one
// upside down. (The normals were turned away from the eye: voronoi's cells all in the
// shadow band, at half their colour.)
TEST(Toon, AProjectionThatMirrorsKeepsTheLitSide)
{
    StyleHarness harness(128, 128);
    ASSERT_TRUE(harness.ok());
    auto render = [&](bool mirror) {
        auto scene = sphereScene(harness, glm::vec4(0.8f, 0.1f, 0.1f, 1.0f),
                                 glm::normalize(glm::vec3(0.0f, 1.0f, 0.3f)));
        for (auto& o : scene.objects) {
            if (mirror) o.projection = glm::scale(glm::mat4(1.0f), {1, -1, 1}) * o.projection;
        }
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
        return image;
    };
    const PngImage upright = render(false);
    PngImage mirrored = render(true);
    ASSERT_EQ(upright.rgba.size(), mirrored.rgba.size());
    mirrored.flipRows();
    int diffuse = 0, differing = 0;
    for (size_t i = 0; i < upright.rgba.size(); i += 4) {
        diffuse += near(Rgb{upright.rgba[i], upright.rgba[i + 1], upright.rgba[i + 2]}, kDiffuse);
        for (int c = 0; c < 3; ++c) {
            if (std::abs(upright.rgba[i + c] - mirrored.rgba[i + c]) > 24) {
                ++differing;
                break;
            }
        }
    }
    EXPECT_GT(diffuse, 500) << "no lit band: no test";
    EXPECT_LT(differing, 40) << "the mirrored view is lit from the other side";
}

// A sky or backdrop the program drew without the depth test and did not light is shaded in
// one even light (the diffuse band: its own colour), not by the head-light, which would put
// half of a sky box's faces into the shadow band. Lit or depth-tested, the same sphere shows
// its shadow band.
TEST(Toon, AnUnlitBackdropIsShadedInAnEvenLight)
{
    StyleHarness harness(128, 128);
    ASSERT_TRUE(harness.ok());
    auto shadowPixels = [&](bool backdrop) {
        // The head-light from the right: the left half of the sphere is in shadow.
        auto scene = sphereScene(harness, glm::vec4(0.8f, 0.1f, 0.1f, 1.0f),
                                 glm::normalize(glm::vec3(1.0f, 0.0f, 0.2f)));
        for (auto& o : scene.objects) o.depthTest = !backdrop;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
        int shadow = 0, diffuse = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) {
            const Rgb c{image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
            shadow += near(c, Rgb{112, 14, 14});
            diffuse += near(c, kDiffuse);
        }
        EXPECT_GT(diffuse, 500);
        return shadow;
    };
    EXPECT_GT(shadowPixels(false), 500) << "no shadow band on the depth-tested sphere: no test";
    EXPECT_EQ(shadowPixels(true), 0) << "the backdrop is shaded by the head-light";
}

// A GL_ALPHA texture gives the fixed-function pipeline only alpha (the fragment keeps its
// colour); a shader samples it black. Text and sprites drawn with one (crack-attack's) were
// black shapes, invisible on a dark screen: the styles read its colour as white.
TEST_F(Shading, AnAlphaTextureKeepsTheObjectsColour)
{
    ASSERT_TRUE(harness.ok());
    const PngImage image = render("toon", "toon.band=nearest", "toon_alpha_texture",
                                  glm::vec4(0.8f, 0.1f, 0.1f, 1.0f), alphaTexture());
    int diffuse = 0, black = 0;
    forSphere(image, [&](const Rgb& c, float) {
        diffuse += near(c, kDiffuse);
        black += c.r < 40 && c.g < 40 && c.b < 40;
    });
    EXPECT_GT(diffuse, 1000);
    EXPECT_EQ(black, 0) << "the alpha texture's colour was taken as black";
}

// A translucent object drawn without the depth test (text, a sprite, a HUD part in
// perspective) is blended as the program blends it, not drawn opaque over what is behind.
TEST(Toon, ATranslucentObjectWithoutTheDepthTestIsBlended)
{
    StyleHarness harness(128, 128);
    ASSERT_TRUE(harness.ok());
    auto scene = sphereScene(harness, glm::vec4(0.8f, 0.1f, 0.1f, 0.5f)); // half transparent
    for (auto& o : scene.objects) {
        o.depthTest = false;
        o.translucent = true;
        o.depthWrite = false;
    }
    PngImage image;
    std::string error;
    ASSERT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
    // The centre: the unlit sphere's even diffuse colour over the white background, its back
    // and front halves each at alpha 0.5 (no depth test, no culling: 1 - 0.5^2 of it).
    const uint8_t* p = &image.rgba[(size_t(64) * 128 + 64) * 4];
    EXPECT_NEAR(int(p[0]), (204 * 3 + 255) / 4, 6);
    EXPECT_NEAR(int(p[1]), (26 * 3 + 255) / 4, 6) << "drawn opaque";
}

// Faces the program culls stay culled: seen from inside, a box the program draws with back
// faces culled shows nothing (lavalite's lamp hid its own lava blob behind the inner faces of
// its glass); without culling its inside fills the view.
TEST(Toon, TheProgramsCulledFacesAreNotDrawn)
{
    StyleHarness harness(64, 64);
    ASSERT_TRUE(harness.ok());
    auto drawnPixels = [&](GLenum culled) {
        auto scene = harness.makeScene(
            {boxBatch(glm::mat4(1.0f), glm::vec3(3.0f), glm::vec4(0.8f, 0.1f, 0.1f, 1.0f))},
            perspective());
        for (auto& o : scene.objects) o.culled = culled;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "", image, error)) << error;
        int drawn = 0;
        for (size_t i = 0; i < image.rgba.size(); i += 4) drawn += image.rgba[i + 1] < 200;
        return drawn;
    };
    EXPECT_EQ(drawnPixels(0), 64 * 64) << "the box's inside does not fill the view: no test";
    EXPECT_EQ(drawnPixels(GL_CW), 0) << "back faces the program culls were drawn";
}

// The program's front face at the flush is its own business: the styles draw with theirs.
// Two spheres, the left culled as the program culled it: with the program's glFrontFace(GL_CW)
// still set at the flush, every shading style drew both turned inside out (lit on the side
// away from the light), since it read the front face once and the culled sphere's set-up
// changed it under the other.
class FrontFaceAtFlush : public ::testing::TestWithParam<const char*> {};

TEST_P(FrontFaceAtFlush, DoesNotTurnTheShading)
{
    StyleHarness harness(128, 64);
    ASSERT_TRUE(harness.ok());
    const glm::vec4 red(0.8f, 0.1f, 0.1f, 1.0f);
    auto picture = [&](GLenum programFront) {
        const glm::mat4 left = glm::translate(glm::mat4(1.0f), glm::vec3(-1.6f, 0, -6));
        const glm::mat4 right = glm::translate(glm::mat4(1.0f), glm::vec3(1.6f, 0, -6));
        auto scene = harness.makeScene(
            {sphereBatch(left, 1.4f, 32, 16, red), sphereBatch(right, 1.4f, 32, 16, red)},
            glm::perspective(glm::radians(kFov), 2.0f, 1.0f, 20.0f),
            glm::normalize(glm::vec3(1.0f, 0.0f, 0.3f)));
        EXPECT_EQ(scene.objects.size(), 2u);
        scene.objects.front().culled = GL_CW; // the back faces of a sphere wound CCW outside
        harness.gl().FrontFace(programFront);
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, GetParam(), "", image, error)) << error;
        harness.gl().FrontFace(GL_CCW);
        return image;
    };
    const PngImage own = picture(GL_CCW), clockwise = picture(GL_CW);
    ASSERT_EQ(own.rgba.size(), clockwise.rgba.size());
    size_t differ = 0, drawn = 0;
    for (size_t i = 0; i < own.rgba.size(); i += 4) {
        differ += std::memcmp(&own.rgba[i], &clockwise.rgba[i], 3) != 0;
        drawn += own.rgba[i + 1] < 200;
    }
    EXPECT_GT(drawn, 1000u) << "no spheres drawn: no test";
    EXPECT_EQ(differ, 0u) << "the program's front face changed the picture";
}

INSTANTIATE_TEST_SUITE_P(Styles, FrontFaceAtFlush,
                         ::testing::Values("toon", "textured", "halftone", "gooch", "xtoon",
                                           "pencil", "coverage"),
                         [](const auto& p) { return std::string(p.param); });

// Every shading style takes the reflections parameter: a sphere-mapped texture on a sphere
// the program lit is dropped without it (the picture is the untextured sphere's, pixel for
// pixel) and shown with it (the checkerboard's reflection changes the sphere).
class Reflections : public Shading, public ::testing::WithParamInterface<const char*> {
protected:
    PngImage reflecting(GLuint texture, bool shown)
    {
        auto mv = glm::translate(glm::mat4(1.0f), kCentre);
        auto scene = harness.makeScene({sphereBatch(mv, kRadius, 48, 24, glm::vec4(0.9f))},
                                       perspective(), kLight);
        for (auto& o : scene.objects) {
            o.generated.texture = texture;
            o.generated.mode[0] = o.generated.mode[1] = GL_SPHERE_MAP;
            // Lit by the program (one far light where makeScene's head-light is): the
            // reflection is not its light (ReflectionLight).
            o.lights.count = 1;
            o.lights.lights[0].position = glm::vec4(kLight, 0.0f);
        }
        const std::string style = GetParam();
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, style, style + ".reflections=" + (shown ? "1" : "0"),
                                   image, error))
            << error;
        return image;
    }
};

TEST_P(Reflections, ShowASphereMapOnlyWhenAsked)
{
    ASSERT_TRUE(harness.ok());
    const GLuint checker = checkerTexture();
    const PngImage plain = reflecting(0, true), dropped = reflecting(checker, false);
    const PngImage shown = reflecting(checker, true);
    size_t droppedDiffer = 0, shownDiffer = 0;
    for (size_t i = 0; i < plain.rgba.size(); i += 4) {
        droppedDiffer += std::memcmp(&plain.rgba[i], &dropped.rgba[i], 3) != 0;
        shownDiffer += std::memcmp(&plain.rgba[i], &shown.rgba[i], 3) != 0;
    }
    EXPECT_EQ(droppedDiffer, 0u) << "the reflection was drawn without the parameter";
    EXPECT_GT(shownDiffer, 500u) << "the parameter did not show the reflection";
}

INSTANTIATE_TEST_SUITE_P(Styles, Reflections,
                         ::testing::Values("toon", "textured", "halftone", "gooch", "xtoon"),
                         [](const auto& p) { return std::string(p.param); });

TEST_F(Shading, TwoTonesGiveTwoColoursMatchingTheLight)
{
    ASSERT_TRUE(harness.ok());
    const PngImage image = render("toon", "toon.tones=2,toon.band=nearest", "toon_2tones");
    std::set<Rgb> colours;
    int wrong = 0, total = 0;
    const Rgb shadow{112, 14, 14}; // 0.8 x 0.55, 0.1 x 0.55 in 8 bits
    forSphere(image, [&](const Rgb& c, float ln) {
        colours.insert(c);
        // Away from the boundary (tessellation moves it a little) the colour follows L·n.
        if (std::abs(ln) < 0.06f) return;
        ++total;
        if (!near(c, ln < 0.0f ? shadow : kDiffuse)) ++wrong;
    });
    EXPECT_EQ(distinct(colours), 2u);
    EXPECT_GT(total, 3000);
    EXPECT_LT(wrong, total / 200);
}

TEST_F(Shading, ThreeTonesNearestShowAtMostThreeColours)
{
    ASSERT_TRUE(harness.ok());
    const PngImage image =
        render("toon", "toon.band=nearest,toon.highlight_threshold=0.8", "toon_3tones");
    std::set<Rgb> colours;
    int highlight = 0;
    forSphere(image, [&](const Rgb& c, float ln) {
        colours.insert(c);
        if (ln > 0.85f) highlight += luminance(c) > luminance(kDiffuse) + 0.1f;
    });
    EXPECT_EQ(distinct(colours), 3u);
    EXPECT_GT(highlight, 50);
}

TEST_F(Shading, DiffuseThresholdMovesTheBoundary)
{
    ASSERT_TRUE(harness.ok());
    double previous = -1.0;
    for (const char* td : {"-0.4", "0", "0.4"}) {
        const std::string config = "toon.tones=2,toon.band=nearest,toon.diffuse_threshold=";
        const PngImage image = render("toon", config + td, std::string("toon_td_") + td);
        int shadow = 0, total = 0;
        forSphere(image, [&](const Rgb& c, float) {
            ++total;
            shadow += luminance(c) < luminance(kDiffuse) - 0.05f;
        });
        const double share = double(shadow) / total;
        EXPECT_GT(share, previous + 0.1) << "t_d=" << td;
        previous = share;
    }
}

TEST_F(Shading, SmoothBandsBlendOnlyAtTheBoundaries)
{
    ASSERT_TRUE(harness.ok());
    const PngImage hard = render("toon", "toon.band=nearest", "toon_nearest");
    std::set<Rgb> bands;
    forSphere(hard, [&](const Rgb& c, float) { bands.insert(c); });
    ASSERT_EQ(distinct(bands), 3u);
    const PngImage soft = render("toon", "toon.band=smooth", "toon_smooth");
    int between = 0, far = 0;
    forSphere(soft, [&](const Rgb& c, float ln) {
        bool known = false;
        for (const Rgb& b : bands) known = known || near(c, b);
        if (known) return;
        ++between;
        // One pixel is about 0.03 of L·n on this sphere; allow for the tessellation.
        if (std::abs(ln - 0.0f) > 0.12f && std::abs(ln - 0.92f) > 0.12f) ++far;
    });
    EXPECT_GT(between, 20);
    EXPECT_EQ(far, 0);
}

TEST_F(Shading, BandLinesInkTheBoundaries)
{
    ASSERT_TRUE(harness.ok());
    const PngImage image =
        render("toon", "toon.band_lines=on,toon.band_line_width=2", "toon_band_lines");
    int ink = 0, stray = 0;
    forSphere(image, [&](const Rgb& c, float ln) {
        if (luminance(c) > 0.12f) return;
        ++ink;
        if (std::abs(ln) > 0.15f && std::abs(ln - 0.92f) > 0.15f) ++stray;
    });
    EXPECT_GT(ink, 100);
    EXPECT_EQ(stray, 0);
}

TEST_F(Shading, DetailTextureShowsOnATexturedObject)
{
    ASSERT_TRUE(harness.ok());
    const GLuint checker = checkerTexture();
    const glm::vec4 white(1.0f);
    auto litLuminances = [&](const PngImage& image) {
        std::vector<float> out;
        forSphere(image, [&](const Rgb& c, float ln) {
            if (ln > 0.2f && ln < 0.85f) out.push_back(luminance(c));
        });
        return out;
    };
    auto spread = [](const std::vector<float>& v) {
        float lo = 1.0f, hi = 0.0f;
        for (float x : v) lo = std::min(lo, x), hi = std::max(hi, x);
        return hi - lo;
    };
    const auto modulated = litLuminances(
        render("toon", "toon.band=nearest", "toon_detail_modulate", white, checker));
    const auto decal = litLuminances(
        render("toon", "toon.band=nearest,toon.detail=decal", "toon_detail_decal", white, checker));
    const auto off = litLuminances(
        render("toon", "toon.band=nearest,toon.detail=off", "toon_detail_off", white, checker));
    EXPECT_GT(spread(modulated), 0.4f);
    EXPECT_GT(spread(decal), 0.4f);
    EXPECT_LT(spread(off), 0.01f);
    harness.gl().DeleteTextures(1, &checker);
}

TEST_F(Shading, ThresholdsOutOfOrderAreClampedWithAWarning)
{
    ASSERT_TRUE(harness.ok());
    testing::internal::CaptureStderr();
    const PngImage image = render(
        "toon", "toon.band=nearest,toon.diffuse_threshold=0.5,toon.highlight_threshold=0.2",
        "toon_clamped");
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find("diffuse_threshold"), std::string::npos) << log;
    // Clamped to t_h = t_d + 0.02: the shadow still covers L·n < 0.5.
    int wrong = 0;
    forSphere(image, [&](const Rgb& c, float ln) {
        if (ln < 0.45f && luminance(c) > luminance(kDiffuse) - 0.05f) ++wrong;
    });
    EXPECT_LT(wrong, 20);
}

TEST_F(Shading, TexturedShadowSideIsDarkerAndHatched)
{
    ASSERT_TRUE(harness.ok());
    const PngImage image = render("textured", "", "textured_default");
    double lit = 0, shadow = 0, shadowSq = 0;
    int nLit = 0, nShadow = 0;
    forSphere(image, [&](const Rgb& c, float ln) {
        const double l = luminance(c);
        if (ln > 0.3f) lit += l, ++nLit;
        if (ln < -0.1f) shadow += l, shadowSq += l * l, ++nShadow;
    });
    ASSERT_GT(nLit, 500);
    ASSERT_GT(nShadow, 400);
    const double shadowMean = shadow / nShadow;
    EXPECT_LT(shadowMean + 0.1, lit / nLit);
    // Strokes on paper: the shadow side varies strongly from pixel to pixel.
    const double variance = shadowSq / nShadow - shadowMean * shadowMean;
    EXPECT_GT(std::sqrt(variance), 0.05);
}

TEST_F(Shading, TexturedLayersAreOptional)
{
    ASSERT_TRUE(harness.ok());
    // No textures at all: only the shading colours remain (two, plus their antialiased edge).
    const PngImage plain = render(
        "textured", "textured.light_texture=none,textured.shadow_texture=none", "textured_none");
    std::map<Rgb, int> colours;
    forSphere(plain, [&](const Rgb& c, float) { ++colours[c]; });
    std::set<Rgb> major;
    for (const auto& [c, n] : colours) {
        if (n > 50) major.insert(c);
    }
    EXPECT_EQ(distinct(major), 2u);
    // Hatching on the lit side only: the lit side varies, the shadow side is flat.
    const PngImage lightOnly =
        render("textured", "textured.light_texture=hatching,textured.shadow_texture=none",
               "textured_light_only");
    std::set<Rgb> lit, dark;
    forSphere(lightOnly, [&](const Rgb& c, float ln) {
        if (ln > 0.4f) lit.insert(c);
        if (ln < -0.4f) dark.insert(c);
    });
    EXPECT_GT(lit.size(), 5u);
    EXPECT_EQ(dark.size(), 1u);
}

TEST_F(Shading, TexturedTransitionBandIsIndependentOfTheDiffuseThreshold)
{
    ASSERT_TRUE(harness.ok());
    // A band far from t_d: the shadow texture reaches well into the lit colour region.
    const PngImage image =
        render("textured",
               "textured.tint=off,textured.light_texture=none,textured.transition=symmetric,"
               "textured.alpha_low=0.5,textured.alpha_high=0.6",
               "textured_band_moved");
    int hatchedLit = 0;
    forSphere(image, [&](const Rgb& c, float ln) {
        if (ln > 0.1f && ln < 0.4f) hatchedLit += luminance(c) < 0.5f;
    });
    EXPECT_GT(hatchedLit, 100);
}

TEST_F(Shading, HalftoneIsNearBinaryAndDarkerInShadow)
{
    ASSERT_TRUE(harness.ok());
    for (const char* pattern : {"dots", "lines", "noise", "bricks"}) {
        const PngImage image = render("halftone", std::string("halftone.pattern=") + pattern,
                                      std::string("halftone_") + pattern);
        const Rgb paper{250, 247, 238}, ink{0, 0, 0};
        int binary = 0, total = 0;
        double litInk = 0, shadowInk = 0;
        int nLit = 0, nShadow = 0;
        forSphere(image, [&](const Rgb& c, float ln) {
            ++total;
            binary += near(c, paper, 25) || near(c, ink, 25);
            const double coverage = 1.0 - luminance(c) / luminance(paper);
            if (ln > 0.3f) litInk += coverage, ++nLit;
            if (ln < -0.3f) shadowInk += coverage, ++nShadow;
        });
        EXPECT_GE(binary, total * 95 / 100) << pattern << ": " << binary << " of " << total;
        EXPECT_GT(shadowInk / nShadow, litInk / nLit + 0.2) << pattern;
    }
}

TEST_F(Shading, HalftoneReadsAPngScreen)
{
    ASSERT_TRUE(harness.ok());
    // Vertical stripes, 4 ink and 4 blank texels: the output stripes run vertically.
    PngImage screen;
    screen.width = screen.height = 16;
    screen.rgba.resize(16 * 16 * 4);
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            uint8_t* p = &screen.rgba[size_t(y * 16 + x) * 4];
            p[0] = p[1] = p[2] = (x % 8) < 4 ? 0 : 255;
            p[3] = 255;
        }
    }
    // A directory of this run's own: a PNG the style reads back must be ours.
    const std::string path = freshDir("shading_screen") + "/stripes_screen.png";
    std::string error;
    ASSERT_TRUE(screen.write(path, error)) << error;
    const PngImage image =
        render("halftone", "halftone.screen_png=" + path + ",halftone.ambient=0.3",
               "halftone_png");
    // Compare each pixel with its neighbours across and along the stripes.
    int across = 0, along = 0;
    for (int y = 30; y < 98; ++y) {
        for (int x = 30; x < 98; ++x) {
            if (!sphereLight(x, y, 4.0f) || !sphereLight(x + 1, y + 1, 4.0f)) continue;
            const float l = luminance(pixel(image, x, y));
            across += std::abs(l - luminance(pixel(image, x + 1, y))) > 0.5f;
            along += std::abs(l - luminance(pixel(image, x, y + 1))) > 0.5f;
        }
    }
    EXPECT_GT(across, 200);
    EXPECT_LT(along, across / 10);
}

TEST_F(Shading, HalftoneMissingPngFallsBackWithAnError)
{
    ASSERT_TRUE(harness.ok());
    const PngImage reference = render("halftone", "", "halftone_reference");
    testing::internal::CaptureStderr();
    const PngImage image =
        render("halftone", "halftone.screen_png=/nonexistent/screen.png", "halftone_missing");
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find("nprgl"), std::string::npos) << log;
    EXPECT_NE(log.find("/nonexistent/screen.png"), std::string::npos) << log;
    EXPECT_EQ(image.rgba, reference.rgba); // the procedural default
}

TEST_F(Shading, TexturedMissingPngFallsBackWithAnError)
{
    ASSERT_TRUE(harness.ok());
    const PngImage reference = render("textured", "", "textured_reference");
    testing::internal::CaptureStderr();
    const PngImage image =
        render("textured", "textured.shadow_png=/nonexistent/shadow.png", "textured_missing");
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find("/nonexistent/shadow.png"), std::string::npos) << log;
    EXPECT_EQ(image.rgba, reference.rgba);
}

TEST(ShadingSettings, OutOfRangeValuesAreRefused)
{
    StyleSettings settings;
    std::string error;
    EXPECT_TRUE(StyleSettings::parse("halftone", "halftone.smoothness=12,halftone.pattern=bricks",
                                     settings, error))
        << error;
    for (const char* bad :
         {"toon.tones=4", "toon.band=wobbly", "toon.band_line_width=0", "toon.detail=sticker",
          "halftone.smoothness=0.5", "halftone.gamma=20", "halftone.screen_scale=0",
          "halftone.pattern=stars", "textured.alpha_low=-2", "textured.light_texture=bricks",
          "textured.transition=wavy", "textured.texture_scale=100"}) {
        const std::string chain = std::string(bad).substr(0, std::string(bad).find('.'));
        EXPECT_FALSE(StyleSettings::parse(chain, bad, settings, error)) << bad;
        EXPECT_NE(error.find(std::string(bad).substr(0, std::string(bad).find('='))),
                  std::string::npos)
            << error;
    }
}

TEST(ShadingTextures, GeneratorsAreDeterministicAndTile)
{
    using namespace nprgl::styles;
    const TextureImage a = HatchTexture::make({}), b = HatchTexture::make({});
    EXPECT_EQ(a.pixels, b.pixels);
    HatchTexture::Options cross;
    cross.cross = true;
    cross.size = 96;
    cross.spacing = 6;
    const TextureImage c = HatchTexture::make(cross);
    auto inkShare = [](const TextureImage& t) {
        int ink = 0;
        for (uint8_t v : t.pixels) ink += v < 128;
        return double(ink) / double(t.pixels.size());
    };
    EXPECT_GT(inkShare(a), 0.05);
    EXPECT_GT(inkShare(c), inkShare(a) * 1.5); // cross-hatching is darker
    EXPECT_GT(inkShare(StippleTexture::make({})), 0.02);
    // Seamless: the last column continues into the first about as smoothly as neighbours do.
    auto seam = [](const TextureImage& t, int x0, int x1) {
        int diff = 0;
        for (int y = 0; y < t.height; ++y) diff += std::abs(int(t.at(x0, y)) - int(t.at(x1, y)));
        return diff;
    };
    EXPECT_LT(seam(c, c.width - 1, 0), 2 * seam(c, 10, 11) + 255);
}

TEST(ShadingTextures, ScreensCombineAsTheThesisSays)
{
    using namespace nprgl::styles;
    HalftoneScreens::Set set;
    set.a = TextureImage::grey(8, 8, 255);
    set.b = TextureImage::grey(8, 8, 0);
    set.c = TextureImage::grey(8, 8, 0);
    set.a.at(0, 0) = 0;
    const TextureImage h = HalftoneScreens::combine(set);
    EXPECT_EQ(h.at(0, 0), 0);  // A's ink
    EXPECT_EQ(h.at(3, 3), 84); // B's ink remapped to 0.33
    set.b = TextureImage::grey(8, 8, 255);
    EXPECT_EQ(HalftoneScreens::combine(set).at(3, 3), 168); // C's ink at 0.66
    // The generated screens span the whole range, darkest in A.
    for (auto pattern : {HalftoneScreens::Pattern::Dots, HalftoneScreens::Pattern::Lines,
                         HalftoneScreens::Pattern::Noise, HalftoneScreens::Pattern::Bricks}) {
        const TextureImage combined = HalftoneScreens::combine(HalftoneScreens::make(pattern));
        int lo = 255, hi = 0;
        for (uint8_t v : combined.pixels) lo = std::min(lo, int(v)), hi = std::max(hi, int(v));
        EXPECT_LT(lo, 30);
        EXPECT_GT(hi, 150);
    }
}

TEST_F(Shading, TexturedAsymmetricTransitionKeepsStrokesSolid)
{
    ASSERT_TRUE(harness.ok());
    // In the middle of the band the symmetric cross-fade greys the strokes out; the
    // non-symmetric transition (fig. 3.13) keeps them at full strength.
    const std::string common = "textured.tint=off,textured.light_texture=none,"
                               "textured.alpha_low=-0.4,textured.alpha_high=0.4,";
    auto solidInk = [&](const std::string& transition) {
        const PngImage image = render("textured", common + "textured.transition=" + transition,
                                      "textured_" + transition);
        int solid = 0;
        forSphere(image, [&](const Rgb& c, float ln) {
            if (std::abs(ln) < 0.08f) solid += luminance(c) < 0.3f;
        });
        return solid;
    };
    const int symmetric = solidInk("symmetric");
    const int asymmetric = solidInk("asymmetric");
    EXPECT_LT(symmetric, 5);
    EXPECT_GT(asymmetric, 40);
}

TEST_F(Shading, TexturedHighlightVariantKeepsDetailOutOfTheHighlight)
{
    ASSERT_TRUE(harness.ok());
    const GLuint checker = checkerTexture();
    const PngImage image = render("textured",
                                  "textured.variant=highlight,textured.highlight_threshold=0.7,"
                                  "textured.alpha_low=-0.05,textured.alpha_high=0.05",
                                  "textured_highlight", glm::vec4(1.0f), checker);
    std::set<Rgb> highlight, below;
    forSphere(image, [&](const Rgb& c, float ln) {
        if (ln > 0.8f) highlight.insert(c);
        if (ln > 0.1f && ln < 0.6f) below.insert(c);
    });
    EXPECT_EQ(distinct(highlight), 1u);
    EXPECT_GT(below.size(), 10u);
    harness.gl().DeleteTextures(1, &checker);
}

// Gooch et al.: per pixel, mix((0, 0, b) + alpha k, (y, y, 0) + beta k, (1 + L.n) / 2) for the
// object's colour k: on a grey object, cool (blue wins) turned away from the light, warm (red
// wins) towards it, and nowhere black.
TEST_F(Shading, GoochTonesFollowTheLightFromCoolToWarm)
{
    ASSERT_TRUE(harness.ok());
    const glm::vec3 k(0.5f, 0.5f, 0.5f);
    const PngImage image = render("gooch", "", "gooch", glm::vec4(k, 1.0f));
    const glm::vec3 cool = glm::vec3(0, 0, 0.4f) + 0.2f * k;
    const glm::vec3 warm = glm::vec3(0.4f, 0.4f, 0) + 0.6f * k;
    int wrong = 0, total = 0, coolSide = 0, warmSide = 0;
    float darkest = 1.0f;
    forSphere(image, [&](const Rgb& c, float ln) {
        ++total;
        const glm::vec3 e = 255.0f * glm::mix(cool, warm, 0.5f * (1.0f + ln));
        // The tessellated normal is a little off the analytic one; a few levels allowed.
        if (!near(c, {int(std::lround(e.r)), int(std::lround(e.g)), int(std::lround(e.b))}, 8))
            ++wrong;
        if (ln < -0.2f) coolSide += c.b > c.r;
        if (ln > 0.2f) warmSide += c.r > c.b;
        darkest = std::min(darkest, luminance(c));
    });
    EXPECT_GT(total, 3000);
    EXPECT_LT(wrong, total / 100) << wrong << " of " << total;
    EXPECT_GT(coolSide, 300);
    EXPECT_GT(warmSide, 300);
    EXPECT_GT(darkest, 0.05f);
}

// The parameters reach the shader: with no blue and no yellow, alpha = beta = 1 leaves the
// object's own colour everywhere.
TEST_F(Shading, GoochWithoutTonesIsTheObjectsColour)
{
    ASSERT_TRUE(harness.ok());
    const PngImage image = render(
        "gooch", "gooch.blue=0,gooch.yellow=0,gooch.alpha=1,gooch.beta=1", "gooch_flat");
    std::set<Rgb> colours;
    forSphere(image, [&](const Rgb& c, float) { colours.insert(c); });
    EXPECT_EQ(distinct(colours), 1u);
    EXPECT_TRUE(near(*colours.begin(), kDiffuse, 2));
}

namespace {

// A tone map for xtoon: colour(u, v) for u, v in [0, 1], v = 0 the top row.
std::string toneMapPng(const std::string& name, const std::function<Rgb(float, float)>& colour)
{
    PngImage image;
    image.width = 64;
    image.height = 32;
    image.rgba.resize(size_t(image.width) * image.height * 4);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const Rgb c = colour((x + 0.5f) / image.width, (y + 0.5f) / image.height);
            uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
            p[0] = uint8_t(c.r);
            p[1] = uint8_t(c.g);
            p[2] = uint8_t(c.b);
            p[3] = 255;
        }
    }
    const std::string path = freshDir("xtoon_maps") + "/" + name + ".png";
    std::string error;
    EXPECT_TRUE(image.write(path, error)) << error;
    return path;
}

const glm::vec4 kWhite(1.0f);

} // namespace

// The map's first axis is L.n: a user map blue on its left half, yellow on its right, gives
// a white sphere blue where it turns from the light and yellow where it faces it.
TEST_F(Shading, XToonTakesItsToneFromTheMapByTheLight)
{
    const std::string map = toneMapPng("halves", [](float u, float) {
        return u < 0.5f ? Rgb{40, 60, 220} : Rgb{230, 210, 40};
    });
    PngImage image = render("xtoon", "xtoon.texture=" + map, "xtoon_halves", kWhite);
    int right = 0, wrong = 0;
    forSphere(image, [&](const Rgb& c, float ln) {
        if (std::abs(ln) < 0.15f) return; // the boundary, filtered
        const bool blue = c.b > c.r + 100, yellow = c.r > c.b + 100 && c.g > c.b + 100;
        ((ln < 0.0f ? blue : yellow) ? right : wrong)++;
    });
    EXPECT_GT(right, 2000);
    EXPECT_LT(wrong, right / 100);
}

// The depth axis: with the whole sphere nearer than `far` the bands are there (v = 0); with
// all of it beyond `far`, the generated map's top row gives nearly one flat tone.
TEST_F(Shading, XToonFlattensTheBandsWithDepth)
{
    auto spread = [](const PngImage& image) {
        float lo = 1.0f, hi = 0.0f;
        forSphere(image, [&](const Rgb& c, float) {
            lo = std::min(lo, luminance(c));
            hi = std::max(hi, luminance(c));
        });
        return hi - lo;
    };
    const float detailed =
        spread(render("xtoon", "xtoon.near=0.1,xtoon.far=100", "xtoon_near", kWhite));
    const float abstract =
        spread(render("xtoon", "xtoon.near=0.1,xtoon.far=2", "xtoon_far", kWhite));
    EXPECT_GT(detailed, 0.45f) << "no bands in full detail";
    EXPECT_LT(abstract, 0.2f) << "the far sphere kept its bands";
}

// The orientation axis: v = 1 - |n.v|^r. A map green on its top half (v < 0.5), magenta below
// gives the sphere's middle green and its rim magenta.
TEST_F(Shading, XToonOrientationTintsTheRim)
{
    const std::string map = toneMapPng("rims", [](float, float v) {
        return v < 0.5f ? Rgb{40, 200, 60} : Rgb{210, 40, 200};
    });
    PngImage image = render("xtoon", "xtoon.mode=orientation,xtoon.texture=" + map,
                            "xtoon_rims", kWhite);
    auto isGreen = [](const Rgb& c) { return c.g > c.r + 100; };
    auto isMagenta = [](const Rgb& c) { return c.r > c.g + 100 && c.b > c.g + 100; };
    const int cx = kSize / 2, cy = kSize / 2;
    EXPECT_TRUE(isGreen(pixel(image, cx, cy))) << "the middle is not green";
    // Just inside the outline, left and right.
    const float t = std::tan(glm::radians(kFov) / 2.0f);
    const int r = int(kRadius / (-kCentre.z * t) * (kSize / 2.0f) * 0.97f);
    EXPECT_TRUE(isMagenta(pixel(image, cx - r + 2, cy))) << "the left rim is not magenta";
    EXPECT_TRUE(isMagenta(pixel(image, cx + r - 2, cy))) << "the right rim is not magenta";
}

// A tone map that cannot be read (missing, or not a PNG) is said and replaced by the
// generated one: the same picture.
TEST_F(Shading, XToonFallsBackToTheGeneratedMap)
{
    const PngImage generated = render("xtoon", "", "xtoon_default", kWhite);
    std::set<Rgb> colours;
    forSphere(generated, [&](const Rgb& c, float) { colours.insert(c); });
    EXPECT_GT(distinct(colours), 2u) << "nothing drawn";
    const std::string garbage = freshDir("xtoon_garbage") + "/tone.png";
    {
        std::ofstream out(garbage);
        out << "not a PNG at all";
    }
    for (const std::string& path : {std::string("/nonexistent/tone.png"), garbage}) {
        testing::internal::CaptureStderr();
        const PngImage fallback = render("xtoon", "xtoon.texture=" + path, "xtoon_fallback",
                                         kWhite);
        const std::string log = testing::internal::GetCapturedStderr();
        EXPECT_NE(log.find("nprgl"), std::string::npos) << log;
        EXPECT_NE(log.find(path), std::string::npos) << log;
        EXPECT_EQ(generated.rgba, fallback.rgba) << path;
    }
}

// r widens the rims: more of the sphere reaches the map's lower half with r = 8 than with
// r = 1 (v = 1 - |n.v|^r grows with r wherever |n.v| < 1).
TEST_F(Shading, XToonRimWidensWithR)
{
    const std::string map = toneMapPng("rims_r", [](float, float v) {
        return v < 0.5f ? Rgb{40, 200, 60} : Rgb{210, 40, 200};
    });
    auto rim = [&](const std::string& r) {
        const PngImage image = render("xtoon", "xtoon.mode=orientation,xtoon.r=" + r +
                                                   ",xtoon.texture=" + map,
                                      "xtoon_rims_r" + r, kWhite);
        int magenta = 0;
        forSphere(image, [&](const Rgb& c, float) { magenta += c.r > c.g + 100; });
        return magenta;
    };
    const int thin = rim("1"), wide = rim("8");
    EXPECT_GT(thin, 100) << "no rim at r = 1";
    EXPECT_GT(wide, 2 * thin) << "the rim did not widen with r";
}

// The generated map has `bands` cel bands: in full detail (v about 0) the sphere shows that
// many flat tones, each over a good number of pixels.
TEST_F(Shading, XToonGeneratedMapHasTheBandsAskedFor)
{
    auto plateaus = [&](int bands) {
        const PngImage image = render(
            "xtoon", "xtoon.near=0.1,xtoon.far=10000,xtoon.bands=" + std::to_string(bands),
            "xtoon_bands" + std::to_string(bands), kWhite);
        std::map<int, int> counts;
        forSphere(image, [&](const Rgb& c, float) { ++counts[c.g]; });
        int n = 0;
        for (const auto& [level, count] : counts) n += count >= 60;
        return n;
    };
    EXPECT_EQ(plateaus(2), 2);
    EXPECT_EQ(plateaus(3), 3);
    EXPECT_EQ(plateaus(5), 5);
}

namespace {

// Luminance spread (max - min) of the pixels within 0.85 of a sphere's projected radius.
float sphereSpread(const PngImage& image, const glm::mat4& projection, glm::vec3 centre,
                   float radius)
{
    const glm::vec4 clip = projection * glm::vec4(centre, 1.0f);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const glm::vec2 px((ndc.x + 1.0f) * 0.5f * image.width, (1.0f - ndc.y) * 0.5f * image.height);
    const float r = 0.85f * radius / -centre.z * projection[1][1] * 0.5f * image.height;
    float lo = 1.0f, hi = 0.0f;
    int n = 0;
    for (int y = 0; y < int(image.height); ++y) {
        for (int x = 0; x < int(image.width); ++x) {
            if (glm::length(glm::vec2(x + 0.5f, y + 0.5f) - px) > r) continue;
            lo = std::min(lo, luminance(pixel(image, x, y)));
            hi = std::max(hi, luminance(pixel(image, x, y)));
            ++n;
        }
    }
    EXPECT_GT(n, 300);
    return hi - lo;
}

} // namespace

// With near and far at 0 the depth axis spans the scene: of two like spheres the near one
// keeps its bands, the far one is flattened (level of abstraction). Moving only `near` out to
// the far sphere gives it back its bands, the scene still giving `far`.
TEST(XToon, DepthAxisSpansTheScene)
{
    StyleHarness harness(256, 128);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 projection =
        glm::perspective(glm::radians(kFov), 2.0f, 1.0f, 40.0f);
    const glm::vec3 nearCentre(-1.5f, 0.0f, -4.0f), farCentre(4.5f, 0.0f, -12.0f);
    auto scene = harness.makeScene(
        {sphereBatch(glm::translate(glm::mat4(1.0f), nearCentre), 1.0f, 48, 24, kWhite, 1),
         sphereBatch(glm::translate(glm::mat4(1.0f), farCentre), 1.0f, 48, 24, kWhite, 2)},
        projection, glm::normalize(glm::vec3(-1.0f, 0.4f, 0.3f))); // from the side: all bands
    ASSERT_EQ(scene.objects.size(), 2u);
    auto spreads = [&](const std::string& config, const std::string& name) {
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "xtoon", config, image, error)) << error;
        save(image, name);
        return std::make_pair(sphereSpread(image, projection, nearCentre, 1.0f),
                              sphereSpread(image, projection, farCentre, 1.0f));
    };
    const auto [nearBands, farBands] = spreads("", "xtoon_scene_depth");
    EXPECT_GT(nearBands, 0.45f) << "the near sphere lost its bands";
    EXPECT_LT(farBands, 0.2f) << "the far sphere kept its bands";
    const auto [nearAgain, farNow] = spreads("xtoon.near=10.5", "xtoon_scene_depth_near");
    EXPECT_GT(nearAgain, 0.45f);
    EXPECT_GT(farNow, 0.3f) << "near alone did not move the axis";
}

// Gooch's pure tones: generated from b and y (blue facing away from the light, yellow facing
// it), or the user's ramp; with the object's share at zero only the tones show.
TEST_F(Shading, GoochTakesItsPureTonesFromTheRamp)
{
    const std::string bare = "gooch.alpha=0,gooch.beta=0";
    auto count = [](const PngImage& image, const std::function<bool(const Rgb&)>& shadow,
                    const std::function<bool(const Rgb&)>& lit) {
        int right = 0, wrong = 0;
        forSphere(image, [&](const Rgb& c, float ln) {
            if (std::abs(ln) < 0.5f) return; // the middle of the ramp mixes both
            ((ln < 0.0f ? shadow(c) : lit(c)) ? right : wrong)++;
        });
        return std::pair{right, wrong};
    };
    const PngImage generated = render("gooch", bare, "gooch_generated", kWhite);
    auto [gRight, gWrong] = count(
        generated, [](const Rgb& c) { return c.b > c.r + 40 && c.b > c.g + 40; },
        [](const Rgb& c) { return c.r > c.b + 40 && c.g > c.b + 40; });
    EXPECT_GT(gRight, 1000);
    EXPECT_LT(gWrong, gRight / 100);

    const std::string map = toneMapPng("gooch_ramp", [](float u, float) {
        return u < 0.5f ? Rgb{200, 30, 200} : Rgb{30, 200, 200};
    });
    const PngImage user = render("gooch", bare + ",gooch.texture=" + map, "gooch_user", kWhite);
    auto [uRight, uWrong] = count(
        user, [](const Rgb& c) { return c.r > c.g + 100 && c.b > c.g + 100; },
        [](const Rgb& c) { return c.g > c.r + 100 && c.b > c.r + 100; });
    EXPECT_GT(uRight, 1000);
    EXPECT_LT(uWrong, uRight / 100);

    const PngImage fallback =
        render("gooch", bare + ",gooch.texture=/nonexistent/ramp.png", "gooch_fallback", kWhite);
    EXPECT_EQ(fallback.rgba, generated.rgba);
}

namespace {

// The mean luminance of the size x size patch from pixel (x0, y0) on, as pixel() counts.
float meanLuminance(const PngImage& image, int x0, int y0, int size)
{
    float sum = 0.0f;
    for (int y = y0; y < y0 + size; ++y) {
        for (int x = x0; x < x0 + size; ++x) sum += luminance(pixel(image, x, y));
    }
    return sum / float(size * size);
}

// A 2x2 quad facing the eye at kCentre, in colour; its texture (or else lightmap) coordinates
// run from 0 on its left edge to 1 on its right, at t = 0.5.
reconstruct::Batch facingQuad(const glm::vec4& colour, bool texture)
{
    reconstruct::Batch quad;
    quad.mode = GL_TRIANGLES;
    quad.modelview = glm::translate(glm::mat4(1.0f), kCentre);
    quad.materialId = 1;
    const glm::vec2 corners[6] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (const glm::vec2& c : corners) {
        reconstruct::Vertex v{};
        v.position = {c.x, c.y, 0.0f};
        v.normal = {0.0f, 0.0f, 1.0f};
        v.hasNormal = true;
        v.color = colour;
        (texture ? v.texcoord : v.lightcoord) = {0.5f * (c.x + 1.0f), 0.5f};
        quad.vertices.push_back(v);
    }
    return quad;
}

} // namespace

// A lightmapped surface of a program without GL lighting (Quake-style worlds): the shading
// styles take its light from the lightmap's luminance, not from L·n. A flat quad whose
// lightmap is dark on the left and bright on the right gets the shadow band on the left and a
// lit band on the right in toon; without the lightmap both halves are alike (one plane, one
// light direction), and so are they in halftone's density and pencil's hatching.
TEST_F(Shading, LightmapsGiveTheLightOfUnlitSurfaces)
{
    ASSERT_TRUE(harness.ok());
    const styles::GlFunctions& gl = harness.gl();
    const uint8_t texels[2 * 3] = {30, 30, 30, 240, 240, 240};
    const GLuint lightmap = nearestTexture(GL_RGB8, 2, 1, GL_RGB, texels);

    // The lightmap's left texel on the left half, its right one on the right.
    const reconstruct::Batch quad = facingQuad(glm::vec4(0.8f, 0.8f, 0.8f, 1.0f), false);
    auto halves = [&](const std::string& chain, bool withLightmap, const std::string& name) {
        auto scene = harness.makeScene({quad}, perspective(), kLight);
        for (auto& o : scene.objects) o.lightmap = withLightmap ? lightmap : 0;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, chain, "", image, error)) << error;
        save(image, name);
        // A patch left and right of the middle, inside the quad.
        return std::pair{meanLuminance(image, kSize / 2 - 20, kSize / 2 - 6, 12),
                         meanLuminance(image, kSize / 2 + 8, kSize / 2 - 6, 12)};
    };
    for (const std::string chain : {"toon", "halftone", "pencil"}) {
        const auto [left, right] = halves(chain, true, chain + "_lightmap");
        const auto [plainLeft, plainRight] = halves(chain, false, chain + "_no_lightmap");
        EXPECT_GT(right - left, 0.2f) << chain << ": the lightmap's dark side is not darker";
        // Hatching lines cross the two patches at different places.
        const float alike = chain == "pencil" ? 0.08f : 0.05f;
        EXPECT_LT(std::abs(plainRight - plainLeft), alike) << chain;
    }
    gl.DeleteTextures(1, &lightmap);
}

// A texture layer the styles do not draw keeps its average effect (SceneObject::layerScale,
// layerOffset, from its texture's mean): a detail texture added signed over a terrain left it
// darker than the program's. The shading styles apply the layer before fog.
TEST_F(Shading, ALayerNotDrawnKeepsItsMeanEffect)
{
    ASSERT_TRUE(harness.ok());
    const reconstruct::Batch quad = facingQuad(glm::vec4(0.4f, 0.4f, 0.4f, 1.0f), true);
    auto centre = [&](const std::string& chain, glm::vec3 scale, glm::vec3 offset) {
        // Lit from 53 degrees: toon's diffuse band (its highlight mixes in white).
        auto scene = harness.makeScene({quad}, perspective(), glm::vec3(0.0f, 0.8f, 0.6f));
        for (auto& o : scene.objects) {
            o.layerScale = scale;
            o.layerOffset = offset;
        }
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, chain, "", image, error)) << error;
        return meanLuminance(image, kSize / 2 - 6, kSize / 2 - 6, 12);
    };
    for (const std::string chain : {"toon", "textured", "xtoon"}) {
        const float plain = centre(chain, glm::vec3(1.0f), glm::vec3(0.0f));
        const float added = centre(chain, glm::vec3(1.0f), glm::vec3(0.3f));
        const float halved = centre(chain, glm::vec3(0.5f), glm::vec3(0.0f));
        EXPECT_NEAR(added - plain, 0.3f, 0.03f) << chain;
        EXPECT_NEAR(halved, 0.5f * plain, 0.03f) << chain;
    }
}

// A decal's or cut-out's texture is its drawing: pencil hatches its dark parts darker, as it
// does a darker colour. A translucent quad whose texture is black on the left and white on
// the right, lit evenly: the left half is hatched darker (before, the tone took the vertex
// colour alone, and neverball's painted start arrow vanished into its floor's hatching).
TEST_F(Shading, PencilHatchesADecalByItsTexture)
{
    ASSERT_TRUE(harness.ok());
    const styles::GlFunctions& gl = harness.gl();
    const uint8_t texels[2 * 4] = {0, 0, 0, 255, 255, 255, 255, 255};
    const GLuint texture = nearestTexture(GL_RGBA8, 2, 1, GL_RGBA, texels);

    const reconstruct::Batch quad = facingQuad(glm::vec4(1.0f), true);
    // Lit head-on: bare paper by the light alone, so only the texture can darken it.
    auto scene = harness.makeScene({quad}, perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (auto& o : scene.objects) {
        o.texture = texture;
        o.translucent = true;
    }
    PngImage image;
    std::string error;
    EXPECT_TRUE(harness.render(scene, "pencil", "pencil.outlines=off", image, error)) << error;
    save(image, "pencil_decal");
    const float left = meanLuminance(image, kSize / 2 - 30, kSize / 2 - 10, 20);
    const float right = meanLuminance(image, kSize / 2 + 10, kSize / 2 - 10, 20);
    EXPECT_GT(right - left, 0.1f) << "the texture's black half is not hatched darker: "
                                  << left << " against " << right;
    gl.DeleteTextures(1, &texture);
}

// GL reflects a sphere map about the normal as the modelview moved it, made unit only under
// GL_NORMALIZE: a quad whose normals are 0.7 long (blocktube's) shows about half the
// reflection. A texture whose red is its S coordinate, on a quad facing the eye: at a point on
// its diagonal the red is GL's S, interpolated from GL's formula at the corners (the replica
// normalised every normal, and blocktube's shine bands fell elsewhere: fidelity 0.61).
TEST_F(Shading, ReplicaReflectsASphereMapAboutTheNormalGlUses)
{
    ASSERT_TRUE(harness.ok());
    const styles::GlFunctions& gl = harness.gl();
    std::vector<uint8_t> ramp(256 * 4, 255);
    for (int x = 0; x < 256; ++x) ramp[size_t(x) * 4] = uint8_t(x);
    const GLuint texture = nearestTexture(GL_RGBA8, 256, 1, GL_RGBA, ramp.data());
    gl.BindTexture(GL_TEXTURE_2D, texture);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    // A quad 4 wide (the wider, the more the reflections differ), normals 0.7 long.
    constexpr float kHalf = 2.0f, kLength = 0.7f;
    reconstruct::Batch quad = facingQuad(glm::vec4(1.0f), false);
    for (auto& v : quad.vertices) {
        v.position *= kHalf;
        v.normal *= kLength;
    }
    // GL_SPHERE_MAP's S at the corner (h, h): the reflection of the eye's ray about n.
    auto cornerS = [&](float length) {
        const glm::vec3 u = glm::normalize(glm::vec3(kHalf, kHalf, 0.0f) + kCentre);
        const glm::vec3 n(0.0f, 0.0f, length);
        const glm::vec3 r = u - 2.0f * glm::dot(n, u) * n;
        return r.x / (2.0f * glm::length(r + glm::vec3(0.0f, 0.0f, 1.0f))) + 0.5f;
    };
    // A pixel on a diagonal, where the quad's two triangles agree: at eye x (and |y|) x h, S
    // is (1 - x) / 2 + x S(h, h) (by symmetry S(-h, -h) = 1 - S(h, h)).
    const int column = kSize - 21, row = 20;
    const float x = ((column + 0.5f) / (kSize / 2.0f) - 1.0f) * -kCentre.z *
                    std::tan(glm::radians(kFov / 2.0f)) / kHalf;
    auto redAt = [&](GLenum normals) {
        auto scene = harness.makeScene({quad}, perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
        for (auto& o : scene.objects) {
            o.texture = o.generated.texture = texture;
            o.generated.mode[0] = o.generated.mode[1] = GL_SPHERE_MAP;
            o.normals = normals;
        }
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "replica", "", image, error)) << error;
        save(image, normals == GL_NORMALIZE ? "replica_sphere_unit" : "replica_sphere_short");
        return pixel(image, column, row).r;
    };
    for (const GLenum normals : {GLenum(0), GLenum(GL_NORMALIZE)}) {
        const float s = (1.0f - x) / 2.0f + x * cornerS(normals == 0 ? kLength : 1.0f);
        // Red i is the texel centred on S (i + 0.5) / 256, sampled linearly.
        EXPECT_NEAR(redAt(normals), s * 256.0f - 0.5f, 3.0f)
            << (normals == 0 ? "normals as given" : "GL_NORMALIZE");
    }
    gl.DeleteTextures(1, &texture);
}

// Without GL lighting a sphere map is all the shading the program's picture has (blocktube's
// blocks): where a style drops it, the reflection gives the style its light as a lightmap
// does. An unlit quad reflecting a dark map comes out darker than one reflecting a bright map
// (before, both were shaded alike by the head-light, and blocktube's blocks lost the order of
// their lightness: 255 of 562 objects off the palette).
class ReflectionLight : public Shading, public ::testing::WithParamInterface<const char*> {};

TEST_P(ReflectionLight, AnUnlitSurfaceTakesItsLightFromTheReflectionItDrops)
{
    ASSERT_TRUE(harness.ok());
    const styles::GlFunctions& gl = harness.gl();
    auto lightness = [&](uint8_t grey) {
        const uint8_t texel[4] = {grey, grey, grey, 255};
        const GLuint map = nearestTexture(GL_RGBA8, 1, 1, GL_RGBA, texel);
        reconstruct::Batch quad = facingQuad(glm::vec4(0.2f, 0.7f, 0.3f, 1.0f), false);
        auto scene = harness.makeScene({quad}, perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
        for (auto& o : scene.objects) {
            o.lights.count = 0; // the program did not light it
            o.generated.texture = map;
            o.generated.mode[0] = o.generated.mode[1] = GL_SPHERE_MAP;
        }
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, GetParam(), "", image, error)) << error;
        gl.DeleteTextures(1, &map);
        return meanLuminance(image, kSize / 2 - 10, kSize / 2 - 10, 20);
    };
    const float dark = lightness(20), bright = lightness(235);
    EXPECT_GT(bright - dark, 0.03f) << "the reflection did not light the surface: " << dark
                                   << " against " << bright;
}

INSTANTIATE_TEST_SUITE_P(Styles, ReflectionLight,
                         ::testing::Values("toon", "textured", "halftone", "gooch", "xtoon"),
                         [](const auto& p) { return std::string(p.param); });

// A texture the program bound but never gave an image is incomplete: GL draws as if its unit
// were off, the surface in its own colour (atunnel's lit tunnel came out black in every style).
TEST_F(Shading, ATextureWithoutAnImageLeavesTheSurfaceItsColour)
{
    ASSERT_TRUE(harness.ok());
    const styles::GlFunctions& gl = harness.gl();
    GLuint empty = 0;
    glGenTextures(1, &empty);
    gl.BindTexture(GL_TEXTURE_2D, empty); // created, no image
    gl.BindTexture(GL_TEXTURE_2D, 0);
    const reconstruct::Batch quad = facingQuad(glm::vec4(0.9f, 0.6f, 0.2f, 1.0f), true);
    auto scene = harness.makeScene({quad}, perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (auto& o : scene.objects) o.texture = empty;
    PngImage image;
    std::string error;
    EXPECT_TRUE(harness.render(scene, "replica", "", image, error)) << error;
    save(image, "replica_incomplete_texture");
    const Rgb centre = pixel(image, kSize / 2, kSize / 2);
    EXPECT_NEAR(centre.r, 230, 3) << "the surface sampled the empty texture";
    EXPECT_NEAR(centre.g, 153, 3);
    gl.DeleteTextures(1, &empty);
}
