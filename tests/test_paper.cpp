// The paper background style rendered in-process through the style harness: which pixels
// become paper, that the scene and the ink keep theirs, and that the page stays inside the
// viewport. Pictures go to /tmp/paper/ for looking at them.

#include "tests/support/Process.h"
#include "tests/support/StyleHarness.h"

#include "styles/StyleChain.h"
#include "styles/StyleSettings.h"

#include <GL/osmesa.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <filesystem>
#include <functional>
#include <set>

using namespace nprgl;
using namespace nprgl::test;

namespace {

constexpr int kSize = 128;
constexpr float kFov = 40.0f;
constexpr float kDistance = 6.0f;
constexpr float kRadius = 1.5f;
const glm::vec4 kRed(0.85f, 0.25f, 0.2f, 1.0f);
const glm::vec4 kBlack(0.0f, 0.0f, 0.0f, 1.0f);

struct Rgb {
    int r, g, b;
    bool operator==(const Rgb&) const = default;
    bool operator<(const Rgb& o) const { return std::tie(r, g, b) < std::tie(o.r, o.g, o.b); }
};

const Rgb kPaper{0xf4, 0xef, 0xe1}; // the default colour

glm::mat4 perspective() { return glm::perspective(glm::radians(kFov), 1.0f, 1.0f, 20.0f); }

styles::Scene sphereScene(StyleHarness& harness)
{
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
    return harness.makeScene({sphereBatch(mv, kRadius, 48, 24, kRed)}, perspective());
}

// The sphere's outline radius in pixels (centred on the optical axis).
float silhouetteRadius()
{
    const float half = std::tan(std::asin(kRadius / kDistance));
    return half / std::tan(glm::radians(kFov) * 0.5f) * float(kSize) * 0.5f;
}

// Distance of pixel (x, y) (top row first) from the image centre.
float fromCentre(int x, int y)
{
    return std::hypot(x + 0.5f - kSize * 0.5f, y + 0.5f - kSize * 0.5f);
}

Rgb pixel(const PngImage& image, int x, int y)
{
    const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
    return {p[0], p[1], p[2]};
}

bool near(const Rgb& a, const Rgb& b, int tolerance = 1)
{
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance &&
           std::abs(a.b - b.b) <= tolerance;
}

void save(const PngImage& image, const std::string& name)
{
    std::filesystem::create_directories("/tmp/paper");
    std::string error;
    image.write("/tmp/paper/" + name + ".png", error);
}

// These tests are of the light page (PageTone's choice has its own): paper.tone=light unless
// the test says otherwise.
std::string lightPage(const std::string& config)
{
    if (config.find("paper.tone=") != std::string::npos) return config;
    return "paper.tone=light" + (config.empty() ? "" : "," + config);
}

PngImage render(StyleHarness& harness, const styles::Scene& scene, const std::string& chain,
                const std::string& config, glm::vec4 background = kBlack)
{
    // The harness clears with whatever masks the previous chain left (edges leaves some).
    const styles::GlFunctions& gl = harness.gl();
    gl.DepthMask(GL_TRUE);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.Disable(GL_SCISSOR_TEST);
    PngImage image;
    std::string error;
    EXPECT_TRUE(harness.render(scene, chain, lightPage(config), image, error, background))
        << chain << ": " << error;
    return image;
}

// Starts `chain` with `config` in the harness's (current) OSMesa context.
void startChain(styles::StyleChain& chain, const std::string& name, const std::string& config)
{
    StyleSettings settings;
    std::string error;
    ASSERT_TRUE(StyleSettings::parse(name, lightPage(config), settings, error)) << error;
    auto getProc = [](const char* entry) {
        return reinterpret_cast<void*>(OSMesaGetProcAddress(entry));
    };
    ASSERT_TRUE(chain.init(settings, getProc, error)) << error;
}

// The window's pixels, top row first.
PngImage readBack(const styles::GlFunctions& gl)
{
    gl.Finish();
    PngImage image;
    image.width = image.height = kSize;
    image.rgba.resize(size_t(kSize) * kSize * 4);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    image.flipRows();
    return image;
}

// Runs a chain over whatever `paint` put into the colour and depth buffers, like a flush
// after the program's own drawing (a 2D backdrop, say). The held-back scene draws nothing
// here, so the chain should be free of shading styles.
PngImage renderOver(StyleHarness& harness, const styles::Scene& scene, const std::string& chain,
                    const std::string& config,
                    const std::function<void(const styles::GlFunctions&)>& paint)
{
    styles::StyleChain styleChain;
    startChain(styleChain, chain, config);
    const styles::GlFunctions& gl = harness.gl();
    gl.Viewport(0, 0, kSize, kSize);
    gl.ClearColor(scene.clearColor.r, scene.clearColor.g, scene.clearColor.b, 1.0f);
    gl.ClearDepth(1.0);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    paint(gl);
    styleChain.render(scene);
    PngImage image = readBack(gl);
    styleChain.shutdown();
    return image;
}

// Fills a window rectangle (x, y up) of the colour and/or depth buffer, without touching the
// other: what a program's 2D drawing with depth writes off (or colour writes off) leaves.
void fillRect(const styles::GlFunctions& gl, glm::ivec4 rect, const glm::vec4* colour,
              const double* depth)
{
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(rect.x, rect.y, rect.z, rect.w);
    GLbitfield mask = 0;
    if (colour) {
        gl.ClearColor(colour->r, colour->g, colour->b, colour->a);
        mask |= GL_COLOR_BUFFER_BIT;
    }
    if (depth) {
        gl.ClearDepth(*depth);
        mask |= GL_DEPTH_BUFFER_BIT;
    }
    gl.Clear(mask);
    gl.Disable(GL_SCISSOR_TEST);
    gl.ClearDepth(1.0);
}

} // namespace

