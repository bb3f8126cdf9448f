// The outline styles (thesis chapter 4: wireframe, per-pixel, image-space) rendered
// in-process through the style harness and checked against analytically known outlines.

#include "tests/support/StyleHarness.h"

#include "styles/StyleChain.h"
#include "styles/StyleSettings.h"
#include "styles/outlines/FeatureLines.h"
#include "styles/outlines/MotionHistory.h"
#include "styles/outlines/TileUnion.h"

#include <GL/osmesa.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

using namespace nprgl;
using namespace nprgl::test;

namespace {

constexpr int kSize = 256;
constexpr float kFov = 40.0f;
constexpr float kDistance = 6.0f;
constexpr float kRadius = 1.5f;

glm::mat4 perspective() { return glm::perspective(glm::radians(kFov), 1.0f, 1.0f, 20.0f); }

glm::mat4 sphereModelview()
{
    return glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
}

// The outline of a sphere centred on the optical axis: a circle of angular radius
// asin(R/d) around the image centre, in pixels for a viewport of `size`.
float silhouetteRadius(int size)
{
    const float half = std::tan(std::asin(kRadius / kDistance));
    return half / std::tan(glm::radians(kFov) * 0.5f) * float(size) * 0.5f;
}

glm::mat4 boxModelview()
{
    glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
    mv = glm::rotate(mv, glm::radians(30.0f), glm::vec3(1, 0, 0));
    return glm::rotate(mv, glm::radians(40.0f), glm::vec3(0, 1, 0));
}

const glm::vec4 kRed(0.85f, 0.25f, 0.2f, 1.0f);
const glm::vec4 kPale(0.9f, 0.85f, 0.6f, 1.0f);

// Ink: every channel below `below` (solid outlines are near black; a pencil mark is lighter).
bool isInk(const PngImage& image, int x, int y, int below = 90)
{
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return false;
    const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
    return p[0] < below && p[1] < below && p[2] < below;
}

// Ink anywhere within `radius` pixels of the GL window point (x, y up).
bool inkNear(const PngImage& image, glm::vec2 window, float radius, int below = 90)
{
    const int r = int(std::ceil(radius));
    const int cx = int(std::floor(window.x)), cy = image.height - 1 - int(std::floor(window.y));
    for (int dy = -r; dy <= r; ++dy) {
        for (int dx = -r; dx <= r; ++dx) {
            if (dx * dx + dy * dy <= radius * radius && isInk(image, cx + dx, cy + dy, below)) {
                return true;
            }
        }
    }
    return false;
}

// Distance of a pixel's centre from the window point `centre` (GL window coordinates).
float distanceFrom(const PngImage& image, int x, int y, glm::vec2 centre)
{
    return glm::length(glm::vec2(x + 0.5f, image.height - y - 0.5f) - centre);
}

struct RingStats {
    float rimCoverage = 0.0f; // fraction of directions with ink within the rim band
    int insideInk = 0;        // ink pixels deeper than `inner` x radius
    int inside = 0;
    int outsideInk = 0;       // ink pixels further than radius + `outer`
};

RingStats ring(const PngImage& image, glm::vec2 centre, float radius, float band = 3.0f,
               float inner = 0.75f, float outer = 6.0f, int below = 90)
{
    RingStats s;
    int hits = 0;
    constexpr int kDirections = 360;
    for (int a = 0; a < kDirections; ++a) {
        const float t = glm::radians(float(a));
        const glm::vec2 dir(std::cos(t), std::sin(t));
        bool hit = false;
        for (float r = radius - band; r <= radius + band && !hit; r += 0.5f) {
            hit = inkNear(image, centre + dir * r, 0.5f, below);
        }
        hits += hit;
    }
    s.rimCoverage = float(hits) / kDirections;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float d = distanceFrom(image, x, y, centre);
            if (d < inner * radius) {
                ++s.inside;
                s.insideInk += isInk(image, x, y, below);
            } else if (d > radius + outer) {
                s.outsideInk += isInk(image, x, y, below);
            }
        }
    }
    return s;
}

int countInk(const PngImage& image, int below = 90)
{
    int n = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) n += isInk(image, x, y, below);
    }
    return n;
}

PngImage render(StyleHarness& harness, const styles::Scene& scene, const std::string& chain,
                const std::string& config, const std::string& name)
{
    PngImage image;
    std::string error;
    EXPECT_TRUE(harness.render(scene, chain, config, image, error)) << chain << ": " << error;
    std::filesystem::create_directories("/tmp/outlines");
    image.write("/tmp/outlines/" + name + ".png", error);
    return image;
}

const glm::vec2 kCentre(kSize * 0.5f, kSize * 0.5f);

// The centre's sphere drawn mirrored (glScalef(-1, 1, 1)): it winds clockwise on screen.
styles::Scene mirroredSphere(StyleHarness& harness)
{
    const glm::mat4 mirrored = glm::scale(sphereModelview(), glm::vec3(-1.0f, 1.0f, 1.0f));
    return harness.makeScene({sphereBatch(mirrored, kRadius, 48, 24, kRed)}, perspective());
}

// A sphere at the centre outlined on its rim alone in `chain`: ink all round its silhouette,
// none deeper inside than `inner` x its radius. Returns the figures for further checks.
RingStats expectRimOnly(StyleHarness& harness, const styles::Scene& scene,
                        const std::string& chain, const std::string& name, float inner)
{
    const PngImage image = render(harness, scene, chain, "", name);
    const RingStats s = ring(image, kCentre, silhouetteRadius(kSize), 3.0f, inner);
    EXPECT_GE(s.inside, 10000) << name << ": no sphere, no test";
    EXPECT_GE(s.rimCoverage, 0.99f) << name;
    EXPECT_EQ(s.insideInk, 0) << name << ": ink inside the outline";
    return s;
}

class SphereOutline : public ::testing::TestWithParam<std::string> {};

TEST_P(SphereOutline, InkOnTheAnalyticSilhouetteOnly)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    PngImage image = render(harness, scene, GetParam(), "", "sphere_" + GetParam());
    const RingStats s = ring(image, kCentre, silhouetteRadius(kSize));
    EXPECT_GE(s.rimCoverage, 0.99f) << "gaps in the outline";
    EXPECT_LE(s.insideInk, s.inside / 500) << "ink inside the sphere";
    EXPECT_EQ(s.outsideInk, 0) << "ink far outside the sphere";
}

INSTANTIATE_TEST_SUITE_P(Styles, SphereOutline,
                         ::testing::Values("wireframe", "perpixel", "edges"));

// Under an orthographic projection the sphere's outline is a circle of its own radius.
TEST_P(SphereOutline, Orthographic)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 ortho = glm::ortho(-3.0f, 3.0f, -3.0f, 3.0f, 1.0f, 20.0f);
    auto scene =
        harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)}, ortho);
    PngImage image = render(harness, scene, "toon+" + GetParam(), "toon.band=nearest",
                            "ortho_" + GetParam());
    const RingStats s = ring(image, kCentre, kRadius / 3.0f * kSize * 0.5f);
    EXPECT_GE(s.rimCoverage, 0.99f);
    EXPECT_EQ(s.insideInk, 0);
    EXPECT_EQ(s.outsideInk, 0);
}

// Composed with toon shading: the interior keeps toon's band colours, the rim is inked.
class ToonOutline : public ::testing::TestWithParam<std::string> {};

TEST_P(ToonOutline, BandsInsideInkOnTheRim)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    const std::string chain = "toon+" + GetParam();
    // Hard band boundaries: exactly the band colours inside.
    PngImage image = render(harness, scene, chain, "toon.band=nearest", "toon_" + GetParam());
    const float radius = silhouetteRadius(kSize);
    const RingStats s = ring(image, kCentre, radius);
    EXPECT_GE(s.rimCoverage, 0.99f);
    EXPECT_EQ(s.insideInk, 0);
    std::set<uint32_t> colours;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (distanceFrom(image, x, y, kCentre) > 0.75f * radius) continue;
            const uint8_t* p = &image.rgba[(size_t(y) * kSize + x) * 4];
            colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
        }
    }
    EXPECT_GE(colours.size(), 2u);
    EXPECT_LE(colours.size(), 3u);
}

