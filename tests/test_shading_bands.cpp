// Toon bands that follow the program's own lighting (toon.bands=program): objects keep the
// lightness order GL gave them, and the highlight is where the material shines.

#include "tests/support/StyleHarness.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

using namespace nprgl;
using namespace nprgl::test;

namespace {

constexpr int kSize = 128;

glm::mat4 perspective() { return glm::perspective(glm::radians(40.0f), 1.0f, 1.0f, 20.0f); }

float luminanceAt(const PngImage& image, int x, int y)
{
    const uint8_t* p = &image.rgba[(size_t(y) * kSize + x) * 4];
    return (0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]) / 255.0f;
}

// The mean luminance of the 12 x 12 patch centred at (x, y).
float patch(const PngImage& image, int x, int y)
{
    float sum = 0.0f;
    for (int j = y - 6; j < y + 6; ++j) {
        for (int i = x - 6; i < x + 6; ++i) sum += luminanceAt(image, i, j);
    }
    return sum / 144.0f;
}

// A 1.6 x 1.6 quad facing the eye, 6 in front of it, centred at x.
reconstruct::Batch facingQuad(float x, const glm::vec4& colour)
{
    reconstruct::Batch quad;
    quad.mode = GL_TRIANGLES;
    quad.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, -6.0f));
    quad.materialId = x < 0.0f ? 1 : 2;
    const glm::vec2 corners[6] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
    for (const glm::vec2& c : corners) {
        reconstruct::Vertex v{};
        v.position = {0.8f * c.x, 0.8f * c.y, 0.0f};
        v.normal = {0.0f, 0.0f, 1.0f};
        v.hasNormal = true;
        v.color = colour;
        quad.vertices.push_back(v);
    }
    return quad;
}

// One far light of the program's, from `towards` (eye space), with GL's default ambient
// terms against the lit colour (StateTracker::litBy, FixedLighting's shares).
void litBy(styles::SceneObject& object, glm::vec3 towards)
{
    styles::SceneLights& lights = object.lights;
    lights.count = 1;
    lights.lights[0].position = glm::vec4(glm::normalize(towards), 0.0f);
    lights.lights[0].weight = 1.0f;
    lights.ambientShare = 0.05f;
    lights.diffuseShare = 1.0f;
}

// Two facing quads, the left in `left` lit from `leftLight`, the right in `right` lit from
// `rightLight` (eye space), drawn in toon with `config`: the mean luminance of each one's
// centre.
std::pair<float, float> twoLitQuads(StyleHarness& harness, const glm::vec4& left,
                                    glm::vec3 leftLight, const glm::vec4& right,
                                    glm::vec3 rightLight, const std::string& config)
{
    auto scene = harness.makeScene({facingQuad(-1.0f, left), facingQuad(1.0f, right)},
                                   perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(scene.objects.size(), 2u);
    if (scene.objects.size() != 2) return {0.0f, 0.0f};
    litBy(scene.objects[0], leftLight);
    litBy(scene.objects[1], rightLight);
    PngImage image;
    std::string error;
    EXPECT_TRUE(harness.render(scene, "toon", config, image, error)) << error;
    return {patch(image, kSize / 2 - 32, kSize / 2), patch(image, kSize / 2 + 32, kSize / 2)};
}

} // namespace

// Two objects the program lit: a dark grey one head-on (GL: 0.35 of white) and a light grey
// one by a light at a grazing 81 degrees (GL: 0.8 x (0.05 + 0.15) = 0.16). GL shows the dark
// grey one lighter. The thesis's bands (L.n above t_d = 0: the full colour) drew the grazing
// one in its full 0.8, far the lighter: the order between objects reversed (cubestorm's cube
// faces turned from the light, glknots, moebiusgears). By GL's own light it takes the shadow
// band and stays the darker.
TEST(ToonBands, AnObjectGlShowsDarkerStaysDarker)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const float grazing = std::acos(0.15f);
    auto sides = [&](const std::string& config) {
        return twoLitQuads(harness, glm::vec4(0.35f, 0.35f, 0.35f, 1.0f),
                           glm::vec3(0.0f, 0.0f, 1.0f), glm::vec4(0.8f, 0.8f, 0.8f, 1.0f),
                           glm::vec3(std::sin(grazing), 0.0f, std::cos(grazing)), config);
    };
    const auto [headOn, grazed] = sides("toon.band=nearest");
    EXPECT_GT(headOn, grazed + 0.05f) << "the object GL shows darker came out the lighter";
    // The thesis's bands, still a choice, reverse them: the test tells the two apart.
    const auto [thesisHeadOn, thesisGrazed] = sides("toon.band=nearest,toon.bands=thesis");
    EXPECT_GT(thesisGrazed, thesisHeadOn);
}