TEST(Paper, FillsTheBackgroundAndKeepsTheToonBands)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    const PngImage toon = render(harness, scene, "toon", "");
    const PngImage paper = render(harness, scene, "toon+paper", "paper.grain=0");
    save(toon, "toon");
    save(paper, "toon_paper");
    int background = 0, sphere = 0;
    std::set<Rgb> bands;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Rgb before = pixel(toon, x, y), after = pixel(paper, x, y);
            if (before == Rgb{0, 0, 0}) {
                // The cleared background: all of it is paper now.
                ++background;
                EXPECT_TRUE(near(after, kPaper)) << x << "," << y;
            } else {
                // The sphere: exactly the toon colours.
                ++sphere;
                bands.insert(after);
                EXPECT_EQ(after, before) << x << "," << y;
            }
        }
    }
    EXPECT_GT(background, kSize * kSize / 2);
    EXPECT_GT(sphere, 1000);
    EXPECT_GE(bands.size(), 3u); // shadow, diffuse and highlight survive
}

// The page follows the program's background (paper.tone=auto, the default): a program that
// clears to black gets a dark page, and the ink of its outlines is light on it, not black on
// black; one that clears to a light colour gets paper and black ink.
TEST(Paper, APageAsDarkAsTheProgramsBackgroundWithLightInk)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    const std::string config = "paper.tone=auto,paper.grain=0";
    const PngImage dark = render(harness, scene, "toon+paper+edges", config, kBlack);
    const glm::vec4 grey(0.85f, 0.85f, 0.85f, 1.0f);
    const PngImage light = render(harness, scene, "toon+paper+edges", config, grey);
    save(dark, "auto_dark");
    save(light, "auto_light");
    const Rgb slate{0x15, 0x17, 0x1a};
    EXPECT_TRUE(near(pixel(dark, 2, 2), slate)) << "not the dark page on a black background";
    EXPECT_TRUE(near(pixel(light, 2, 2), kPaper)) << "not paper on a light background";
    // The silhouette's ink, just inside the sphere's outline on its horizontal axis.
    const int rim = int(std::floor(kSize * 0.5f + silhouetteRadius())) - 1;
    auto lightness = [](const Rgb& c) { return (c.r + c.g + c.b) / 3; };
    int darkInk = 0, lightInk = 0;
    for (int x = rim - 2; x <= rim; ++x) {
        darkInk = std::max(darkInk, lightness(pixel(dark, x, kSize / 2)));
        lightInk = std::max(lightInk, 255 - lightness(pixel(light, x, kSize / 2)));
    }
    EXPECT_GT(darkInk, 170) << "no light ink along the outline on the dark page";
    EXPECT_GT(lightInk, 170) << "no dark ink along the outline on paper";
}