INSTANTIATE_TEST_SUITE_P(Styles, ToonOutline,
                         ::testing::Values("wireframe", "perpixel", "edges"));

// The box's visible edges (those with a front-facing face) are creases or silhouettes: ink
// along all of them, none in the middle of its faces.
class BoxOutline : public ::testing::TestWithParam<std::string> {};

TEST_P(BoxOutline, InkAlongTheProjectedEdges)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 mv = boxModelview();
    auto scene = harness.makeScene({boxBatch(mv, glm::vec3(1.0f), kPale)}, perspective());
    PngImage image = render(harness, scene, "toon+" + GetParam(), "", "box_" + GetParam());
    const glm::vec4 viewport(0, 0, kSize, kSize);
    auto project = [&](glm::vec3 p) {
        return glm::vec2(glm::project(p, mv, perspective(), viewport));
    };
    auto frontFacing = [&](glm::vec3 n) {
        const glm::vec3 centre = glm::vec3(mv * glm::vec4(n, 1.0f));
        const glm::vec3 normal = glm::mat3(mv) * n;
        return glm::dot(normal, -centre) > 0.0f;
    };
    int samples = 0, inked = 0, faces = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            if (!frontFacing(n)) continue;
            ++faces;
            EXPECT_FALSE(inkNear(image, project(n), 6.0f)) << "ink on a face, axis " << axis;
            // The face's four edges.
            const int u = (axis + 1) % 3, w = (axis + 2) % 3;
            for (int e = 0; e < 4; ++e) {
                glm::vec3 a = n, b = n;
                const int along = e < 2 ? u : w, across = e < 2 ? w : u;
                const float side = (e % 2) ? 1.0f : -1.0f;
                a[along] = -1.0f;
                b[along] = 1.0f;
                a[across] = b[across] = side;
                // About one sample per pixel: a dotted line fails.
                for (float t = 0.1f; t <= 0.9f; t += 0.01f) {
                    ++samples;
                    inked += inkNear(image, project(glm::mix(a, b, t)), 1.0f);
                }
            }
        }
    }
    EXPECT_EQ(faces, 3);
    EXPECT_GE(float(inked), 0.97f * float(samples)) << inked << " of " << samples;
}

INSTANTIATE_TEST_SUITE_P(Styles, BoxOutline, ::testing::Values("wireframe", "edges"));

// The width parameter widens the lines.
struct WidthCase {
    std::string chain, thin, wide;
};

void PrintTo(const WidthCase& c, std::ostream* os) { *os << c.chain; }

class OutlineWidth : public ::testing::TestWithParam<WidthCase> {};

TEST_P(OutlineWidth, GrowsWithTheParameter)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    const WidthCase& c = GetParam();
    const int thin = countInk(render(harness, scene, c.chain, c.thin, "thin_" + c.chain));
    const int wide = countInk(render(harness, scene, c.chain, c.wide, "wide_" + c.chain));
    EXPECT_GT(thin, 200);
    EXPECT_GT(float(wide), 2.0f * float(thin)) << thin << " vs " << wide;
}

INSTANTIATE_TEST_SUITE_P(
    Styles, OutlineWidth,
    ::testing::Values(
        WidthCase{"wireframe", "wireframe.silhouette_width=2", "wireframe.silhouette_width=8"},
        WidthCase{"perpixel", "perpixel.epsilon=0.15", "perpixel.epsilon=0.4"},
        WidthCase{"edges", "edges.silhouette_width=2", "edges.silhouette_width=6"}),
    [](const auto& p) { return p.param.chain; });

// A box behind the sphere: its edges must not show through the sphere, while the sphere's
// outline stays complete over the box.
class Occlusion : public ::testing::TestWithParam<std::string> {};

TEST_P(Occlusion, HiddenEdgesStayHidden)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    glm::mat4 box = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.2f, -11.0f));
    box = glm::rotate(box, glm::radians(35.0f), glm::vec3(1, 1, 0));
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed),
                                    boxBatch(box, glm::vec3(2.0f), kPale, 2)},
                                   perspective());
    PngImage image = render(harness, scene, "toon+" + GetParam(), "", "occlusion_" + GetParam());
    const RingStats s = ring(image, kCentre, silhouetteRadius(kSize), 3.0f, 0.85f, 1e6f);
    EXPECT_GE(s.rimCoverage, 0.99f);
    EXPECT_EQ(s.insideInk, 0);
}

INSTANTIATE_TEST_SUITE_P(Styles, Occlusion, ::testing::Values("wireframe", "perpixel", "edges"));

// The program's fog covers the ink as it covers the surface: a sphere beyond the fog's end is
// the fog's colour, and so is its outline (gl-117's and trigger-rally's fogged horizons were
// drawn as hard black lines across the sky); in a fog that ends far behind it, it is inked.
TEST(Edges, InkFadesIntoTheProgramsFog)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto inked = [&](float fogEnd, const std::string& name) {
        auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                       perspective());
        for (auto& o : scene.objects) o.fog = {GL_LINEAR, 0.0f, fogEnd, 1.0f, glm::vec3(0.8f)};
        return countInk(render(harness, scene, "toon+edges", "", name));
    };
    EXPECT_EQ(inked(0.5f * kDistance, "edges_fogged"), 0);
    EXPECT_GT(inked(100.0f * kDistance, "edges_fog_far"), 500);
}

// An object small on screen keeps its creases (a small box stays a box) but gets no lines
// where its colours change: at a few pixels across those lines are most of it (criticalmass's
// small enemy ships, purple legs on white, came out as blots of ink). edges.detail_size=0
// draws them as before.
TEST(Edges, ASmallObjectKeepsItsCreasesButNotItsColourLines)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    // Half-unit boxes about 35 pixels across: one turned to show three faces, one a plate
    // facing the eye whose front face is two colours split along its diagonal.
    const glm::mat4 at = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -15.0f));
    const glm::mat4 turned = glm::rotate(glm::rotate(at, 0.6f, glm::vec3(1.0f, 0.0f, 0.0f)),
                                         0.7f, glm::vec3(0.0f, 1.0f, 0.0f));
    reconstruct::Batch plate = boxBatch(at, glm::vec3(0.5f, 0.5f, 0.05f), kPale);
    for (size_t k = 30; k < 33; ++k) plate.vertices[k].color = glm::vec4(0.2f, 0.3f, 0.9f, 1.0f);
    auto inkInside = [](const PngImage& image) {
        int n = 0; // 6 pixels around the centre: inside either box
        for (int y = kSize / 2 - 6; y <= kSize / 2 + 6; ++y) {
            for (int x = kSize / 2 - 6; x <= kSize / 2 + 6; ++x) n += isInk(image, x, y);
        }
        return n;
    };
    auto inked = [&](const reconstruct::Batch& b, const std::string& config,
                     const std::string& name) {
        return inkInside(render(harness, harness.makeScene({b}, perspective()), "toon+edges",
                                config, name));
    };
    const reconstruct::Batch box = boxBatch(turned, glm::vec3(0.5f), kPale);
    EXPECT_GT(inked(box, "", "edges_small_box"), 10) << "a small box lost its creases";
    EXPECT_GT(inked(plate, "edges.detail_size=0", "edges_plate_all"), 5)
        << "no line between the colours to begin with";
    EXPECT_EQ(inked(plate, "", "edges_plate_small"), 0);
}