// The highlight band is GL's highlight: none on a material without specular (a black one
// stays black: sonar's black disc was drawn grey by white mixed into its highlight), and where
// GL's own peaks on a shiny one, in the material's colour plus the shine.
TEST(ToonBands, TheHighlightIsWhereTheMaterialShines)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -6.0f));
    const glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.5f, 1.0f));
    auto brightest = [&](const glm::vec4& colour, glm::vec3 shine, const std::string& config) {
        auto scene = harness.makeScene({sphereBatch(mv, 1.5f, 48, 24, colour)}, perspective(),
                                       light);
        litBy(scene.objects[0], light);
        scene.objects[0].lights.shine = shine;
        scene.objects[0].lights.shininess = 20.0f;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", config, image, error)) << error;
        // Over the sphere (some 44 pixels across on each side), away from its rim.
        float top = 0.0f;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                const int dx = x - kSize / 2, dy = y - kSize / 2;
                if (dx * dx + dy * dy < 36 * 36) top = std::max(top, luminanceAt(image, x, y));
            }
        }
        return top;
    };
    const glm::vec4 black(0.0f, 0.0f, 0.0f, 1.0f);
    const glm::vec4 red(0.6f, 0.1f, 0.1f, 1.0f);
    EXPECT_LT(brightest(black, glm::vec3(0.0f), ""), 0.02f) << "a black matte sphere lightened";
    EXPECT_GT(brightest(black, glm::vec3(0.0f), "toon.bands=thesis"), 0.3f)
        << "the thesis's highlight no longer lightens: the test cannot fail";
    const float matte = brightest(red, glm::vec3(0.0f), "");
    const float shiny = brightest(red, glm::vec3(0.5f), "");
    EXPECT_NEAR(matte, 0.299f * 0.6f + 0.587f * 0.1f + 0.114f * 0.1f, 0.08f)
        << "a matte red sphere is brighter than its colour";
    EXPECT_GT(shiny, matte + 0.2f) << "no highlight where the material shines";
}

// Two-sided lighting turns the normal on back faces only, back by the window winding as GL
// tells them. A program that keeps its view in the projection matrix (gflux: glFrustum, then
// glTranslate on GL_PROJECTION) has its surfaces at positive eye-space z; judged by the
// normal against the eye-space position, its front faces counted as back faces, were lit
// from behind and fell into the shadow band (gflux's sheet, lit evenly natively, came out half
// dark).
TEST(ToonBands, TwoSidedLightingTurnsOnlyBackFaces)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 projection =
        perspective() * glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -7.0f));
    reconstruct::Batch quad = facingQuad(0.0f, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f));
    quad.modelview = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1.0f));
    auto centre = [&](bool twoSide) {
        auto scene = harness.makeScene({quad}, projection, glm::vec3(0.0f, 0.0f, 1.0f));
        litBy(scene.objects[0], glm::vec3(0.0f, 0.0f, 1.0f));
        scene.objects[0].lights.twoSide = twoSide;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
        return patch(image, kSize / 2, kSize / 2);
    };
    const float oneSided = centre(false);
    EXPECT_GT(oneSided, 0.5f) << "a quad facing its light is not in the lit band: no test";
    EXPECT_NEAR(centre(true), oneSided, 0.02f) << "two-sided lighting turned a front face";
}

// A light whose attenuation brightens it near a surface (constant attenuation 0.1: ten times
// its colour, antmaze's lights) lights a face it grazes fully, as GL clamps the sum: the
// styles' L·n, capped at one light head-on, put that face in the shadow band.
TEST(ToonBands, ALightAttenuatedBelowOneLightsAsGlDoes)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto centre = [&](float constant) {
        auto scene = harness.makeScene({facingQuad(0.0f, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f))},
                                       perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
        litBy(scene.objects[0], glm::vec3(0.0f, 0.0f, 1.0f));
        // One unit from the quad's centre, at a grazing 81 degrees: L.n 0.15.
        const float grazing = std::acos(0.15f);
        styles::SceneLights::Light& light = scene.objects[0].lights.lights[0];
        light.position = glm::vec4(std::sin(grazing), 0.0f, -6.0f + std::cos(grazing), 1.0f);
        light.falloff = glm::vec4(constant, 0.0f, 0.0f, 0.0f);
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
        return patch(image, kSize / 2, kSize / 2);
    };
    EXPECT_LT(centre(1.0f), 0.45f) << "grazed by a plain light, not in the shadow band: no test";
    EXPECT_GT(centre(0.1f), 0.7f) << "a light ten times as bright there left the face in shadow";
}