// A page colour the user chose is the page whatever the program's background (the blueprint
// preset's blue paper over a black background stayed blue; the dark page replaced it), and
// its own lightness decides the ink. Graphite needs a light sheet: a chain with the pencil
// keeps paper on a black background.
TEST(Paper, AChosenColourOrAPencilKeepsItsPage)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    const PngImage blue = render(harness, scene, "toon+paper",
                                 "paper.tone=auto,paper.grain=0,paper.color=1d4f91", kBlack);
    EXPECT_TRUE(near(pixel(blue, 2, 2), Rgb{0x1d, 0x4f, 0x91})) << "not the chosen blue page";
    const PngImage pencil =
        render(harness, scene, "toon+paper+pencil", "paper.tone=auto,paper.grain=0", kBlack);
    EXPECT_TRUE(near(pixel(pencil, 2, 2), kPaper)) << "the pencil's page is not paper";
}

TEST(Paper, GrainDarkensThePageSubtlyAndRepeatably)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    const PngImage toon = render(harness, scene, "toon", "");
    const PngImage grained =
        render(harness, scene, "toon+paper", "paper.grain=0.3,paper.grain_scene=on");
    const PngImage again =
        render(harness, scene, "toon+paper", "paper.grain=0.3,paper.grain_scene=on");
    save(grained, "toon_paper_grain");
    EXPECT_EQ(grained.rgba, again.rgba); // deterministic, fixed to the screen
    std::set<Rgb> paperShades;
    int darkenedScene = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Rgb before = pixel(toon, x, y), after = pixel(grained, x, y);
            const Rgb base = before == Rgb{0, 0, 0} ? kPaper : before;
            // Multiplied by a factor in [1 - grain, 1].
            EXPECT_LE(after.r, base.r + 1) << x << "," << y;
            EXPECT_GE(after.r, int(base.r * 0.7f) - 1) << x << "," << y;
            EXPECT_GE(after.g, int(base.g * 0.7f) - 1) << x << "," << y;
            if (before == Rgb{0, 0, 0}) {
                paperShades.insert(after);
            } else if (after.r < base.r - 1) {
                ++darkenedScene;
            }
        }
    }
    EXPECT_GT(paperShades.size(), 20u); // a structure, not a flat tint
    EXPECT_GT(darkenedScene, 100);      // the scene is drawn on the paper too
    // By default only the page is grained: the scene keeps its colours exactly.
    const PngImage pageOnly = render(harness, scene, "toon+paper", "paper.grain=0.3");
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const Rgb before = pixel(toon, x, y);
            if (before != Rgb{0, 0, 0}) {
                ASSERT_EQ(pixel(pageOnly, x, y), before) << x << "," << y;
            }
        }
    }
}

TEST(Paper, BackgroundOffLeavesTheProgramsBackground)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    const glm::vec4 blue(0.1f, 0.2f, 0.6f, 1.0f);
    const PngImage toon = render(harness, scene, "toon", "", blue);
    const PngImage off =
        render(harness, scene, "toon+paper", "paper.background=off,paper.grain=0", blue);
    EXPECT_EQ(off.rgba, toon.rgba);
    const PngImage on = render(harness, scene, "toon+paper", "paper.grain=0", blue);
    EXPECT_TRUE(near(pixel(on, 2, 2), kPaper));
}

TEST(Paper, ColourParameterAndChainOrder)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    const PngImage a = render(harness, scene, "toon+paper", "paper.grain=0,paper.color=#336699");
    EXPECT_TRUE(near(pixel(a, 3, 3), Rgb{0x33, 0x66, 0x99}));
    // Named before the shading style, it still runs after it.
    const PngImage b = render(harness, scene, "paper+toon", "paper.grain=0,paper.color=336699");
    EXPECT_EQ(a.rgba, b.rgba);
}

TEST(Paper, KeepsWhatTheProgramDrewWithoutDepth)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    styles::Scene scene = sphereScene(harness); // not drawn (no shading), but not empty
    scene.clearColor = kBlack;
    const glm::vec4 backdrop(0.2f, 0.4f, 0.9f, 1.0f);
    const glm::vec4 nearlyClear(1.0f / 255.0f, 0.0f, 1.0f / 255.0f, 1.0f);
    const glm::vec4 notClear(3.0f / 255.0f, 0.0f, 0.0f, 1.0f);
    const double halfway = 0.5;
    const PngImage image = renderOver(harness, scene, "paper", "paper.grain=0", [&](auto& gl) {
        fillRect(gl, {0, 0, 32, 128}, &backdrop, nullptr);   // 2D image, no depth
        fillRect(gl, {32, 0, 32, 64}, nullptr, &halfway);    // depth, clear colour
        fillRect(gl, {64, 0, 32, 64}, &nearlyClear, nullptr); // within 1.5/255
        fillRect(gl, {96, 0, 32, 64}, &notClear, nullptr);    // beyond it
    });
    save(image, "backdrop");
    // Rows are top first: window y 0..63 is image rows 64..127.
    EXPECT_EQ(pixel(image, 10, 100), (Rgb{51, 102, 230}));
    EXPECT_EQ(pixel(image, 10, 10), (Rgb{51, 102, 230}));
    EXPECT_EQ(pixel(image, 40, 100), (Rgb{0, 0, 0}));
    EXPECT_TRUE(near(pixel(image, 70, 100), kPaper));
    EXPECT_EQ(pixel(image, 110, 100), (Rgb{3, 0, 0}));
    EXPECT_TRUE(near(pixel(image, 70, 10), kPaper));
}