// An object under edges.thin_size is outlined by one pixel drawn around it, on what lies
// behind it, and keeps every pixel of its own: lines two pixels wide on both sides of its rim
// had left neverball's coins, a few pixels across, as blots of ink.
TEST(Edges, ATinyObjectIsOutlinedAroundItNotOverIt)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    // A plate facing the eye, about 12 pixels across on a white background.
    const glm::mat4 at = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -15.0f));
    const auto scene = harness.makeScene(
        {boxBatch(at, glm::vec3(0.25f, 0.25f, 0.05f), kPale)}, perspective());
    const PngImage plain = render(harness, scene, "toon", "", "edges_tiny_plain");
    auto own = [&](int x, int y) {
        if (x < 0 || y < 0 || x >= plain.width || y >= plain.height) return false;
        const uint8_t* p = &plain.rgba[(size_t(y) * plain.width + x) * 4];
        return p[0] < 250 || p[1] < 250 || p[2] < 250;
    };
    int area = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) area += own(x, y);
    }
    ASSERT_GT(area, 80);
    ASSERT_LT(area, 400);
    // Ink on the plate's pixels; ink on the ring of pixels just outside, and that ring's size.
    auto inked = [&](const std::string& config, const std::string& name) {
        const PngImage image = render(harness, scene, "toon+edges", config, name);
        glm::ivec3 n(0);
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (own(x, y)) {
                    n.x += isInk(image, x, y);
                } else if (own(x + 1, y) || own(x - 1, y) || own(x, y + 1) || own(x, y - 1)) {
                    n.y += isInk(image, x, y);
                    ++n.z;
                }
            }
        }
        return n;
    };
    const glm::ivec3 tiny = inked("", "edges_tiny");
    EXPECT_EQ(tiny.x, 0) << "ink over the tiny plate's own pixels";
    EXPECT_GE(tiny.y, tiny.z * 9 / 10) << "the outline around it is broken";
    const glm::ivec3 wide = inked("edges.thin_size=0", "edges_tiny_wide");
    EXPECT_GT(wide.x, area / 4) << "with two-pixel lines its rim was inked to begin with";
}

// A flat grid of quads, n x n, facing the eye at depth z, one colour (GL_TRIANGLES).
reconstruct::Batch gridBatch(int n, float z, glm::vec4 color)
{
    reconstruct::Batch b;
    b.mode = GL_TRIANGLES;
    b.materialId = 1;
    auto at = [&](int i, int j) {
        reconstruct::Vertex v{};
        v.position = glm::vec3(float(i) / n - 0.5f, float(j) / n - 0.5f, z);
        v.normal = glm::vec3(0.0f, 0.0f, 1.0f);
        v.color = color;
        v.hasNormal = true;
        return v;
    };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            b.vertices.insert(b.vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1),
                                                 at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return b;
}

size_t featureLineCount(StyleHarness& harness, const reconstruct::Batch& batch)
{
    const styles::Scene scene = harness.makeScene({batch}, perspective());
    EXPECT_EQ(scene.objects.size(), 1u);
    std::vector<uint32_t> pairs;
    if (!scene.objects.empty()) styles::FeatureLines::collect(*scene.objects[0].mesh, pairs);
    return pairs.size() / 2;
}

// The edge operator can find a line only along a border, a fold, or an edge across which the
// corners' colours or normals change; the edges inside a flat, even surface are skipped.
TEST(FeatureLines, BordersFoldsAndChangesButNotTheInsideOfAFlatSurface)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    EXPECT_EQ(featureLineCount(harness, boxBatch(boxModelview(), glm::vec3(1.0f), kPale)), 12u)
        << "a box: its 12 edges, not its faces' diagonals";
    reconstruct::Batch two = boxBatch(boxModelview(), glm::vec3(1.0f), kPale);
    for (size_t k = 30; k < 33; ++k) two.vertices[k].color = glm::vec4(0.2f, 0.3f, 0.9f, 1.0f);
    EXPECT_EQ(featureLineCount(harness, two), 13u) << "a face of two colours: and its diagonal";
    reconstruct::Batch grid = gridBatch(4, -5.0f, kPale);
    grid.modelview = glm::mat4(1.0f);
    EXPECT_EQ(featureLineCount(harness, grid), 16u) << "a flat grid: its border alone";
    for (size_t k = 0; k < 6; ++k) grid.vertices[k].normal = glm::normalize(glm::vec3(0, 1, 1));
    EXPECT_GT(featureLineCount(harness, grid), 16u) << "normals that turn within the plane";
    const reconstruct::Batch sphere = sphereBatch(sphereModelview(), kRadius, 12, 6, kRed);
    const styles::Scene round = harness.makeScene({sphere}, perspective());
    ASSERT_EQ(round.objects.size(), 1u);
    // Each of its quads between two rings is planar and smooth: its diagonal draws nothing.
    EXPECT_EQ(featureLineCount(harness, sphere), round.objects[0].mesh->edgeCount() - 12 * 4)
        << "a curved surface: every edge but its quads' diagonals may be a silhouette";
}

// The direct pass run on the pixels near the feature lines finds the lines the pass over the
// whole rectangle finds: silhouettes against the background and against other objects,
// creases, a colour change, a tiny object's outline and a thin plate's.
TEST(Edges, ThePassNearTheFeatureLinesDrawsWhatTheFullPassDraws)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 far = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -12.0f));
    reconstruct::Batch floor = gridBatch(6, 0.0f, glm::vec4(0.4f, 0.7f, 0.4f, 1.0f));
    floor.modelview = glm::scale(glm::rotate(far, -1.1f, glm::vec3(1, 0, 0)), glm::vec3(12.0f));
    reconstruct::Batch plate = boxBatch(glm::translate(far, glm::vec3(-2.0f, 1.5f, 3.0f)),
                                        glm::vec3(0.8f, 0.8f, 0.05f), kPale);
    for (size_t k = 30; k < 33; ++k) plate.vertices[k].color = glm::vec4(0.2f, 0.3f, 0.9f, 1.0f);
    const auto scene = harness.makeScene(
        {floor, sphereBatch(glm::translate(far, glm::vec3(1.5f, 0.5f, 2.0f)), 1.2f, 16, 8, kRed),
         boxBatch(boxModelview(), glm::vec3(0.6f), kPale), plate,
         boxBatch(glm::translate(far, glm::vec3(0.5f, -2.5f, 4.0f)), glm::vec3(0.15f), kRed)},
        perspective());
    const PngImage full = render(harness, scene, "toon+edges", "edges.pass=full", "pass_full");
    const PngImage near = render(harness, scene, "toon+edges", "edges.pass=lines", "pass_lines");
    const PngImage chosen = render(harness, scene, "toon+edges", "", "pass_auto");
    ASSERT_EQ(full.rgba.size(), near.rgba.size());
    const int ink = countInk(full);
    EXPECT_GT(ink, 500);
    auto differing = [&](const PngImage& image) {
        int n = 0;
        for (size_t i = 0; i < full.rgba.size(); i += 4) {
            for (size_t c = 0; c < 3; ++c) {
                if (std::abs(int(full.rgba[i + c]) - int(image.rgba[i + c])) > 16) {
                    ++n;
                    break;
                }
            }
        }
        return n;
    };
    // Where a line leaves the viewport its band is clipped with it: a pixel or two.
    EXPECT_LE(differing(near), 4) << "on every object's lines, of " << ink << " ink pixels";
    EXPECT_LE(differing(chosen), 4) << "on the cheaper of each object's lines and box";
}

TEST(Wireframe, StencilKeepsLinesOffTheInterior)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    PngImage image = render(harness, scene, "toon+wireframe",
                            "wireframe.stencil=on,wireframe.antialias=on", "wireframe_stencil");
    const float radius = silhouetteRadius(kSize);
    const RingStats s = ring(image, kCentre, radius, 3.0f, 0.97f);
    EXPECT_GE(s.rimCoverage, 0.99f);
    EXPECT_EQ(s.insideInk, 0);
    EXPECT_EQ(s.outsideInk, 0);
}