// The shadow band is in the hue of GL's own unlit colour (SceneLights::shadowTint), not the lit
// colour darkened: coloured lights over a white ambient light (extrusion's yellow and cyan)
// tint the lit side, and GL's shadowed side keeps the material's own hue. Where the style
// lifts a dark shadow to its floor, the lift is in the lit colour's hue.
TEST(ToonBands, TheShadowBandIsInTheHueOfGlsUnlitColour)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto blueOverRed = [&](glm::vec3 tint, float ambientShare) {
        auto scene = harness.makeScene({facingQuad(0.0f, glm::vec4(0.8f, 0.8f, 0.6f, 1.0f))},
                                       perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
        litBy(scene.objects[0], glm::vec3(0.0f, 0.0f, -1.0f)); // from behind: all shadow
        scene.objects[0].lights.ambientShare = ambientShare;
        scene.objects[0].lights.shadowTint = tint;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
        const uint8_t* p = &image.rgba[(size_t(kSize / 2) * kSize + kSize / 2) * 4];
        EXPECT_GT(p[0], 10) << "no shadow band drawn";
        return float(p[2]) / std::max(float(p[0]), 1.0f);
    };
    EXPECT_NEAR(blueOverRed(glm::vec3(1.0f), 0.4f), 0.75f, 0.05f) << "the base's own hue";
    const float own = blueOverRed(glm::vec3(0.8f, 0.8f, 2.0f), 0.4f);
    EXPECT_NEAR(own, 0.75f * 2.5f, 0.15f) << "GL's unlit hue";
    const float lifted = blueOverRed(glm::vec3(0.8f, 0.8f, 2.0f), 0.1f);
    EXPECT_LT(lifted, own - 0.3f) << "the lift to the floor is not in the lit colour's hue";
    EXPECT_GT(lifted, 0.75f + 0.1f);
}

// GL lights by the program's normal as the modelview moved it, unit only under GL_NORMALIZE
// (GL_RESCALE_NORMAL takes the modelview's scale out). A program that scales its objects by 3
// with neither shows them a third as lit (boxed's balls): the styles lit them by the unit
// normal and drew them in the full colour, far lighter than GL, and lighter than objects GL
// shows lighter.
TEST(ToonBands, AScaledNormalLightsAsGlTakesIt)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    reconstruct::Batch quad = facingQuad(0.0f, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f));
    quad.modelview = glm::scale(quad.modelview, glm::vec3(3.0f));
    for (reconstruct::Vertex& v : quad.vertices) v.position /= 3.0f; // the same quad on screen
    auto centre = [&](GLenum normals) {
        auto scene = harness.makeScene({quad}, perspective(), glm::vec3(0.0f, 0.0f, 1.0f));
        litBy(scene.objects[0], glm::vec3(0.0f, 0.0f, 1.0f)); // head-on
        scene.objects[0].normals = normals;
        PngImage image;
        std::string error;
        EXPECT_TRUE(harness.render(scene, "toon", "toon.band=nearest", image, error)) << error;
        return patch(image, kSize / 2, kSize / 2);
    };
    // GL: 0.05 + 0.95 / 3 of the colour, nearer the shadow band's lightness than the full's.
    EXPECT_LT(centre(0), 0.45f) << "normals a third long lit the quad fully";
    EXPECT_GT(centre(GL_NORMALIZE), 0.7f) << "GL_NORMALIZE: not lit head-on";
    EXPECT_GT(centre(GL_RESCALE_NORMAL), 0.7f) << "GL_RESCALE_NORMAL: the scale not taken out";
}

// Two materials GL shows clearly apart keep their order through the bands. A light grey face
// GL lights at 0.67 of its colour (0.53: the darker on screen) and a darker grey one it lights
// fully (0.70). With the two bands alone, 0.67 is nearer the full colour's lightness than the
// shadow's and the light grey face took its full 0.8: the lighter of the two, reversed
// (cubestorm's beams, nakagin's walls, moebiusgears' gears). The half band, midway in
// lightness, is within a quarter of the bands' distance of GL's light, and keeps the order.
TEST(ToonBands, TwoMaterialsGlShowsApartKeepTheirOrder)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const float slanted = std::acos(0.65f); // GL: 0.05 + 0.95 x 0.65 = 0.67 of the colour
    auto sides = [&](const std::string& config) {
        return twoLitQuads(harness, glm::vec4(0.8f, 0.8f, 0.8f, 1.0f),
                           glm::vec3(std::sin(slanted), 0.0f, std::cos(slanted)),
                           glm::vec4(0.7f, 0.7f, 0.7f, 1.0f), glm::vec3(0.0f, 0.0f, 1.0f), config);
    };
    const auto [slantedLight, headOnDark] = sides("toon.band=nearest");
    EXPECT_GT(headOnDark, slantedLight + 0.1f) << "the face GL shows darker came out lighter";
    EXPECT_NEAR(headOnDark, 0.7f, 0.03f) << "a face GL lights fully is not in its full colour";
    // Without the half band the two trade places: the test tells the two apart.
    const auto [twoBandsLight, twoBandsDark] = sides("toon.band=nearest,toon.half_band=off");
    EXPECT_GT(twoBandsLight, twoBandsDark);
}