// The page is laid at a frame's first flush; later flushes of the frame find the background
// paper already, and what the program drew between them in its clear colour (a 2D panel with
// no depth) stays its own. After the program clears colour, the background is new and gets
// paper again, as at the next frame.
TEST(Paper, IsLaidOncePerFrameAndAgainAfterTheProgramClearsColour)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    styles::Scene scene = sphereScene(harness); // not drawn (no shading), but not empty
    scene.clearColor = kBlack;
    styles::StyleChain chain;
    startChain(chain, "paper", "paper.grain=0");
    const styles::GlFunctions& gl = harness.gl();
    auto flush = [&](const styles::Scene& s) {
        chain.render(s);
        return readBack(gl);
    };
    gl.Viewport(0, 0, kSize, kSize);
    gl.ClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const PngImage first = flush(scene);
    EXPECT_TRUE(near(pixel(first, 10, 10), kPaper));
    EXPECT_TRUE(near(pixel(first, 100, 100), kPaper));

    // The program's panel in its clear colour over the left half, then another flush.
    fillRect(gl, {0, 0, kSize / 2, kSize}, &kBlack, nullptr);
    const PngImage second = flush(scene);
    EXPECT_EQ(pixel(second, 10, 10), (Rgb{0, 0, 0}));
    EXPECT_TRUE(near(pixel(second, 100, 100), kPaper));

    // A colour clear (here of the right half): the background is new everywhere it is the
    // clear colour at the far plane.
    fillRect(gl, {kSize / 2, 0, kSize / 2, kSize}, &kBlack, nullptr);
    styles::Scene cleared = scene;
    cleared.colourClears = scene.colourClears + 1;
    const PngImage third = flush(cleared);
    EXPECT_TRUE(near(pixel(third, 10, 10), kPaper));
    EXPECT_TRUE(near(pixel(third, 100, 100), kPaper));

    // The next frame starts a page of its own.
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    styles::Scene next = scene;
    next.frame = scene.frame + 1;
    const PngImage fourth = flush(next);
    EXPECT_TRUE(near(pixel(fourth, 10, 10), kPaper));
    chain.shutdown();
}