// A program whose shown faces wind clockwise on screen (Quake III's renderer mirrors its
// modelview and culls GL_FRONT) still gets its silhouette only: the faces turned away are
// the ones it culls, not the counter-clockwise ones (which would ink its whole surface).
TEST(Wireframe, AProgramShowingClockwiseFacesIsOutlinedOnItsRimOnly)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = mirroredSphere(harness);
    for (auto& o : scene.objects) o.culled = GL_CCW;
    const RingStats s =
        expectRimOnly(harness, scene, "toon+wireframe", "wireframe_clockwise", 0.9f);
    EXPECT_EQ(s.outsideInk, 0);
}

// A program that culls nothing may wind its faces either way (demo_immediate's sphere and
// torus wind clockwise seen from outside); its normals say which side is the outside, and
// the silhouette pass draws the other, not the shown faces' edges all over the surface.
TEST(Wireframe, AClockwiseMeshTheProgramDoesNotCullIsOutlinedOnItsRimOnly)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    reconstruct::Batch sphere = sphereBatch(sphereModelview(), kRadius, 48, 24, kRed);
    for (size_t i = 0; i + 2 < sphere.vertices.size(); i += 3) {
        std::swap(sphere.vertices[i + 1], sphere.vertices[i + 2]);
    }
    auto scene = harness.makeScene({sphere}, perspective());
    expectRimOnly(harness, scene, "toon+wireframe", "wireframe_clockwise_unculled", 0.9f);
}

// A thin part (a coin, a plate, a shell) seen face on: its back faces lie just behind its
// front, and the silhouette pass must not lift their edges over it (winduprobot's bodies and
// neverball's coins were blots of ink). A plate 0.004 thick at distance 6: ink on its rim, none
// inside (the back face's diagonal and edges).
TEST(Wireframe, AThinPlateShowsNoLinesOfItsBackOverItsFront)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
    auto scene = harness.makeScene({boxBatch(mv, glm::vec3(1.0f, 1.0f, 0.002f), kPale)},
                                   perspective());
    PngImage image = render(harness, scene, "toon+wireframe", "", "wireframe_thin_plate");
    const glm::vec4 viewport(0, 0, kSize, kSize);
    const glm::vec2 lo(glm::project(glm::vec3(-1.0f, -1.0f, 0.002f), mv, perspective(), viewport));
    const glm::vec2 hi(glm::project(glm::vec3(1.0f, 1.0f, 0.002f), mv, perspective(), viewport));
    int inside = 0, insideInk = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const glm::vec2 p(x + 0.5f, kSize - y - 0.5f);
            if (p.x > lo.x + 6 && p.x < hi.x - 6 && p.y > lo.y + 6 && p.y < hi.y - 6) {
                ++inside;
                insideInk += isInk(image, x, y);
            }
        }
    }
    EXPECT_GT(inside, 2000) << "no plate: no test";
    EXPECT_EQ(insideInk, 0);
    EXPECT_TRUE(inkNear(image, glm::vec2(lo.x, 0.5f * (lo.y + hi.y)), 3.0f)) << "no rim";
}

// Which side of a face the eye sees comes from the face's plane, not its winding: a half drawn
// mirrored (glScalef(-1, 1, 1), as winduprobot draws its robots' left halves) winds clockwise
// on screen, and taking that for the inside inked the half black.
TEST(PerPixel, AMirroredObjectIsInkedOnItsRimOnly)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = mirroredSphere(harness);
    expectRimOnly(harness, scene, "toon+perpixel", "perpixel_mirrored", 0.75f);
}

// Faces the program culls are not on screen, so no line comes from them: seen from inside,
// a box drawn with its back faces culled shows nothing, not the creases of its inner corners
// (a long box around the eye: its far end and the edges along its sides are in view).
class CulledFaces : public ::testing::TestWithParam<std::string> {};

TEST_P(CulledFaces, DrawNoLines)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto ink = [&](GLenum culled) {
        auto scene = harness.makeScene(
            {boxBatch(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -5.0f)),
                      glm::vec3(1.0f, 1.0f, 6.0f), kPale)},
            perspective());
        for (auto& o : scene.objects) o.culled = culled;
        return countInk(render(harness, scene, "toon+" + GetParam(), "",
                               GetParam() + (culled ? "_culled_inside" : "_inside")));
    };
    EXPECT_GT(ink(0), 300) << "no ink inside the box: no test";
    EXPECT_EQ(ink(GL_CW), 0);
}

INSTANTIATE_TEST_SUITE_P(Styles, CulledFaces, ::testing::Values("edges", "perpixel"));

// The image-space buffers follow the viewport, also when it does not start at the origin.
TEST(Edges, FollowsAnOffsetViewport)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    scene.viewport = {40, 20, 180, 180};
    PngImage image = render(harness, scene, "toon+edges", "", "edges_viewport");
    const glm::vec2 centre(40 + 90, 20 + 90);
    const RingStats s = ring(image, centre, silhouetteRadius(180));
    EXPECT_GE(s.rimCoverage, 0.99f);
    EXPECT_EQ(s.insideInk, 0);
    EXPECT_EQ(s.outsideInk, 0);
}

// Geometry drawn in pieces (two boxes side by side, one colour, each its own object as the
// program drew it with its own modelview) is one surface where they meet: no ink along the
// seam unless edges.object_seams asks for it; the outer outline is there either way.
TEST(Edges, SeamsBetweenPiecesOfOneSurfaceAreNotInked)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto box = [](float x) {
        return boxBatch(glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, -kDistance)),
                        glm::vec3(0.5f), kPale);
    };
    auto scene = harness.makeScene({box(-0.5f), box(0.5f)}, perspective());
    ASSERT_EQ(scene.objects.size(), 2u);
    // The seam is the middle column; the boxes' front faces span about +-35 pixels around it.
    auto seamInk = [](const PngImage& image) {
        int n = 0;
        for (int y = kSize / 2 - 20; y < kSize / 2 + 20; ++y) {
            for (int x = kSize / 2 - 2; x <= kSize / 2 + 2; ++x) n += isInk(image, x, y);
        }
        return n;
    };
    // (The boxes are small enough on screen to lose lines between objects: detail_size=0.)
    const PngImage joined =
        render(harness, scene, "toon+edges", "edges.detail_size=0", "edges_seam_off");
    const PngImage seams = render(harness, scene, "toon+edges",
                                  "edges.object_seams=on,edges.detail_size=0", "edges_seam_on");
    EXPECT_EQ(seamInk(joined), 0);
    EXPECT_GT(seamInk(seams), 40);
    // The outer outline: ink on the left and right borders in both.
    for (const PngImage* image : {&joined, &seams}) {
        EXPECT_GT(countInk(*image), 200);
    }
}

// A part that covers one pixel (a sliver of one object poking through another, a detail
// smaller than a pixel) gets no outline: around one pixel the line would be a cross of ink five
// pixels big. A part a few pixels big still gets its outline.
TEST(Edges, AnObjectOfOnePixelGetsNoOutline)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    // World units per pixel at eye distance d; a box centred on pixel (px, py) from the centre.
    const float d = 5.0f;
    const float perPixel = 2.0f * d * std::tan(glm::radians(kFov) * 0.5f) / float(kSize);
    auto boxOnPixel = [&](int px, int py, float pixels) {
        const glm::vec3 at((float(px) + 0.5f) * perPixel, (float(py) + 0.5f) * perPixel, -d);
        return boxBatch(glm::translate(glm::mat4(1.0f), at), glm::vec3(0.4f * perPixel * pixels),
                        kPale);
    };
    const reconstruct::Batch wall =
        boxBatch(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance)),
                 glm::vec3(1.2f, 1.2f, 0.2f), kRed);
    auto scene = harness.makeScene({wall, boxOnPixel(-20, 0, 1.0f), boxOnPixel(20, 0, 6.0f)},
                                   perspective());
    const PngImage image = render(harness, scene, "toon+edges", "", "edges_one_pixel");
    const glm::vec2 centre(kSize * 0.5f, kSize * 0.5f);
    auto inkAround = [&](int px) {
        int n = 0;
        for (int dy = -6; dy <= 6; ++dy) {
            for (int dx = -6; dx <= 6; ++dx) {
                n += isInk(image, int(centre.x) + px + dx, kSize - 1 - (int(centre.y) + dy));
            }
        }
        return n;
    };
    EXPECT_EQ(inkAround(-20), 0);
    EXPECT_GT(inkAround(20), 12);
}

// What the program's depth test hides draws no line: a strip seen nearly edge-on just behind a
// wall's face (a tooth's flank behind a gear's face, in xscreensaver's gears) stays hidden in
// the edge style's attributes too. Its polygon offset was by slope as well as by units, which
// pulled steep faces further towards the eye than flat ones, through the face in front of
// them: glxgears' face got a cross of ink five pixels big where no edge is.
TEST(Edges, AFaceSeenEdgeOnBehindAnotherDrawsNoLine)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const reconstruct::Batch wall =
        boxBatch(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance)),
                 glm::vec3(1.2f, 1.2f, 0.2f), kRed);
    // Turned 75 degrees about y: about 5 pixels wide, 0.29 deep; its nearest edge 0.03 behind
    // the wall's face (z = -5.8).
    auto strip = [&](float behind) {
        glm::mat4 mv = glm::translate(glm::mat4(1.0f),
                                      glm::vec3(0.0f, 0.0f, -5.8f - behind - 0.145f));
        mv = glm::rotate(mv, glm::radians(75.0f), glm::vec3(0, 1, 0));
        return boxBatch(mv, glm::vec3(0.15f, 0.6f, 0.002f), kPale);
    };
    auto inkInside = [&](const PngImage& image) {
        int n = 0;
        for (int y = kSize / 2 - 30; y < kSize / 2 + 30; ++y) {
            for (int x = kSize / 2 - 12; x <= kSize / 2 + 12; ++x) n += isInk(image, x, y);
        }
        return n;
    };
    // In front of the wall (it pokes through by 0.05) it is outlined: the test can see ink.
    const PngImage poking = render(harness, harness.makeScene({wall, strip(-0.05f)},
                                                              perspective()),
                                   "toon+edges", "", "edges_edge_on_poking");
    EXPECT_GT(inkInside(poking), 60) << "no ink where the strip shows: no test";
    const PngImage hidden = render(harness, harness.makeScene({wall, strip(0.03f)},
                                                              perspective()),
                                   "toon+edges", "", "edges_edge_on_hidden");
    EXPECT_EQ(inkInside(hidden), 0);
}

// Thin geometry (a wire, a beam, a rail far off: one or two pixels across) keeps its colour
// between its outlines: they are drawn on its neighbours' pixels, not over it. Before, the
// line's two-pixel band covered such a wire whole.
TEST(Edges, AThinWireKeepsItsColourBetweenItsOutlines)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const float d = 5.0f;
    const float perPixel = 2.0f * d * std::tan(glm::radians(kFov) * 0.5f) / float(kSize);
    // A vertical wire `pixels` wide whose left side is at pixel column x0 from the centre.
    auto wire = [&](int x0, int pixels) {
        const glm::vec3 at((float(x0) + 0.5f * float(pixels)) * perPixel, 0.0f, -d);
        return boxBatch(glm::translate(glm::mat4(1.0f), at),
                        glm::vec3(0.5f * float(pixels), 30.0f, 0.5f * float(pixels)) * perPixel,
                        kPale);
    };
    const reconstruct::Batch wall =
        boxBatch(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance)),
                 glm::vec3(1.2f, 1.2f, 0.2f), kRed);
    auto scene = harness.makeScene({wall, wire(-20, 1), wire(20, 2)}, perspective());
    const PngImage image = render(harness, scene, "toon+edges", "", "edges_thin_wire");
    const int cx = kSize / 2;
    // Over the middle 40 rows: ink in a column (x from the centre).
    auto inkIn = [&](int x) {
        int n = 0;
        for (int y = -20; y < 20; ++y) n += isInk(image, cx + x, kSize / 2 + y);
        return n;
    };
    EXPECT_LT(inkIn(-20), 4) << "the one-pixel wire is under its outline";
    EXPECT_LT(inkIn(20) + inkIn(21), 8) << "the two-pixel wire is under its outline";
    EXPECT_GT(inkIn(-21), 36) << "no outline left of the one-pixel wire";
    EXPECT_GT(inkIn(-19), 36) << "no outline right of the one-pixel wire";
    EXPECT_GT(inkIn(19), 36) << "no outline left of the two-pixel wire";
    EXPECT_GT(inkIn(22), 36) << "no outline right of the two-pixel wire";
}

// A beam reaching from behind the eye into the distance (a corridor wall, a rail) is outlined
// all along its visible part: the passes cover the box as GL clips it at the near plane, not
// just its corners in front. It enters the view at the left border and runs to the middle.
TEST(Edges, AnObjectReachingBehindTheEyeIsOutlinedAllAlongIt)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(-1.2f, -0.6f, -5.0f));
    auto scene =
        harness.makeScene({boxBatch(mv, glm::vec3(0.3f, 0.3f, 8.0f), kPale)}, perspective());
    const PngImage image = render(harness, scene, "toon+edges", "", "edges_behind_eye");
    // Its far end lies within 0.35 of the width from the left border; the lines must reach
    // the border, so ink in every column of the leftmost tenth.
    int inkedColumns = 0;
    for (int x = 0; x < kSize / 10; ++x) {
        bool inked = false;
        for (int y = 0; y < kSize && !inked; ++y)
            inked = isInk(image, x, y);
        inkedColumns += inked;
    }
    EXPECT_EQ(inkedColumns, kSize / 10);
}

// One chain kept across flushes whose viewport changes size: the off-screen buffers follow.
TEST(Edges, RecreatesBuffersWhenTheViewportChanges)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    StyleSettings settings;
    std::string error;
    ASSERT_TRUE(StyleSettings::parse("edges", "", settings, error)) << error;
    styles::StyleChain chain;
    auto getProc = [](const char* name) {
        return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
    };
    ASSERT_TRUE(chain.init(settings, getProc, error)) << error;
    const styles::GlFunctions& gl = harness.gl();
    PngImage image;
    scene.clearColor = glm::vec4(1.0f); // as cleared below: black ink on it
    for (int size : {96, kSize, 160}) {
        scene.viewport = {0, 0, size, size};
        gl.Viewport(0, 0, kSize, kSize);
        gl.ClearColor(1, 1, 1, 1);
        gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        chain.render(scene);
        image.width = image.height = kSize;
        image.rgba.resize(size_t(kSize) * kSize * 4);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
        gl.ReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        image.flipRows();
        image.write("/tmp/outlines/edges_resize_" + std::to_string(size) + ".png", error);
        const glm::vec2 centre(size * 0.5f, size * 0.5f);
        const RingStats s = ring(image, centre, silhouetteRadius(size));
        EXPECT_GE(s.rimCoverage, 0.99f) << size;
        EXPECT_EQ(s.insideInk, 0) << size;
        EXPECT_EQ(s.outsideInk, 0) << size;
    }
    chain.shutdown();
}