namespace {

// The program's own fixed-function drawing, as a glow (GlowInk): an orange quad over both
// halves of a picture dark on the left and page-white on the right, in `fogMode` (0: no fog;
// else the program's black fog, all of it at the quad's depth). `lit`: its orange is the
// program's lighting of an orange material set between glBegin and glEnd (blue before it).
PngImage glowOverDarkAndPage(StyleHarness& harness, GLenum fogMode, bool lit = false)
{
    styles::StyleChain chain;
    startChain(chain, "toon+paper", "paper.grain=0");
    EXPECT_TRUE(chain.inksGlows());
    auto getProc = [](const char* name) {
        return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
    };
    const styles::GlFunctions& gl = harness.gl();
    gl.Viewport(0, 0, kSize, kSize);
    const glm::vec4 dark(0.1f, 0.1f, 0.1f, 1.0f), page(0.95f, 0.95f, 0.95f, 1.0f);
    fillRect(gl, {0, 0, kSize / 2, kSize}, &dark, nullptr);
    fillRect(gl, {kSize / 2, 0, kSize / 2, kSize}, &page, nullptr);

    using Begin = void (*)(GLenum);
    using Vertex2f = void (*)(GLfloat, GLfloat);
    using Color3f = void (*)(GLfloat, GLfloat, GLfloat);
    using NoArgs = void (*)();
    using Fogf = void (*)(GLenum, GLfloat);
    using Parameters = void (*)(GLenum, GLenum, const GLfloat*);
    auto begin = reinterpret_cast<Begin>(getProc("glBegin"));
    auto vertex = reinterpret_cast<Vertex2f>(getProc("glVertex2f"));
    auto colour = reinterpret_cast<Color3f>(getProc("glColor3f"));
    auto end = reinterpret_cast<NoArgs>(getProc("glEnd"));
    auto fog = reinterpret_cast<Fogf>(getProc("glFogf"));
    auto material = reinterpret_cast<Parameters>(getProc("glMaterialfv"));
    auto light = reinterpret_cast<Parameters>(getProc("glLightfv"));
    const GLfloat white[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
    const GLfloat orange[4] = {1.0f, 0.5f, 0.0f, 1.0f}, blue[4] = {0.0f, 0.0f, 1.0f, 1.0f};
    if (lit) {
        // Ambient light only: the colour is the material's, whatever the normal.
        light(GL_LIGHT0, GL_AMBIENT, white);
        light(GL_LIGHT0, GL_DIFFUSE, black);
        light(GL_LIGHT0, GL_SPECULAR, black);
        material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
        gl.Enable(GL_LIGHTING);
        gl.Enable(GL_LIGHT0);
    }
    gl.Disable(GL_DEPTH_TEST);
    if (fogMode) {
        // Linear, ending before the quad (eye depth 0): the fog colour (black) everywhere.
        fog(GL_FOG_MODE, float(fogMode));
        fog(GL_FOG_START, -2.0f);
        fog(GL_FOG_END, -1.0f);
        gl.Enable(GL_FOG);
    }
    chain.glowBegin(false, false, fogMode);
    colour(1.0f, 0.5f, 0.0f);
    begin(GL_QUADS);
    if (lit) material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, orange);
    vertex(-0.9f, -0.5f);
    vertex(0.9f, -0.5f);
    vertex(0.9f, 0.5f);
    vertex(-0.9f, 0.5f);
    end();
    chain.glowEnd();
    gl.Disable(GL_FOG);
    gl.Disable(GL_LIGHTING);
    gl.Disable(GL_BLEND);
    const PngImage image = readBack(gl);
    chain.shutdown();
    return image;
}

} // namespace

// An additive glow (an orange flame, GL_ONE onto GL_ONE) around which the chain's glow ink is
// on: over the light page it is orange ink, not white; over a dark surface of the scene it
// still lights the surface up, as the program's addition would.
class GlowInk : public ::testing::TestWithParam<bool> {};

TEST_P(GlowInk, IsInkOnThePageAndLightOnDarkSurfaces)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const PngImage image = glowOverDarkAndPage(harness, 0, GetParam());
    save(image, GetParam() ? "glow_lit" : "glow");
    // Left, over the dark surface: lit up orange (ink alone would leave it near black).
    const Rgb onDark = pixel(image, kSize / 4, kSize / 2);
    EXPECT_GT(onDark.r, 200) << onDark.r << " " << onDark.g << " " << onDark.b;
    EXPECT_GT(onDark.r, onDark.b + 150);
    // Right, over the page: orange ink (the addition would give near white).
    const Rgb onPage = pixel(image, 3 * kSize / 4, kSize / 2);
    EXPECT_GT(onPage.r, 200) << onPage.r << " " << onPage.g << " " << onPage.b;
    EXPECT_LT(onPage.b, 60) << onPage.r << " " << onPage.g << " " << onPage.b;
    // Outside the quad both halves are as they were.
    EXPECT_EQ(pixel(image, kSize / 4, 5), (Rgb{26, 26, 26}));
}

// Lit: the colour is the program's lighting of its materials, also of those set between
// glBegin and glEnd (gibson's floor took the material before its batch: the last glyph's red).
INSTANTIATE_TEST_SUITE_P(Paper, GlowInk, ::testing::Bool(), [](const auto& p) {
    return std::string(p.param ? "Lit" : "Coloured");
});

// A glow in the program's black fog adds nothing natively (gibson's glowing text far down
// its floor): no ink on the page either, and nothing on the dark surface. The ink ignored the
// fog and turned gibson's floor red with the ink of its far-off red glyphs.
TEST(Paper, GlowsFadeIntoTheProgramsFog)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const PngImage image = glowOverDarkAndPage(harness, GL_LINEAR);
    EXPECT_EQ(pixel(image, kSize / 4, kSize / 2), (Rgb{26, 26, 26})) << "lit through the fog";
    EXPECT_EQ(pixel(image, 3 * kSize / 4, kSize / 2), (Rgb{242, 242, 242}))
        << "inked through the fog";
}