// Each option visibly changes its chain's picture (the pictures are kept in /tmp/outlines
// for looking at); widening a line adds ink.
TEST(Gallery, EveryOptionChangesThePicture)
{
    StyleHarness harness(320, 320);
    ASSERT_TRUE(harness.ok());
    glm::mat4 box = glm::translate(glm::mat4(1.0f), glm::vec3(0.9f, -0.3f, -8.0f));
    box = glm::rotate(box, glm::radians(35.0f), glm::vec3(1, 1, 0));
    const glm::mat4 sphere = glm::translate(glm::mat4(1.0f), glm::vec3(-0.8f, 0.2f, -6.0f));
    auto scene = harness.makeScene({boxBatch(box, glm::vec3(1.2f), kPale, 2),
                                    sphereBatch(sphere, 1.2f, 32, 16, kRed)},
                                   perspective());
    struct Case {
        const char* chain;
        const char* config;
        bool moreInk; // the option widens lines
    };
    const Case cases[] = {
        {"toon+wireframe", "wireframe.antialias=on,wireframe.silhouette_width=6", true},
        {"toon+wireframe", "wireframe.stencil=on,wireframe.silhouette_width=10", true},
        {"toon+wireframe", "wireframe.silhouette_width=10,wireframe.vertex_points=off", true},
        {"wireframe", "wireframe.depth_cue=1,wireframe.crease_lightness=0.5", false},
        {"toon+edges", "edges.silhouette_width=5,edges.crease_lightness=0.4", false},
    };
    int i = 0;
    for (const auto& c : cases) {
        const std::string name = "gallery_" + std::to_string(i++);
        const PngImage base = render(harness, scene, c.chain, "", name + "_base");
        const PngImage option = render(harness, scene, c.chain, c.config, name);
        ASSERT_EQ(base.rgba.size(), option.rgba.size());
        int differing = 0;
        for (size_t p = 0; p < base.rgba.size(); p += 4) {
            int delta = 0;
            for (int k = 0; k < 3; ++k) delta += std::abs(base.rgba[p + k] - option.rgba[p + k]);
            differing += delta > 24;
        }
        EXPECT_GT(differing, 320 * 320 / 1000) << c.chain << " " << c.config << " changed nothing";
        if (c.moreInk) {
            EXPECT_GT(countInk(option), countInk(base)) << c.chain << " " << c.config;
        }
    }
    // The other chains of the gallery render, for looking at.
    for (const char* chain : {"toon+perpixel", "edges"}) {
        const PngImage image = render(harness, scene, chain, "", std::string("gallery_") + chain);
        EXPECT_GT(countInk(image), 0) << chain;
    }
}

} // namespace

// HijackGL's depth cue: a near and a far box, the same size. Near lines are nearly opaque
// ink; far lines fade towards far_intensity (0.15): only where several meet at a corner can
// they darken a pixel by half.
TEST(DepthCue, LinesFadeFromTheNearestToTheFarthestPoint)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    glm::mat4 nearBox = glm::translate(glm::mat4(1.0f), glm::vec3(-1.1f, 0.0f, -6.0f));
    nearBox = glm::rotate(nearBox, glm::radians(30.0f), glm::vec3(1, 1, 0));
    glm::mat4 farBox = glm::translate(glm::mat4(1.0f), glm::vec3(3.5f, 0.0f, -14.0f));
    farBox = glm::rotate(farBox, glm::radians(30.0f), glm::vec3(1, 1, 0));
    auto scene = harness.makeScene({boxBatch(nearBox, glm::vec3(0.7f), kPale, 1),
                                    boxBatch(farBox, glm::vec3(0.7f), kPale, 2)},
                                   perspective());
    const PngImage plain = render(harness, scene, "toon", "", "depthcue_plain");
    const PngImage cued = render(harness, scene, "toon+depthcue", "", "depthcue");
    // Per half of the frame (the near box left, the far one right): pixels darkened by more
    // than half, and pixels darkened at all.
    int halfDark[2] = {0, 0}, touched[2] = {0, 0};
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const size_t i = (size_t(y) * kSize + x) * 4;
            const float a = float(plain.rgba[i]) + plain.rgba[i + 1] + plain.rgba[i + 2];
            const float b = float(cued.rgba[i]) + cued.rgba[i + 1] + cued.rgba[i + 2];
            if (a < 30.0f) continue; // the background's own dark pixels, if any
            const int side = x < kSize / 2 ? 0 : 1;
            halfDark[side] += b < 0.5f * a;
            touched[side] += b < 0.97f * a;
        }
    }
    EXPECT_GT(halfDark[0], 200) << "near lines are not dark";
    EXPECT_GT(touched[1], 20) << "far lines are missing";
    EXPECT_LT(halfDark[1] * 10, touched[1]) << "far lines are as dark as near ones";
}

namespace {

// The blueprint preset's chain and values (styles/Presets.cpp), for the harness.
const std::string kBlueprintChain = "toon+paper+blueprint";
const std::string kBlueprintConfig = "toon.tones=2,toon.shadow_color=1d4f91,"
                                     "toon.diffuse_color=1d4f91,toon.detail=off,"
                                     "paper.color=1d4f91,paper.grain=0";

bool isWhite(const PngImage& image, int x, int y)
{
    const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
    return p[0] > 200 && p[1] > 200 && p[2] > 200;
}

} // namespace

// White lines on blue: the box's edges white, its faces and the page the preset's blue.
TEST(Blueprint, WhiteLinesOnBluePaper)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
    mv = glm::rotate(mv, glm::radians(30.0f), glm::vec3(1, 1, 0));
    auto scene = harness.makeScene({boxBatch(mv, glm::vec3(1.0f), kPale)}, perspective());
    PngImage image = render(harness, scene, kBlueprintChain, kBlueprintConfig, "blueprint");
    int white = 0, blue = 0, other = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            const uint8_t* p = &image.rgba[(size_t(y) * kSize + x) * 4];
            if (isWhite(image, x, y)) ++white;
            else if (p[2] > p[0] + 60 && p[2] > p[1] + 30) ++blue; // 1d4f91, grid or not
            else ++other;
        }
    }
    EXPECT_GT(white, 400);                     // the box's edges
    EXPECT_GT(blue, kSize * kSize * 8 / 10);   // page and faces
    EXPECT_LT(other, kSize * kSize / 50);      // blends of white into blue only
}

// Dimensions: with them, white appears away from the box (dimension lines, arrows, digits).
TEST(Blueprint, DimensionsAnnotateTheLongestEdges)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
    mv = glm::rotate(mv, glm::radians(20.0f), glm::vec3(0, 1, 0));
    auto scene = harness.makeScene({boxBatch(mv, glm::vec3(1.2f, 0.8f, 0.8f), kPale)},
                                   perspective());
    auto whiteCount = [&](const std::string& dimensions) {
        PngImage image = render(harness, scene, kBlueprintChain,
                                kBlueprintConfig + ",blueprint.grid=0,blueprint.dimensions=" +
                                    dimensions,
                                "blueprint_dim" + dimensions);
        int n = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) n += isWhite(image, x, y);
        }
        return n;
    };
    const int without = whiteCount("0");
    const int with = whiteCount("3");
    EXPECT_GT(with, without + 150) << "no dimension lines";
    EXPECT_LT(with, without + 3000) << "more than lines";
}

// Hidden lines: with blueprint.hidden the box's far edges appear inside its outline, dashed
// (runs of white broken by gaps along each edge); without it, none of them.
TEST(Blueprint, HiddenEdgesAreDashedAndOnlyOnRequest)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
    mv = glm::rotate(mv, glm::radians(30.0f), glm::vec3(1, 1, 0));
    auto scene = harness.makeScene({boxBatch(mv, glm::vec3(1.0f), kPale)}, perspective());
    const std::string config = kBlueprintConfig + ",blueprint.grid=0,blueprint.dimensions=0";
    const PngImage solid = render(harness, scene, kBlueprintChain, config, "blueprint_solid");
    const PngImage dashed = render(harness, scene, kBlueprintChain,
                                   config + ",blueprint.hidden=1,blueprint.dash=4",
                                   "blueprint_hidden");
    int added = 0, removed = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            added += isWhite(dashed, x, y) && !isWhite(solid, x, y);
            removed += !isWhite(dashed, x, y) && isWhite(solid, x, y);
        }
    }
    EXPECT_GT(added, 60) << "no hidden lines";
    EXPECT_EQ(removed, 0) << "the visible lines changed";
    // Dashes: along the rows, the hidden-only pixels come in runs, not as solid lines. A
    // solid far edge would give runs as long as the edge (about 80 px here).
    int longest = 0;
    for (int y = 0; y < kSize; ++y) {
        int run = 0;
        for (int x = 0; x < kSize; ++x) {
            const bool hiddenOnly = isWhite(dashed, x, y) && !isWhite(solid, x, y);
            run = hiddenOnly ? run + 1 : 0;
            longest = std::max(longest, run);
        }
    }
    for (int x = 0; x < kSize; ++x) {
        int run = 0;
        for (int y = 0; y < kSize; ++y) {
            const bool hiddenOnly = isWhite(dashed, x, y) && !isWhite(solid, x, y);
            run = hiddenOnly ? run + 1 : 0;
            longest = std::max(longest, run);
        }
    }
    EXPECT_LT(longest, 12) << "hidden lines are not dashed";
}

// The harness renders one chain after another in one context, as a compositor would never
// do without restoring the program's state in between: an outline style that left depth
// writes off made the next chain's glClear keep the old depth, and its surfaces failed the
// depth test (the frame stayed empty). The same chain before and after gives the same frame.
TEST(StyleHarness, EachRenderStartsFromAClearedFrame)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    const PngImage before = render(harness, scene, "toon", "", "harness_before");
    render(harness, scene, "toon+perpixel", "", "harness_between");
    const PngImage after = render(harness, scene, "toon", "", "harness_after");
    EXPECT_EQ(before.rgba, after.rgba);
}

namespace {

// Mean luminance (0-255) of the pixels within `radius` of the GL window point `at`.
float meanLuminance(const PngImage& image, glm::vec2 at, float radius)
{
    double sum = 0.0;
    int n = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            if (distanceFrom(image, x, y, at) > radius) continue;
            const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
            sum += 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
            ++n;
        }
    }
    return n ? float(sum / n) : 0.0f;
}

} // namespace

// Pencil: the tone is hatching, denser away from the light, and nothing of the program's
// colour survives as a flat fill: a red sphere becomes graphite on paper.
TEST(Pencil, HatchingDarkensAwayFromTheLightWithoutFlatFills)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective(), glm::normalize(glm::vec3(0.5f, 0.5f, 0.7f)));
    // The program's colour out of the tone: light alone decides it here.
    PngImage image = render(harness, scene, "pencil", "pencil.color_tone=0", "pencil_sphere");
    const float r = silhouetteRadius(kSize);
    const glm::vec2 towards = glm::normalize(glm::vec2(1.0f, 1.0f));
    const float lit = meanLuminance(image, kCentre + towards * (0.45f * r), 0.2f * r);
    const float shadow = meanLuminance(image, kCentre - towards * (0.6f * r), 0.2f * r);
    EXPECT_GT(lit, 200.0f) << "the lit side is (nearly) bare paper";
    EXPECT_LT(shadow, lit - 40.0f) << "no denser hatching on the shadow side";
    int coloured = 0, inside = 0;
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (distanceFrom(image, x, y, kCentre) > 0.9f * r) continue;
            const uint8_t* p = &image.rgba[(size_t(y) * kSize + x) * 4];
            const int hi = std::max({p[0], p[1], p[2]}), lo = std::min({p[0], p[1], p[2]});
            coloured += hi - lo > 40;
            ++inside;
        }
    }
    EXPECT_LT(coloured, inside / 100) << "the program's red shows through";
}

// Pencil outlines: overdrawn strokes around the sphere's silhouette, none far outside it.
TEST(Pencil, StrokesFollowTheSilhouette)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({sphereBatch(sphereModelview(), kRadius, 48, 24, kRed)},
                                   perspective());
    PngImage image = render(harness, scene, "pencil", "pencil.fill=off", "pencil_strokes");
    // A pencil mark: clearly darker than paper (about 240) and the white fill, lighter than ink.
    constexpr int kMark = 170;
    const RingStats s =
        ring(image, kCentre, silhouetteRadius(kSize), 4.0f, 0.75f, 8.0f, kMark);
    EXPECT_GT(s.rimCoverage, 0.9f);
    EXPECT_EQ(s.insideInk, 0);
    EXPECT_LT(s.outsideInk, 20);
    // Without outlines there is no mark at all on a fill-less frame.
    PngImage bare = render(harness, scene, "pencil", "pencil.fill=off,pencil.outlines=off",
                           "pencil_bare");
    EXPECT_EQ(countInk(bare, kMark), 0);
}

// Nothing in the drawing is random per frame: the same scene in a later frame is the same
// picture (the strokes' wobble is fixed per mesh vertex, the hatching per line).
TEST(Pencil, TheSameSceneIsTheSameDrawingInEveryFrame)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    auto scene = harness.makeScene({boxBatch(boxModelview(), glm::vec3(1.0f), kPale)},
                                   perspective());
    scene.frame = 1;
    const PngImage first = render(harness, scene, "pencil", "", "pencil_frame1");
    scene.frame = 2;
    const PngImage second = render(harness, scene, "pencil", "", "pencil_frame2");
    EXPECT_EQ(first.rgba, second.rgba);
    EXPECT_GT(countInk(first), 300) << "nothing drawn";
}

namespace {

// Speed lines need earlier frames: one harness chain renders a sequence of scenes, frame by
// frame, as a program's context would. sceneAt(frame) gives that frame's batches.
template <typename SceneAt>
std::vector<PngImage> renderMotion(int frames, SceneAt sceneAt, const std::string& config,
                                   const std::string& name)
{
    std::vector<PngImage> out;
    StyleHarness harness(kSize, kSize);
    EXPECT_TRUE(harness.ok());
    if (!harness.ok()) return out;
    harness.keepChain(true);
    for (int f = 0; f < frames; ++f) {
        styles::Scene scene = harness.makeScene(sceneAt(f), perspective());
        scene.frame = uint64_t(f);
        out.push_back(render(harness, scene, "motion", config, name + std::to_string(f)));
    }
    return out;
}

// Over the white page (the chain has no shading: the objects leave depth only) every pixel
// darker than white is line: summed darkness of the picture, and of a column range.
double darkness(const PngImage& image, int fromX = 0, int toX = kSize)
{
    double sum = 0.0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = std::max(fromX, 0); x < std::min(toX, image.width); ++x) {
            const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
            sum += 255 - std::min({p[0], p[1], p[2]});
        }
    }
    return sum;
}

// Pixels per object unit at the sphere's distance, and a sphere moved sideways by x units.
float pixelsPerUnit()
{
    return float(kSize) * 0.5f / std::tan(glm::radians(kFov) * 0.5f) / kDistance;
}

reconstruct::Batch sphereAt(float x)
{
    return sphereBatch(glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, -kDistance)), kRadius,
                       48, 24, kRed);
}

} // namespace

// A still object gets no speed lines, however many frames it stays.
TEST(Motion, StillObjectsGetNoLines)
{
    auto still = [](int) { return std::vector<reconstruct::Batch>{sphereAt(0.0f)}; };
    const auto images = renderMotion(5, still, "", "motion_still");
    ASSERT_EQ(images.size(), 5u);
    for (size_t f = 0; f < images.size(); ++f) {
        EXPECT_EQ(darkness(images[f]), 0.0) << "frame " << f;
    }
}

// Moving right, the sphere trails lines to its left, none on its leading (right) side nor
// over the sphere; and none in the first frame, which has no earlier one to move from.
TEST(Motion, LinesTrailBehindTheMotion)
{
    constexpr float kStep = 0.1f; // units a frame: about 6 pixels
    auto right = [](int f) {
        return std::vector<reconstruct::Batch>{sphereAt(-0.3f + kStep * float(f))};
    };
    const auto images = renderMotion(4, right, "", "motion_right");
    ASSERT_EQ(images.size(), 4u);
    EXPECT_EQ(darkness(images[0]), 0.0) << "lines without motion in the first frame";
    const float centre = kCentre.x + (-0.3f + kStep * 3) * pixelsPerUnit();
    const float r = silhouetteRadius(kSize);
    const PngImage& last = images[3];
    EXPECT_GT(countInk(last, 160), 30) << "no (or too faint) speed lines";
    // Left of the sphere's centre the lines, reaching past its left side; right: nothing.
    EXPECT_GT(darkness(last, 0, int(centre - r)), 0.0) << "no lines behind the sphere";
    EXPECT_EQ(darkness(last, int(std::ceil(centre)), kSize), 0.0) << "lines on the leading side";
    // The lines run horizontally: within the sphere's height.
    int strays = 0;
    for (int y = 0; y < kSize; ++y) {
        const float up = std::abs(kSize * 0.5f - (float(y) + 0.5f));
        for (int x = 0; x < kSize && up > r + 3.0f; ++x) strays += isInk(last, x, y, 250);
    }
    EXPECT_EQ(strays, 0) << "lines above or below the sphere";
}