TEST(Paper, StaysInsideTheViewport)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    styles::Scene scene = sphereScene(harness);
    scene.viewport = {20, 30, 60, 50};
    const PngImage image =
        renderOver(harness, scene, "paper", "paper.grain=0.5,paper.grain_scene=on", [](auto&) {});
    save(image, "viewport");
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const int wy = kSize - 1 - y;
            const bool inside = x >= 20 && x < 80 && wy >= 30 && wy < 80;
            const Rgb p = pixel(image, x, y);
            if (inside) {
                EXPECT_GE(p.r, int(kPaper.r * 0.5f) - 1) << x << "," << y;
            } else {
                EXPECT_EQ(p, (Rgb{0, 0, 0})) << x << "," << y;
            }
        }
    }
}

TEST(Paper, EmptySceneChangesNothing)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    styles::Scene scene = sphereScene(harness);
    scene.objects.clear();
    const glm::vec4 grey(0.25f, 0.5f, 0.75f, 1.0f);
    const PngImage image =
        render(harness, scene, "toon+paper", "paper.grain=1,paper.grain_scene=on", grey);
    for (int y = 0; y < kSize; y += 7) {
        for (int x = 0; x < kSize; x += 7) EXPECT_EQ(pixel(image, x, y), (Rgb{64, 128, 191}));
    }
}

TEST(Paper, InkIsDrawnOverThePaper)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    // A coloured ink and a strong grain: ink drawn before the paper would be grained.
    const std::string config =
        "paper.grain=0.8,paper.grain_scene=on,edges.ink_red=0.2,edges.ink_green=0.4,"
        "edges.ink_blue=1,"
        "edges.silhouette_width=3";
    const PngImage image = render(harness, scene, "toon+edges+paper", config);
    const PngImage named = render(harness, scene, "toon+paper+edges", config);
    save(image, "toon_paper_edges");
    EXPECT_EQ(image.rgba, named.rgba);
    const Rgb ink{51, 102, 255};
    const float r = silhouetteRadius();
    int onRim = 0, rim = 0, paperOutside = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const float d = fromCentre(x, y);
            const Rgb p = pixel(image, x, y);
            if (std::abs(d - r) < 0.5f) {
                ++rim;
                if (near(p, ink)) ++onRim;
            }
            // Grained paper (factor >= 0.2 at grain 0.8), warm, never the black clear colour.
            if (d > r + 4.0f && p.r >= int(kPaper.r * 0.2f) && p.r >= p.b) ++paperOutside;
        }
    }
    EXPECT_GT(rim, 100);
    EXPECT_GE(onRim, rim * 9 / 10);
    EXPECT_GT(paperOutside, kSize * kSize / 3);
}

TEST(Paper, TexturePngTilesTheBackground)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    // Two-colour stripes, 4 texels each: nearest-looking at scale 1 away from their edges.
    PngImage tile;
    tile.width = tile.height = 8;
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            const bool a = x < 4;
            tile.rgba.insert(tile.rgba.end(), {uint8_t(a ? 200 : 90), uint8_t(a ? 180 : 60),
                                               uint8_t(a ? 150 : 30), 255});
        }
    }
    // A directory of this run's own: a PNG the style reads back must be ours.
    const std::string tilePath = freshDir("paper_tile") + "/stripes_tile.png";
    std::string error;
    ASSERT_TRUE(tile.write(tilePath, error)) << error;
    const PngImage image = render(harness, scene, "toon+paper",
                                  "paper.grain=0,paper.texture_png=" + tilePath);
    save(image, "texture_png");
    std::set<Rgb> colours;
    for (int x = 0; x < 20; ++x) colours.insert(pixel(image, x, 2));
    EXPECT_TRUE(colours.count(Rgb{200, 180, 150}));
    EXPECT_TRUE(colours.count(Rgb{90, 60, 30}));
    EXPECT_FALSE(colours.count(kPaper));
    // A missing file falls back to the flat paper (and says so once).
    const PngImage missing = render(harness, scene, "toon+paper",
                                    "paper.grain=0,paper.texture_png=/nonexistent/paper.png");
    EXPECT_TRUE(near(pixel(missing, 2, 2), kPaper));
}

TEST(Paper, ThePageIsOpaque)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::Scene scene = sphereScene(harness);
    // glxgears clears alpha to 0; its background still becomes a page one can see.
    const PngImage image =
        render(harness, scene, "toon+paper", "", glm::vec4(0.0f, 0.0f, 0.0f, 0.0f));
    EXPECT_EQ(image.rgba[3], 255);
    EXPECT_EQ(image.rgba[(size_t(kSize) * kSize - 1) * 4 + 3], 255);
}