// After the object stops the lines fade over fade_frames frames, then are gone.
TEST(Motion, LinesFadeAfterTheObjectStops)
{
    // Frames 0-3 move, 4-7 stand where frame 3 was.
    const auto images = renderMotion(
        8,
        [](int f) {
            return std::vector<reconstruct::Batch>{sphereAt(-0.3f + 0.1f * std::min(f, 3))};
        },
        "motion.fade_frames=3", "motion_fade");
    ASSERT_EQ(images.size(), 8u);
    const double moving = darkness(images[3]);
    EXPECT_GT(moving, 0.0);
    EXPECT_GT(darkness(images[4]), 0.0) << "gone at once, not fading";
    EXPECT_LT(darkness(images[4]), moving) << "not fading";
    EXPECT_LT(darkness(images[5]), darkness(images[4])) << "not fading";
    EXPECT_EQ(darkness(images[6]), 0.0) << "still there after fade_frames";
    EXPECT_EQ(darkness(images[7]), 0.0);
}

// A flat box spinning in place about its own axis, like a gear: its centre never moves, its
// corners do, and they trail lines.
TEST(Motion, ObjectsTurningInPlaceGetLines)
{
    auto gear = [](int f) {
        glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
        mv = glm::rotate(mv, glm::radians(25.0f), glm::vec3(1, 0, 0));
        mv = glm::rotate(mv, glm::radians(8.0f * float(f)), glm::vec3(0, 0, 1));
        return std::vector<reconstruct::Batch>{boxBatch(mv, glm::vec3(1.2f, 1.2f, 0.3f), kPale)};
    };
    const auto images = renderMotion(4, gear, "", "motion_spin");
    ASSERT_EQ(images.size(), 4u);
    EXPECT_EQ(darkness(images[0]), 0.0);
    EXPECT_GT(countInk(images[3], 160), 30) << "no speed lines on a spinning object";
}

// A skinned object: the program moves the vertices themselves (the modelview stays), so the
// reconstruction updates the mesh every frame; the lines still trail behind it.
TEST(Motion, DeformedMeshesTrailLinesToo)
{
    auto moved = [](int f) {
        const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
        reconstruct::Batch b = sphereBatch(mv, kRadius, 48, 24, kRed);
        for (reconstruct::Vertex& v : b.vertices) v.position.x += -0.3f + 0.1f * float(f);
        return std::vector<reconstruct::Batch>{b};
    };
    const auto images = renderMotion(4, moved, "", "motion_skinned");
    ASSERT_EQ(images.size(), 4u);
    const float centre = kCentre.x; // where frame 3 has it
    EXPECT_GT(countInk(images[3], 160), 30) << "no lines on a deforming mesh";
    EXPECT_EQ(darkness(images[3], int(std::ceil(centre)), kSize), 0.0);
}

// Which object of the last frame an object is: the same mesh, else the same place in the
// drawing order with the same topology; never a mesh of another topology.
TEST(Motion, HistoryFollowsMeshesThenDrawingOrderAndTopology)
{
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kDistance));
    // Separate reconstructors: separate meshes of the same topology (a skinned mesh that
    // the cache copied), and one of another.
    reconstruct::Reconstructor r1, r2, r3;
    reconstruct::Batch moved = sphereBatch(mv, kRadius, 48, 24, kRed);
    for (reconstruct::Vertex& v : moved.vertices) v.position.x += 0.1f;
    auto a = r1.build({sphereBatch(mv, kRadius, 48, 24, kRed)});
    auto b = r2.build({moved});
    auto c = r3.build({sphereBatch(mv, kRadius, 40, 20, kRed)});
    ASSERT_EQ(a.size(), 1u);
    ASSERT_EQ(b.size(), 1u);
    ASSERT_EQ(c.size(), 1u);
    auto object = [&](const reconstruct::FrameObject& o) {
        styles::SceneObject s;
        s.mesh = o.mesh;
        s.modelview = o.modelview;
        s.projection = perspective();
        return s;
    };
    const glm::ivec4 viewport(0, 0, kSize, kSize);
    styles::MotionHistory history;
    EXPECT_TRUE(history.beginFlush(0, viewport));
    EXPECT_EQ(history.track(object(a[0])).before, nullptr) << "a history before the first frame";
    EXPECT_FALSE(history.beginFlush(0, viewport)) << "a second flush is not a new frame";
    EXPECT_TRUE(history.beginFlush(1, viewport));
    // Another mesh of the same topology in the same place: the same object, moved right.
    const auto motion = history.track(object(b[0]));
    ASSERT_NE(motion.before, nullptr);
    ASSERT_EQ(motion.now->size(), motion.before->size());
    const float dx = (*motion.now)[0].x - (*motion.before)[0].x;
    EXPECT_GT(dx, 0.1f * pixelsPerUnit() * 0.8f);
    EXPECT_TRUE(history.beginFlush(2, viewport));
    EXPECT_EQ(history.track(object(c[0])).before, nullptr) << "matched another topology";
    // A skipped frame forgets: frame 2 had c, frame 4 has c again.
    EXPECT_TRUE(history.beginFlush(4, viewport));
    EXPECT_EQ(history.track(object(c[0])).before, nullptr) << "motion across a skipped frame";
}

// The edge operator runs over the union of the boxes of objects it covers by their box: each
// pixel of every box covered exactly once, by rectangles that do not overlap.
TEST(TileUnion, CoversEveryBoxOnceWithRectanglesThatDoNotOverlap)
{
    const glm::ivec4 area(10, 20, 110, 90); // 100 x 70 pixels: tiles of 16, the last ones cut
    const std::vector<glm::ivec4> boxes = {
        {12, 22, 40, 50}, {30, 30, 60, 60}, {35, 25, 45, 85}, {100, 80, 130, 100}, {0, 0, 5, 5}};
    styles::TileUnion tiles(16);
    tiles.reset(area);
    int64_t added = 0;
    for (const glm::ivec4& b : boxes) added += tiles.add(b);
    EXPECT_EQ(tiles.add(boxes[1]), 0) << "a box again marks nothing new";
    std::vector<int> hits(100 * 70, 0);
    for (const glm::ivec4& r : tiles.rects()) {
        ASSERT_TRUE(r.x >= area.x && r.y >= area.y && r.z <= area.z && r.w <= area.w);
        for (int y = r.y; y < r.w; ++y) {
            for (int x = r.x; x < r.z; ++x) ++hits[size_t(y - area.y) * 100 + size_t(x - area.x)];
        }
    }
    int covered = 0;
    for (int y = area.y; y < area.w; ++y) {
        for (int x = area.x; x < area.z; ++x) {
            const int n = hits[size_t(y - area.y) * 100 + size_t(x - area.x)];
            EXPECT_LE(n, 1) << "rectangles overlap at " << x << ", " << y;
            covered += n;
            const bool inBox = std::any_of(boxes.begin(), boxes.end(), [&](const glm::ivec4& b) {
                return x >= b.x && x < b.z && y >= b.y && y < b.w;
            });
            if (inBox) {
                EXPECT_EQ(n, 1) << "a box's pixel " << x << ", " << y << " not covered";
            }
        }
    }
    // The tiles' pixels, whole tiles counted in full where the area cuts them.
    EXPECT_GE(added, covered);
    EXPECT_LT(covered, 100 * 70) << "the union is the whole area: the test shows nothing";
}
