// The StateTracker on the committed captures: what geometry a frame draws, where, in which
// material — display lists, client arrays and buffers included.

#include "capture/CaptureReader.h"
#include "frame/AttribStack.h"
#include "frame/MatrixStacks.h"
#include "frame/StateTracker.h"
#include "frame/TextureImage.h"
#include "replay/CaptureBlobs.h"
#include "stream/CallWriter.h"
#include "stream/Opcodes.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <set>

using namespace nprgl;

namespace {

// Runs a fixture up to and including `frame` and returns that frame's batches.
std::vector<TrackedBatch> frameBatches(const std::string& name, uint64_t frame)
{
    capture::CaptureReader reader;
    std::string error;
    const std::string path = test::fixture(name);
    EXPECT_TRUE(reader.open(path, error)) << error;
    CaptureBlobs blobs(reader);
    StateTracker tracker;
    std::vector<uint8_t> calls;
    for (size_t i = 0; i < reader.frames().size(); ++i) {
        EXPECT_TRUE(reader.readFrame(i, calls, error)) << error;
        EXPECT_TRUE(tracker.runFrame(calls.data(), calls.size(), &blobs, error)) << error;
        if (reader.frames()[i].frameNumber == frame) return tracker.frameBatches();
    }
    ADD_FAILURE() << "no frame " << frame;
    return {};
}

size_t distinctModelviews(const std::vector<TrackedBatch>& batches)
{
    std::set<std::vector<float>> seen;
    for (const TrackedBatch& b : batches) {
        const float* m = &b.modelview[0][0];
        seen.emplace(m, m + 16);
    }
    return seen.size();
}

// One glBegin(GL_TRIANGLES) triangle at depth z (its vertices alone).
void writeTriangle(CallWriter& w, float z = -2.0f)
{
    w.op(op::glBegin);
    w.put<GLenum>(GL_TRIANGLES);
    for (float x : {0.0f, 1.0f, 0.0f}) {
        w.op(op::glVertex3f);
        for (float c : {x, x == 0.0f ? 0.0f : 1.0f, z}) w.put<float>(c);
    }
    w.op(op::glEnd);
}

// Ends the frame `w` holds (frame 1) and runs it through `tracker`.
void runOneFrame(CallWriter& w, StateTracker& tracker)
{
    w.op(op::kFrameEnd);
    w.put<uint64_t>(1);
    std::string error;
    ASSERT_TRUE(tracker.runFrame(w.data(), w.size(), nullptr, error)) << error;
}

} // namespace

TEST(StateTracker, GlxgearsDrawsThreeGearsFromItsDisplayLists)
{
    std::vector<TrackedBatch> batches = frameBatches("glxgears", 2);
    // Each gear list: front face, front teeth, back face, back teeth, outward faces, inside
    // cylinder.
    ASSERT_EQ(batches.size(), 18u);
    EXPECT_EQ(distinctModelviews(batches), 3u);
    std::set<uint32_t> materials;
    for (const TrackedBatch& b : batches) {
        EXPECT_TRUE(b.is3D);
        EXPECT_TRUE(b.hasNormals);
        materials.insert(b.materialId);
    }
    EXPECT_EQ(materials.size(), 3u);
    // The first gear is red: its lit colour is the material's diffuse.
    EXPECT_NEAR(batches[0].vertices[0].color.r, 0.8f, 1e-6f);
    EXPECT_NEAR(batches[0].vertices[0].color.g, 0.1f, 1e-6f);
}

TEST(StateTracker, ImmediateModeBatchesArePolygonalAndThreeDimensional)
{
    std::vector<TrackedBatch> batches = frameBatches("immediate", 2);
    ASSERT_EQ(batches.size(), 64u); // glBegin calls per frame of the demo
    std::set<GLenum> modes;
    for (const TrackedBatch& b : batches) {
        modes.insert(b.mode);
        EXPECT_TRUE(b.is3D);
        for (const TrackedVertex& v : b.vertices) ASSERT_TRUE(std::isfinite(v.position.x));
    }
    for (GLenum mode : {GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                        GL_QUAD_STRIP, GL_POLYGON}) {
        EXPECT_EQ(modes.count(mode), 1u) << mode;
    }
}

TEST(StateTracker, DisplayListSceneFollowsNestedAndCompileAndExecuteLists)
{
    std::vector<TrackedBatch> first = frameBatches("displaylist", 1);
    std::vector<TrackedBatch> third = frameBatches("displaylist", 3);
    ASSERT_FALSE(third.empty());
    // Frame 1 compiles the lists and draws them; later frames only call them: same geometry.
    EXPECT_EQ(first.size(), third.size());
    EXPECT_GE(distinctModelviews(third), 4u); // back plate and three gears
}

TEST(StateTracker, ClientArraysAndBuffersGiveTheSameGeometry)
{
    std::vector<TrackedBatch> client = frameBatches("arrays", 2);
    std::vector<TrackedBatch> vbo = frameBatches("arrays_vbo", 2);
    ASSERT_FALSE(client.empty());
    ASSERT_EQ(client.size(), vbo.size());
    for (size_t i = 0; i < client.size(); ++i) {
        ASSERT_EQ(client[i].vertices.size(), vbo[i].vertices.size()) << i;
        for (size_t k = 0; k < client[i].vertices.size(); ++k) {
            ASSERT_EQ(client[i].vertices[k].position, vbo[i].vertices[k].position) << i << "/" << k;
            ASSERT_EQ(client[i].vertices[k].normal, vbo[i].vertices[k].normal);
        }
    }
}

TEST(StateTracker, TheOverlayIsNotThreeDimensional)
{
    std::vector<TrackedBatch> batches = frameBatches("overlay", 1);
    size_t flat = 0, deep = 0;
    for (const TrackedBatch& b : batches) (b.is3D ? deep : flat)++;
    EXPECT_GT(deep, 0u);
    EXPECT_GT(flat, 0u); // the HUD panel and bar
}

TEST(StateTracker, VerticesCarryTheirBatchNormalFlagAndContentHash)
{
    // The compositor lends the vertices to the reconstruction as they are: each vertex's
    // hasNormal must be its batch's, and the hash taken at the draw that of the vertices.
    const std::pair<const char*, uint64_t> cases[] = {
        {"glxgears", 2}, {"immediate", 2}, {"displaylist", 3}, {"arrays", 2},
        {"arrays_vbo", 2}, {"overlay", 1}, {"character_skin", 2}, {"textured", 2}};
    for (const auto& [name, frame] : cases) {
        std::vector<TrackedBatch> batches = frameBatches(name, frame);
        ASSERT_FALSE(batches.empty()) << name;
        for (const TrackedBatch& b : batches) {
            for (const TrackedVertex& v : b.vertices) ASSERT_EQ(v.hasNormal, b.hasNormals) << name;
            const uint32_t mode = reconstruct::assemblyMode(b.mode, b.clockwise, b.quadCut);
            EXPECT_EQ(b.contentHash,
                      reconstruct::hashVertices(b.vertices.data(), b.vertices.size(), mode))
                << name;
        }
    }
}

TEST(StateTracker, StaticGeometryHashesTheSameEveryFrame)
{
    // The demo turns its shapes with the modelview only: the reconstruction cache must hit.
    std::vector<TrackedBatch> second = frameBatches("immediate", 2);
    std::vector<TrackedBatch> third = frameBatches("immediate", 3);
    ASSERT_EQ(second.size(), third.size());
    for (size_t i = 0; i < second.size(); ++i) {
        EXPECT_EQ(second[i].contentHash, third[i].contentHash) << i;
    }
}

TEST(StateTracker, TheFirstNormalInsideABatchCountsForItsEarlierVertices)
{
    CallWriter w;
    w.op(op::glBegin);
    w.put<GLenum>(GL_TRIANGLES);
    const float positions[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    for (int i = 0; i < 3; ++i) {
        if (i == 1) {
            w.op(op::glNormal3f);
            for (float c : {0.0f, 0.0f, 1.0f}) w.put<float>(c);
        }
        w.op(op::glVertex3f);
        for (float c : positions[i]) w.put<float>(c);
    }
    w.op(op::glEnd);
    StateTracker tracker;
    ASSERT_NO_FATAL_FAILURE(runOneFrame(w, tracker));
    ASSERT_EQ(tracker.frameBatches().size(), 1u);
    const TrackedBatch& b = tracker.frameBatches()[0];
    EXPECT_TRUE(b.hasNormals);
    for (const TrackedVertex& v : b.vertices) EXPECT_TRUE(v.hasNormal);
}

// A depth test at GL_ALWAYS hides nothing but still writes depth: dreamchess resets its depth
// buffer each frame with such a quad instead of glClear, and styled as a depth-tested object
// (with the styles' GL_LESS) it left the old depth in place, and the whole board failed it.
TEST(StateTracker, ADepthTestAtAlwaysIsNoTestButWritesDepth)
{
    CallWriter w;
    auto triangle = [&] { writeTriangle(w); };
    auto depthFunc = [&](GLenum f) {
        w.op(op::glDepthFunc);
        w.put<GLenum>(f);
    };
    w.op(op::glEnable);
    w.put<GLenum>(GL_DEPTH_TEST);
    triangle();
    w.op(op::glPushAttrib);
    w.put<GLbitfield>(GL_DEPTH_BUFFER_BIT);
    depthFunc(GL_ALWAYS);
    triangle();
    w.op(op::glPopAttrib); // back to GL_LESS
    triangle();
    StateTracker tracker;
    ASSERT_NO_FATAL_FAILURE(runOneFrame(w, tracker));
    const std::vector<TrackedBatch>& batches = tracker.frameBatches();
    ASSERT_EQ(batches.size(), 3u);
    EXPECT_TRUE(batches[0].depthTest);
    EXPECT_FALSE(batches[0].depthAlways);
    EXPECT_FALSE(batches[1].depthTest);
    EXPECT_TRUE(batches[1].depthAlways);
    EXPECT_TRUE(batches[1].depthWrite);
    EXPECT_TRUE(batches[2].depthTest) << "glPopAttrib(GL_DEPTH_BUFFER_BIT) restores the function";
    EXPECT_FALSE(batches[2].depthAlways);
}

TEST(StateTracker, AnUnlitDrawDoesNotTakeANormalLeftByAnotherObject)
{
    // Lit: glNormal, a triangle. Then unlit: a triangle without a normal of its own (the
    // terrain of a game whose light is baked into its texture), one with glNormal just before
    // it, and one lit again without one.
    CallWriter w;
    auto cap = [&](uint16_t opcode, GLenum c) {
        w.op(opcode);
        w.put<GLenum>(c);
    };
    auto triangle = [&](bool normal) {
        if (normal) {
            w.op(op::glNormal3f);
            for (float c : {0.0f, 0.0f, -1.0f}) w.put<float>(c);
        }
        writeTriangle(w);
    };
    cap(op::glEnable, GL_LIGHTING);
    triangle(true);
    cap(op::glDisable, GL_LIGHTING);
    triangle(false);
    triangle(true);
    cap(op::glEnable, GL_LIGHTING);
    triangle(false);
    StateTracker tracker;
    ASSERT_NO_FATAL_FAILURE(runOneFrame(w, tracker));
    const std::vector<TrackedBatch>& batches = tracker.frameBatches();
    ASSERT_EQ(batches.size(), 4u);
    const bool expected[4] = {true, false, true, true};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(batches[i].hasNormals, expected[i]) << i;
        for (const TrackedVertex& v : batches[i].vertices) EXPECT_EQ(v.hasNormal, expected[i]) << i;
    }
}

TEST(StateTracker, NothingIsHeldWhileTheAttributeStacksHaveNoRoomForTheStyles)
{
    StateTracker tracker;
    tracker.setHolding(true);
    tracker.setStackLimits(3, 2);
    std::string error;
    auto run = [&](auto&& write) {
        CallWriter w;
        write(w);
        ASSERT_TRUE(tracker.feed(w.data(), w.size(), nullptr, error)) << error;
    };
    run([](CallWriter& w) {
        w.op(op::glEnable);
        w.put<GLenum>(GL_DEPTH_TEST);
    });
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES));
    for (int i = 0; i < 3; ++i) {
        run([](CallWriter& w) {
            w.op(op::glPushAttrib);
            w.put<GLbitfield>(GL_CURRENT_BIT);
        });
    }
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    ASSERT_NE(tracker.unstylableState(), nullptr);
    EXPECT_STREQ(tracker.unstylableState(), "a full attribute stack");
    run([](CallWriter& w) { w.op(op::glPopAttrib); });
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES));
    for (int i = 0; i < 2; ++i) {
        run([](CallWriter& w) {
            w.op(op::glPushClientAttrib);
            w.put<GLbitfield>(GL_CLIENT_PIXEL_STORE_BIT);
        });
    }
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    run([](CallWriter& w) { w.op(op::glPopClientAttrib); });
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES));
}

// A call of two enums and a vector of values (glMaterialfv, glLightfv, glTexGenfv), written
// as the recorder writes it: one payload.
static void vectorCall(CallWriter& w, uint16_t opcode, GLenum a, GLenum b, const void* v,
                       size_t bytes)
{
    w.op(opcode);
    const size_t mark = w.beginPayload();
    w.put<GLenum>(a);
    w.put<GLenum>(b);
    w.putBytes(v, bytes);
    w.endPayload(mark);
}

// glTexImage2D of level 0 of the bound 2D texture, RGBA bytes, as the recorder writes it.
static void rgbaImage(CallWriter& w, GLint width, GLint height, const uint8_t* pixels)
{
    w.op(op::glTexImage2D);
    const size_t mark = w.beginPayload();
    for (GLint v : {GLint(GL_TEXTURE_2D), 0, GLint(GL_RGBA), width, height, 0}) w.put<GLint>(v);
    w.put<GLenum>(GL_RGBA);
    w.put<GLenum>(GL_UNSIGNED_BYTE);
    w.put<uint8_t>(1);
    w.putBytes(pixels, size_t(4 * width * height));
    w.endPayload(mark);
}

// glTexImage2D of level 0 of the bound 2D texture without pixels (storage only), then
// glTexSubImage2D of its lowest `rows` rows from RGBA bytes: SFML's way of making textures.
static void rgbaImageByPart(CallWriter& w, GLint width, GLint height, GLint rows,
                            const uint8_t* pixels)
{
    w.op(op::glTexImage2D);
    size_t mark = w.beginPayload();
    for (GLint v : {GLint(GL_TEXTURE_2D), 0, GLint(GL_RGBA), width, height, 0}) w.put<GLint>(v);
    w.put<GLenum>(GL_RGBA);
    w.put<GLenum>(GL_UNSIGNED_BYTE);
    w.put<uint8_t>(0); // no pixels: storage only
    w.endPayload(mark);
    w.op(op::glTexSubImage2D);
    mark = w.beginPayload();
    for (GLint v : {GLint(GL_TEXTURE_2D), 0, 0, 0, width, rows}) w.put<GLint>(v);
    w.put<GLenum>(GL_RGBA);
    w.put<GLenum>(GL_UNSIGNED_BYTE);
    w.put<uint8_t>(1);
    w.putBytes(pixels, size_t(4 * width * rows));
    w.endPayload(mark);
}

// Feeds a tracker calls written on the spot: the state tests' building blocks.
struct Feed {
    StateTracker& tracker;
    template <typename Write>
    void run(Write&& write)
    {
        CallWriter w;
        write(w);
        std::string error;
        ASSERT_TRUE(tracker.feed(w.data(), w.size(), nullptr, error)) << error;
    }
    void enable(GLenum cap, bool on)
    {
        run([&](CallWriter& w) {
            w.op(on ? op::glEnable : op::glDisable);
            w.put<GLenum>(cap);
        });
    }
    void depthMask(bool on)
    {
        run([&](CallWriter& w) {
            w.op(op::glDepthMask);
            w.put<GLboolean>(on ? GL_TRUE : GL_FALSE);
        });
    }
    void blendFunc(GLenum src, GLenum dst)
    {
        run([&](CallWriter& w) {
            w.op(op::glBlendFunc);
            w.put<GLenum>(src);
            w.put<GLenum>(dst);
        });
    }
    void activeTexture(GLenum unit)
    {
        run([&](CallWriter& w) {
            w.op(op::glActiveTexture);
            w.put<GLenum>(unit);
        });
    }
    // glTexEnvi(GL_TEXTURE_ENV, pname, value) on the active unit.
    void texEnv(GLenum pname, GLint value)
    {
        run([&](CallWriter& w) {
            w.op(op::glTexEnvi);
            w.put<GLenum>(GL_TEXTURE_ENV);
            w.put<GLenum>(pname);
            w.put<GLint>(value);
        });
    }
    // glMaterialfv(face, pname, v).
    void material(GLenum face, GLenum pname, std::array<float, 4> v)
    {
        run([&](CallWriter& w) {
            w.op(op::glMaterialfv);
            const size_t mark = w.beginPayload();
            w.put<GLenum>(face);
            w.put<GLenum>(pname);
            w.putBytes(v.data(), sizeof v);
            w.endPayload(mark);
        });
    }
    // Calls on GL_PROJECTION, then back to GL_MODELVIEW.
    template <typename Write>
    void projection(Write&& write)
    {
        run([&](CallWriter& w) {
            w.op(op::glMatrixMode);
            w.put<GLenum>(GL_PROJECTION);
            write(w);
            w.op(op::glMatrixMode);
            w.put<GLenum>(GL_MODELVIEW);
        });
    }
    // One triangle in immediate mode.
    void triangle()
    {
        run([](CallWriter& w) { writeTriangle(w, 0.0f); });
    }
    // A unit GL_QUADS quad at z -2, counter-clockwise from the origin, a normal per vertex.
    void quad(const std::array<glm::vec3, 4>& normals)
    {
        run([&](CallWriter& w) {
            w.op(op::glBegin);
            w.put<GLenum>(GL_QUADS);
            for (int k = 0; k < 4; ++k) {
                w.op(op::glNormal3f);
                for (int c = 0; c < 3; ++c) w.put<float>(normals[size_t(k)][c]);
                w.op(op::glVertex3f);
                for (float c : {k == 1 || k == 2 ? 1.0f : 0.0f, k >= 2 ? 1.0f : 0.0f, -2.0f}) {
                    w.put<float>(c);
                }
            }
            w.op(op::glEnd);
        });
    }
    // glBindTexture(GL_TEXTURE_2D, texture) on the active unit.
    void bindTexture(GLuint texture)
    {
        run([&](CallWriter& w) {
            w.op(op::glBindTexture);
            w.put<GLenum>(GL_TEXTURE_2D);
            w.put<GLuint>(texture);
        });
    }
};

// A side's polygon mode counts only where that side is drawn: lines for the back faces a
// program culls leave its filled front as it is (foobillardplus sets GL_BACK to GL_LINE and
// culls the back; all its table was left for "lines or points").
TEST(StateTracker, LinesForCulledFacesDoNotLeaveTheFilledSide)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto call = [&](uint16_t opcode, std::initializer_list<GLenum> args) {
        feed.run([&](CallWriter& w) {
            w.op(opcode);
            for (GLenum a : args) w.put<GLenum>(a);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    call(op::glPolygonMode, {GL_BACK, GL_LINE});
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES)) << "back faces drawn as lines";
    feed.enable(GL_CULL_FACE, true);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    call(op::glCullFace, {GL_FRONT});
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES)) << "the back, drawn as lines, is shown";
    call(op::glPolygonMode, {GL_FRONT_AND_BACK, GL_FILL});
    call(op::glPolygonMode, {GL_FRONT, GL_POINT});
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
}

// Materials set between glBegin and glEnd colour their own vertices (xscreensaver's cityflow
// sets one per box face inside one GL_QUADS batch; every box came out in the last one's
// colour), drawn directly and from a display list compiled so.
TEST(StateTracker, MaterialsInsideABatchColourTheirOwnVertices)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto material = [](CallWriter& w, glm::vec4 c) {
        vectorCall(w, op::glMaterialfv, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, &c, sizeof c);
    };
    const glm::vec4 red(1, 0, 0, 1), green(0, 1, 0, 1), blue(0, 0, 1, 1);
    // Blue before glBegin; red for the first triangle, green for the second.
    auto batch = [&](CallWriter& w) {
        material(w, blue);
        w.op(op::glBegin);
        w.put<GLenum>(GL_TRIANGLES);
        for (int t = 0; t < 2; ++t) {
            material(w, t == 0 ? red : green);
            for (float x : {0.0f, 1.0f, 0.0f}) {
                w.op(op::glVertex3f);
                for (float c : {x + 2.0f * float(t), x == 0.0f ? 0.0f : 1.0f, 0.0f}) {
                    w.put<float>(c);
                }
            }
        }
        w.op(op::glEnd);
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true);
    feed.run(batch);
    feed.run([&](CallWriter& w) {
        w.op(op::glNewList);
        w.put<GLuint>(1);
        w.put<GLenum>(GL_COMPILE);
        batch(w);
        w.op(op::glEndList);
        w.op(op::glCallList);
        w.put<GLuint>(1);
    });
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 2u);
    for (const TrackedBatch& b : batches) {
        ASSERT_EQ(b.vertices.size(), 6u);
        for (size_t i = 0; i < 6; ++i) {
            EXPECT_EQ(b.vertices[i].color, i < 3 ? red : green) << "vertex " << i;
        }
    }
}

// The held batches are writeTriangle's, one each, coloured `expected` in turn.
static void expectTriangleColours(StateTracker& tracker, const std::vector<glm::vec4>& expected)
{
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), expected.size());
    for (size_t b = 0; b < batches.size(); ++b) {
        ASSERT_EQ(batches[b].vertices.size(), 3u);
        for (int c = 0; c < 4; ++c) {
            EXPECT_NEAR(batches[b].vertices[0].color[c], expected[b][c], 1e-5f)
                << "batch " << b << " channel " << c;
        }
    }
}

// The light a material emits adds to its lit colour, as GL sums it (torcs's track: grey 0.4
// that emits 0.4 was drawn at 0.4, 2.5 times too dark), also under glColorMaterial; and
// glPopAttrib(GL_LIGHTING_BIT) takes it back.
TEST(StateTracker, AMaterialsEmissionAddsToItsLitColour)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto material = [](CallWriter& w, GLenum pname, glm::vec4 c) {
        vectorCall(w, op::glMaterialfv, GL_FRONT_AND_BACK, pname, &c, sizeof c);
    };
    const glm::vec4 grey(0.4f, 0.4f, 0.4f, 1.0f), glow(0.4f, 0.2f, 0.0f, 1.0f);
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true); // white: the lit side's light is white at full strength
    feed.run([&](CallWriter& w) {
        material(w, GL_AMBIENT_AND_DIFFUSE, grey);
        material(w, GL_EMISSION, glow);
        writeTriangle(w);
        w.op(op::glPushAttrib);
        w.put<GLbitfield>(GL_LIGHTING_BIT);
        material(w, GL_EMISSION, glm::vec4(0.0f, 0.0f, 0.5f, 1.0f));
        w.op(op::glPopAttrib);
        w.op(op::glEnable);
        w.put<GLenum>(GL_COLOR_MATERIAL);
        w.op(op::glColor3f);
        for (float c : {0.4f, 0.4f, 0.4f}) w.put<float>(c);
        writeTriangle(w);
        material(w, GL_EMISSION, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        writeTriangle(w);
    });
    expectTriangleColours(tracker, {{0.8f, 0.6f, 0.4f, 1.0f}, {0.8f, 0.6f, 0.4f, 1.0f}, grey});
}

// Under GL_COLOR_MATERIAL, glColor sets what glColorMaterial names: the diffuse colour (the
// default, and GL_DIFFUSE), the emission (added to the material's lit diffuse), or the
// ambient or specular colour (the material's diffuse is what shows).
TEST(StateTracker, ColourMaterialColoursWhatItsModeNames)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    const glm::vec4 grey(0.4f, 0.4f, 0.4f, 1.0f);
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true); // white
    feed.run([&](CallWriter& w) {
        vectorCall(w, op::glMaterialfv, GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, &grey,
                   sizeof grey);
        w.op(op::glEnable);
        w.put<GLenum>(GL_COLOR_MATERIAL);
        w.op(op::glColor3f);
        for (float c : {0.2f, 0.5f, 0.0f}) w.put<float>(c);
        for (GLenum mode : {GL_AMBIENT_AND_DIFFUSE, GL_EMISSION, GL_SPECULAR}) {
            w.op(op::glColorMaterial);
            w.put<GLenum>(GL_FRONT_AND_BACK);
            w.put<GLenum>(mode);
            writeTriangle(w);
        }
    });
    expectTriangleColours(tracker, {{0.2f, 0.5f, 0.0f, 1.0f}, {0.6f, 0.9f, 0.4f, 1.0f}, grey});
}

// Sphere mapping on unit 0: the surface is styled, without the generated texture; turning
// the generation off again gives the plain texture back (a program that sphere-maps one
// object must not leave every later draw unstyled). A texture on unit 1 layers over unit 0's.
// Generated coordinates reach the batch as GL would make them: the mode of S and T, the
// object plane as given, the eye plane in eye space by the modelview of its glTexGen call (not
// of the draw), and glPopAttrib(GL_TEXTURE_BIT) brings the modes and planes back.
TEST(StateTracker, GeneratedCoordinatesKeepTheirModesAndPlanes)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto run = [&](auto&& write) { feed.run(write); };
    auto mode = [&](GLenum coord, GLenum m) {
        run([&](CallWriter& w) {
            w.op(op::glTexGeni);
            w.put<GLenum>(coord);
            w.put<GLenum>(GL_TEXTURE_GEN_MODE);
            w.put<GLint>(GLint(m));
        });
    };
    auto plane = [&](GLenum coord, GLenum pname, glm::vec4 p) {
        run([&](CallWriter& w) { vectorCall(w, op::glTexGenfv, coord, pname, &p, sizeof p); });
    };
    auto translate = [&](float z) {
        run([&](CallWriter& w) {
            w.op(op::glTranslatef);
            for (float c : {0.0f, 0.0f, z}) w.put<float>(c);
        });
    };
    auto attrib = [&](bool push) {
        run([&](CallWriter& w) {
            w.op(push ? op::glPushAttrib : op::glPopAttrib);
            if (push) w.put<GLbitfield>(GL_TEXTURE_BIT);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true);
    run([](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLuint>(7);
    });
    feed.enable(GL_TEXTURE_GEN_S, true);
    feed.enable(GL_TEXTURE_GEN_T, true);
    translate(-5.0f);
    mode(GL_S, GL_OBJECT_LINEAR);
    plane(GL_S, GL_OBJECT_PLANE, glm::vec4(2, 0, 0, 1));
    plane(GL_T, GL_EYE_PLANE, glm::vec4(0, 0, 1, 0)); // T keeps GL's default, eye linear
    translate(-3.0f); // after the call: the eye plane stays where it was put
    feed.triangle();
    attrib(true);
    mode(GL_S, GL_SPHERE_MAP);
    mode(GL_T, GL_SPHERE_MAP);
    feed.triangle();
    feed.enable(GL_RESCALE_NORMAL, true); // the normals GL reflects the sphere map about
    feed.triangle();
    feed.enable(GL_NORMALIZE, true);
    feed.triangle();
    attrib(false);
    feed.enable(GL_NORMALIZE, false);
    feed.enable(GL_RESCALE_NORMAL, false);
    feed.triangle();
    mode(GL_T, GL_REFLECTION_MAP); // cube-map coordinates: no 2D map to show
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 6u);
    EXPECT_EQ(batches[1].normals, 0u) << "GL reflects about the normal as given";
    EXPECT_EQ(batches[2].normals, GLenum(GL_RESCALE_NORMAL));
    EXPECT_EQ(batches[3].normals, GLenum(GL_NORMALIZE)) << "GL_NORMALIZE wins";
    batches.erase(batches.begin() + 2, batches.begin() + 4);
    const styles::GeneratedTexture& g = batches[0].generated;
    EXPECT_EQ(g.texture, 7u);
    EXPECT_EQ(g.mode[0], GLenum(GL_OBJECT_LINEAR));
    EXPECT_EQ(g.mode[1], GLenum(GL_EYE_LINEAR));
    EXPECT_EQ(g.plane[0], glm::vec4(2, 0, 0, 1));
    // The object-space plane z = 0, moved 5 units away by the call's modelview: eye z = -5.
    EXPECT_EQ(g.plane[1], glm::vec4(0, 0, 1, 5));
    EXPECT_EQ(batches[1].generated.mode[0], GLenum(GL_SPHERE_MAP));
    EXPECT_EQ(batches[1].generated.mode[1], GLenum(GL_SPHERE_MAP));
    EXPECT_EQ(batches[2].generated.mode[0], GLenum(GL_OBJECT_LINEAR)) << "not popped";
    EXPECT_EQ(batches[2].generated.mode[1], GLenum(GL_EYE_LINEAR)) << "not popped";
    EXPECT_EQ(batches[3].generated.texture, 0u);
    for (const TrackedBatch& b : batches) EXPECT_EQ(b.texture, 0u);
}

TEST(StateTracker, GeneratedCoordinatesOnUnitZeroAreStyledWithoutTheirTexture)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto run = [&](auto&& write) { feed.run(write); };
    auto enable = [&](GLenum cap, bool on) { feed.enable(cap, on); };
    auto triangle = [&] { feed.triangle(); };
    enable(GL_DEPTH_TEST, true);
    enable(GL_TEXTURE_2D, true);
    run([](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLuint>(7);
    });
    enable(GL_TEXTURE_GEN_S, true);
    enable(GL_TEXTURE_GEN_T, true);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    // The generated unit is the surface's (drawn on generated coordinates), not a layer the
    // log says is dropped (it named unit 0 so for trigger-rally's terrain).
    EXPECT_EQ(tracker.droppedLayers(), 0u);
    triangle();
    enable(GL_TEXTURE_GEN_S, false);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES));
    triangle(); // T still generated: still not the surface's texture
    enable(GL_TEXTURE_GEN_T, false);
    triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 3u);
    EXPECT_EQ(batches[0].texture, 0u) << "the sphere map taken for the surface's texture";
    EXPECT_EQ(batches[1].texture, 0u);
    EXPECT_EQ(batches[2].texture, 7u) << "the plain texture did not come back";
    EXPECT_NE(batches[0].materialId, batches[2].materialId);

    run([](CallWriter& w) {
        w.op(op::glActiveTexture);
        w.put<GLenum>(GL_TEXTURE1);
    });
    // Generation on a unit that textures nothing changes nothing; with its texture on, unit 1
    // modulates the surface's texture (unit 0) on its own T: a lightmap, the light. With S and
    // T generated it is an effect layer, not drawn.
    enable(GL_TEXTURE_GEN_S, true);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    EXPECT_EQ(tracker.droppedLayers(), 0u);
    enable(GL_TEXTURE_2D, true);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    EXPECT_EQ(tracker.lightmapUnit(), 1);
    EXPECT_EQ(tracker.droppedLayers(), 0u);
    enable(GL_TEXTURE_GEN_T, true);
    EXPECT_EQ(tracker.lightmapUnit(), -1);
    EXPECT_EQ(tracker.droppedLayers(), 2u);
    enable(GL_TEXTURE_GEN_T, false);
    // A cube map as the surface's texture: not what the styles draw.
    run([](CallWriter& w) {
        w.op(op::glActiveTexture);
        w.put<GLenum>(GL_TEXTURE0);
    });
    enable(GL_TEXTURE_2D, false);
    enable(GL_TEXTURE_CUBE_MAP, true);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    ASSERT_NE(tracker.unstylableState(), nullptr);
    EXPECT_NE(std::string(tracker.unstylableState()).find("cube-map"), std::string::npos);
    enable(GL_TEXTURE_CUBE_MAP, false);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
}

// A reflective surface: an environment map (generated coordinates) on one unit under a
// combiner layer on another (neverball's rails: a shadow combined on unit 0, the sphere-mapped
// metal on unit 2) is styled without either texture. A combiner alone stays the program's.
TEST(StateTracker, AnEnvironmentMapUnderCombinedLayersIsStyledWithoutThem)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto unit = [&](GLenum u) { feed.activeTexture(u); };
    auto envMode = [&](GLint mode) { feed.texEnv(GL_TEXTURE_ENV_MODE, mode); };
    feed.enable(GL_DEPTH_TEST, true);
    envMode(GL_COMBINE);
    feed.enable(GL_TEXTURE_2D, true);
    ASSERT_FALSE(tracker.wouldHold(GL_TRIANGLES)) << "a combiner alone was styled";
    EXPECT_NE(std::string(tracker.unstylableState()).find("GL_COMBINE"), std::string::npos);
    unit(GL_TEXTURE2);
    feed.enable(GL_TEXTURE_2D, true);
    feed.enable(GL_TEXTURE_GEN_S, true);
    feed.enable(GL_TEXTURE_GEN_T, true);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    feed.triangle();
    // The same with a plain-looking but unsupported layer (GL_BLEND) under it: left.
    unit(GL_TEXTURE0);
    envMode(GL_BLEND);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, 0u) << "the sphere map taken for the surface's texture";
}

// Textures on object planes are the surface's own, per batch: a terrain drawn in tiles, each
// with its texture and planes of its own, welded into one object, took the first tile's
// planes for every tile (trigger-rally's terrain: one brown smear).
TEST(StateTracker, ObjectPlanesGiveEachBatchItsOwnCoordinates)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto run = [&](auto&& write) { feed.run(write); };
    auto planes = [&](float sOffset) {
        for (GLenum coord : {GLenum(GL_S), GLenum(GL_T)}) {
            run([&](CallWriter& w) {
                w.op(op::glTexGeni);
                w.put<GLenum>(coord);
                w.put<GLenum>(GL_TEXTURE_GEN_MODE);
                w.put<GLint>(GL_OBJECT_LINEAR);
            });
            const glm::vec4 p = coord == GL_S ? glm::vec4(0.5f, 0, 0, sOffset)
                                              : glm::vec4(0, 0.25f, 0, 0);
            run([&](CallWriter& w) {
                vectorCall(w, op::glTexGenfv, coord, GL_OBJECT_PLANE, &p, sizeof p);
            });
        }
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true);
    feed.enable(GL_TEXTURE_GEN_S, true);
    feed.enable(GL_TEXTURE_GEN_T, true);
    feed.bindTexture(7);
    planes(0.0f);
    feed.triangle();
    feed.bindTexture(8);
    planes(-1.0f);
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 2u);
    for (size_t i = 0; i < 2; ++i) {
        const TrackedBatch& b = batches[i];
        EXPECT_EQ(b.texture, GLuint(7 + i)) << i;
        EXPECT_EQ(b.generated.texture, 0u) << i;
        for (const TrackedVertex& v : b.vertices) {
            EXPECT_FLOAT_EQ(v.texcoord.x, 0.5f * v.position.x - float(i)) << i;
            EXPECT_FLOAT_EQ(v.texcoord.y, 0.25f * v.position.y) << i;
        }
    }
}

// A layer the styles do not draw keeps its average effect: a detail texture added signed over
// a terrain (trigger-rally) brightens it by its mean above one half; scaled by GL_RGB_SCALE;
// a combiner reading other sources is not followed (no effect assumed).
TEST(StateTracker, ALayerNotDrawnKeepsItsMeanEffect)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto run = [&](auto&& write) { feed.run(write); };
    auto env = [&](GLenum pname, GLint value) { feed.texEnv(pname, value); };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true); // unit 0: the surface (texture 0's image, below)
    feed.activeTexture(GL_TEXTURE1);
    feed.enable(GL_TEXTURE_2D, true);
    run([](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLuint>(9);
        // Half 0.5 grey, half white: mean 0.75.
        std::vector<uint8_t> texels(4 * 4 * 4, 255);
        for (size_t i = 0; i < 8; ++i) texels[4 * i] = texels[4 * i + 1] = texels[4 * i + 2] = 128;
        rgbaImage(w, 4, 4, texels.data());
    });
    env(GL_TEXTURE_ENV_MODE, GL_COMBINE);
    env(GL_COMBINE_RGB, GL_ADD_SIGNED);
    feed.triangle();
    env(GL_RGB_SCALE, 2);
    feed.triangle();
    env(GL_SOURCE1_RGB, GL_CONSTANT);
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 3u);
    const float mean = (8 * 128.0f / 255.0f + 8 * 1.0f) / 16.0f;
    EXPECT_EQ(batches[0].layerScale, glm::vec3(1.0f));
    EXPECT_NEAR(batches[0].layerOffset.r, mean - 0.5f, 1e-5f);
    EXPECT_EQ(batches[1].layerScale, glm::vec3(2.0f));
    EXPECT_NEAR(batches[1].layerOffset.g, 2.0f * (mean - 0.5f), 1e-5f);
    EXPECT_EQ(batches[2].layerScale, glm::vec3(1.0f));
    EXPECT_EQ(batches[2].layerOffset, glm::vec3(0.0f));
}

// A surface coloured by a cube map alone on reflection coordinates (criticalmass's crystal
// ship), which the styles do not draw, keeps its faces' mean tint instead of turning white.
TEST(StateTracker, ADroppedCubeMapKeepsItsMeanTint)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto run = [&](auto&& write) { feed.run(write); };
    run([](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_CUBE_MAP);
        w.put<GLuint>(11);
        for (GLenum face = 0; face < 6; ++face) {
            // Faces of blue (0, 0, 255) and white: mean (0.5, 0.5, 1).
            const uint8_t c = face % 2 ? 255 : 0;
            std::vector<uint8_t> texels(2 * 2 * 4, 255);
            for (size_t i = 0; i < 4; ++i) texels[4 * i] = texels[4 * i + 1] = c;
            w.op(op::glTexImage2D);
            const size_t mark = w.beginPayload();
            for (GLint v : {GLint(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GLint(GL_RGBA), 2,
                            2, 0}) {
                w.put<GLint>(v);
            }
            w.put<GLenum>(GL_RGBA);
            w.put<GLenum>(GL_UNSIGNED_BYTE);
            w.put<uint8_t>(1);
            w.putBytes(texels.data(), texels.size());
            w.endPayload(mark);
        }
    });
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_CUBE_MAP, true);
    for (GLenum coord : {GLenum(GL_S), GLenum(GL_T), GLenum(GL_R)}) {
        run([&](CallWriter& w) {
            w.op(op::glTexGeni);
            w.put<GLenum>(coord);
            w.put<GLenum>(GL_TEXTURE_GEN_MODE);
            w.put<GLint>(GL_REFLECTION_MAP);
        });
        feed.enable(GL_TEXTURE_GEN_S + (coord - GL_S), true);
    }
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, 0u);
    EXPECT_NEAR(batches[0].layerScale.r, 0.5f, 1e-3f);
    EXPECT_NEAR(batches[0].layerScale.b, 1.0f, 1e-3f);
}

// A draw textured by one unit other than 0 alone (units 0 and 1 off, 2 on: neverball draws
// its backgrounds so) is styled with that unit's texture and coordinates (glMultiTexCoord of
// that unit; array draws take its coordinate array, seen on neverball).
TEST(StateTracker, ADrawTexturedByAnotherUnitAloneTakesThatUnitsTextureAndCoordinates)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto run = [&](auto&& write) { feed.run(write); };
    auto unit = [&](GLenum u) {
        run([u](CallWriter& w) {
            w.op(op::glActiveTexture);
            w.put<GLenum>(u);
            w.op(op::glClientActiveTexture);
            w.put<GLenum>(u);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    unit(GL_TEXTURE2);
    feed.enable(GL_TEXTURE_2D, true);
    run([](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLuint>(9);
    });
    unit(GL_TEXTURE0);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    // Immediate mode: unit 2's coordinates, not unit 0's.
    run([](CallWriter& w) {
        w.op(op::glBegin);
        w.put<GLenum>(GL_TRIANGLES);
        for (float x : {0.0f, 1.0f, 0.0f}) {
            w.op(op::glTexCoord2f); // unit 0's: not what the draw textures with
            w.put<float>(0.9f);
            w.put<float>(0.9f);
            w.op(op::glMultiTexCoord2f);
            w.put<GLenum>(GL_TEXTURE2);
            w.put<float>(x);
            w.put<float>(0.25f);
            w.op(op::glVertex3f);
            for (float c : {x, x == 0.0f ? 0.0f : 1.0f, 0.0f}) w.put<float>(c);
        }
        w.op(op::glEnd);
    });
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, 9u);
    ASSERT_EQ(batches[0].vertices.size(), 3u);
    EXPECT_FLOAT_EQ(batches[0].vertices[1].texcoord.x, 1.0f);
    EXPECT_FLOAT_EQ(batches[0].vertices[1].texcoord.y, 0.25f);

    // Unit 0's texture on as well: the surface's is unit 0's, unit 2 modulates it with its own
    // coordinates: the lightmap that gives the styles their light.
    feed.enable(GL_TEXTURE_2D, true);
    run([](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLuint>(4);
    });
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    EXPECT_EQ(tracker.droppedLayers(), 0u);
    EXPECT_EQ(tracker.lightmapUnit(), 2);
    run([](CallWriter& w) {
        w.op(op::glBegin);
        w.put<GLenum>(GL_TRIANGLES);
        for (float x : {0.0f, 1.0f, 0.0f}) {
            w.op(op::glMultiTexCoord2f);
            w.put<GLenum>(GL_TEXTURE2);
            w.put<float>(0.5f);
            w.put<float>(x);
            w.op(op::glVertex3f);
            for (float c : {x, x == 0.0f ? 0.0f : 1.0f, 0.0f}) w.put<float>(c);
        }
        w.op(op::glEnd);
    });
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, 4u);
    EXPECT_EQ(batches[0].lightmap, 9u);
    ASSERT_EQ(batches[0].vertices.size(), 3u);
    EXPECT_FLOAT_EQ(batches[0].vertices[1].lightcoord.x, 0.5f);
    EXPECT_FLOAT_EQ(batches[0].vertices[1].lightcoord.y, 1.0f);
}

// Lights other than GL_LIGHT0: the brightest enabled one gives the direction, and the lights'
// colours tint lit surfaces (a floor under a green GL_LIGHT1 is not white when styled).
TEST(StateTracker, TheBrightestEnabledLightAndTheLightsColoursReachTheBatch)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto run = [&](auto&& write) { feed.run(write); };
    auto enable = [&](GLenum cap, bool on) { feed.enable(cap, on); };
    auto lightfv = [&](GLenum light, GLenum pname, std::array<float, 4> v) {
        run([&](CallWriter& w) { vectorCall(w, op::glLightfv, light, pname, v.data(), sizeof v); });
    };
    auto triangle = [&] { feed.triangle(); };
    enable(GL_DEPTH_TEST, true);
    enable(GL_LIGHTING, true);
    enable(GL_LIGHT1, true); // light 0 stays off
    lightfv(GL_LIGHT1, GL_DIFFUSE, {0.2f, 0.9f, 0.2f, 1.0f});
    lightfv(GL_LIGHT1, GL_POSITION, {1.0f, 0.0f, 0.0f, 0.0f});
    triangle();
    enable(GL_LIGHT0, true); // white: now the brightest, and the tint goes towards white
    triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 2u);
    ASSERT_GT(batches[0].lights.count, 0u);
    EXPECT_EQ(batches[0].lights.lights[0].position, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
    const glm::vec4 green = batches[0].vertices[0].color;
    EXPECT_GT(green.g, green.r + 0.4f) << "the green light did not tint the white material";
    ASSERT_GT(batches[1].lights.count, 0u);
    EXPECT_EQ(batches[1].lights.lights[0].position, glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
    const glm::vec4 mixed = batches[1].vertices[0].color;
    EXPECT_GT(mixed.r, green.r + 0.2f);
    EXPECT_LT(mixed.g - mixed.r, green.g - green.r);
}

// The ambient light counts in the light of a lit surface as in GL's sum: a pinkish sun over a
// bluish ambient lights a white material white, not pink; the light model's ambient too; and
// glLightiv's integer colours map onto 0..1.
TEST(StateTracker, AmbientLightTintsLitSurfacesToo)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto put = [&](uint16_t opcode, GLenum a, GLenum b, const void* v, size_t bytes) {
        feed.run([&](CallWriter& w) {
            w.op(opcode);
            const size_t mark = w.beginPayload();
            if (opcode != op::glLightModelfv) w.put<GLenum>(a);
            w.put<GLenum>(b);
            w.putBytes(v, bytes);
            w.endPayload(mark);
        });
    };
    auto lightfv = [&](GLenum pname, std::array<float, 4> v) {
        put(op::glLightfv, GL_LIGHT0, pname, v.data(), sizeof v);
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true);
    lightfv(GL_DIFFUSE, {1.0f, 0.8f, 1.0f, 1.0f});
    feed.triangle();
    lightfv(GL_AMBIENT, {0.2f, 0.4f, 0.9f, 1.0f});
    feed.triangle();
    const std::array<float, 4> dark = {0.0f, 0.0f, 0.0f, 1.0f};
    put(op::glLightModelfv, 0, GL_LIGHT_MODEL_AMBIENT, dark.data(), sizeof dark);
    const std::array<GLint, 4> blue = {0, 0, 2147483647, 2147483647};
    put(op::glLightiv, GL_LIGHT0, GL_AMBIENT, blue.data(), sizeof blue);
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 3u);
    const glm::vec4 sun = batches[0].vertices[0].color;
    const glm::vec4 sky = batches[1].vertices[0].color;
    const glm::vec4 deep = batches[2].vertices[0].color;
    EXPECT_LT(sun.g, sun.b - 0.1f) << "the pinkish light alone tints pink";
    EXPECT_GE(sky.g, sky.r - 0.01f) << "a bluish ambient takes the pink out";
    EXPECT_GE(sky.b, sun.b) << "the ambient light took light away";
    // Without the model's ambient the blue light ambient weighs more: bluer than before.
    EXPECT_LT(deep.r, sky.r - 0.1f);
    EXPECT_GT(deep.r, 0.3f) << "glLightiv's integer colour was taken as a huge number";
}

// For the replica style, lit vertices take the colour GL's lighting equation gives them
// (emission, the scene's ambient on the material's ambient, N·L on the diffuse), not the
// material's colour the shading styles shade from; two-sided lighting lights a normal turned
// from the eye from its other side; GL_FLAT gives a quad its last vertex's colour.
// A tracker that holds its batches, with the depth test, GL lighting and light 0 on, and
// quads facing the eye.
struct LitFeed {
    StateTracker tracker;
    Feed feed{tracker};
    LitFeed()
    {
        tracker.setHolding(true);
        feed.enable(GL_DEPTH_TEST, true);
        feed.enable(GL_LIGHTING, true);
        feed.enable(GL_LIGHT0, true);
    }
    void quad()
    {
        const glm::vec3 towardsEye(0.0f, 0.0f, 1.0f);
        feed.quad({towardsEye, towardsEye, towardsEye, towardsEye});
    }
};

// How dark the program's own shadowed side is, as a share of the lit colour the styles get:
// GL's emission and ambient terms over the lit side's colour. cubestorm's faces turned from
// its light are nearly black (0.2 of its colour: GL's default scene ambient, no light
// ambient), and the cartoon's shadow band at 0.55 of the colour lit them brighter than the
// faces towards the light. A strong ambient gives a large share, emission adds to it.
TEST(StateTracker, TheShadowedSidesShareOfTheLitColourIsGlsAmbient)
{
    LitFeed lighting;
    Feed& feed = lighting.feed;
    auto quad = [&] { lighting.quad(); };
    // GL's defaults: ambient material 0.2, diffuse 0.8, scene ambient 0.2, light 0 white.
    quad();
    feed.material(GL_FRONT_AND_BACK, GL_AMBIENT, {0.8f, 0.8f, 0.8f, 1.0f});
    feed.run([](CallWriter& w) {
        const std::array<float, 4> ambient = {0.5f, 0.5f, 0.5f, 1.0f};
        w.op(op::glLightModelfv);
        const size_t mark = w.beginPayload();
        w.put<GLenum>(GL_LIGHT_MODEL_AMBIENT);
        w.putBytes(ambient.data(), sizeof ambient);
        w.endPayload(mark);
    });
    quad();
    feed.enable(GL_LIGHTING, false);
    quad();
    std::vector<TrackedBatch> batches;
    lighting.tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 3u);
    // The lit side: diffuse 0.8 in the light at full strength plus the ambient 0.04 (GL sums
    // ambient, diffuse at N.L 0.75, normalised to 1); unlit, 0.2 x 0.2 of it.
    const float lit = batches[0].vertices[0].color.r;
    EXPECT_NEAR(batches[0].lights.ambientShare, 0.04f / lit, 0.01f);
    EXPECT_LT(batches[0].lights.ambientShare, 0.1f);
    EXPECT_NEAR(batches[1].lights.ambientShare,
                std::min(0.4f / batches[1].vertices[0].color.r, 1.0f), 0.02f);
    EXPECT_GT(batches[1].lights.ambientShare, 0.3f);
    EXPECT_LT(batches[2].lights.ambientShare, 0.0f) << "unlit: no share known";
}

// The shadowed side's hue is GL's unlit colour's, not the lit side's darkened: under a yellow
// light a cream material is yellow where lit and keeps its cream (the white ambient's) where
// not. extrusion's tubes were a dark green instead of GL's olive.
TEST(StateTracker, TheShadowedSideKeepsTheHueOfGlsUnlitColour)
{
    auto lights = [](std::array<float, 4> diffuse) {
        LitFeed lighting;
        lighting.feed.run([&](CallWriter& w) {
            vectorCall(w, op::glLightfv, GL_LIGHT0, GL_DIFFUSE, diffuse.data(), sizeof diffuse);
        });
        lighting.feed.material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE,
                               {0.6f, 0.6f, 0.4f, 1.0f});
        lighting.quad();
        std::vector<TrackedBatch> batches;
        lighting.tracker.takeBatches(batches);
        return batches.at(0);
    };
    auto luma = [](glm::vec3 c) { return 0.299f * c.r + 0.587f * c.g + 0.114f * c.b; };
    const TrackedBatch yellow = lights({1.0f, 1.0f, 0.0f, 1.0f});
    const glm::vec3 lit(yellow.vertices[0].color);
    const glm::vec3 shadow = lit * yellow.lights.shadowTint;
    const glm::vec3 unlit = 0.2f * glm::vec3(0.6f, 0.6f, 0.4f); // GL's: the scene's ambient
    EXPECT_LT(lit.b / lit.r, 0.3f) << "yellow where lit";
    EXPECT_NEAR(shadow.b / shadow.r, unlit.b / unlit.r, 0.02f) << "GL's cream where not";
    EXPECT_NEAR(luma(shadow), luma(lit), 0.01f) << "a hue: ambientShare says how dark";
    const TrackedBatch white = lights({1.0f, 1.0f, 1.0f, 1.0f});
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(white.lights.shadowTint[c], 1.0f, 1e-3f) << c;
    // A colour without blue (crackberg's terrain, colour material) darkens evenly in a white
    // light: the channel it lacks does not turn its shadow blue or purple.
    LitFeed lighting;
    lighting.feed.enable(GL_COLOR_MATERIAL, true);
    lighting.feed.run([](CallWriter& w) {
        w.op(op::glColor3f);
        for (float c : {0.5f, 0.3f, 0.0f}) w.put<float>(c);
    });
    lighting.quad();
    std::vector<TrackedBatch> batches;
    lighting.tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    const glm::vec3 even = batches[0].lights.shadowTint;
    EXPECT_NEAR(even.b, even.r, 1e-3f) << "the missing channel tints the shadow";
    EXPECT_NEAR(even.g, even.r, 1e-3f);
}

// Two-sided lighting with a back unlike the front: the faces the window shows wound the other
// way take the back's colour in the shading styles too, as GL colours them.
TEST(StateTracker, TwoSidedLightingShowsTheBacksColourOnFacesWoundTheOtherWay)
{
    LitFeed lighting;
    Feed& feed = lighting.feed;
    feed.run([](CallWriter& w) {
        w.op(op::glLightModeli);
        w.put<GLenum>(GL_LIGHT_MODEL_TWO_SIDE);
        w.put<GLint>(1);
    });
    feed.material(GL_FRONT, GL_DIFFUSE, {0.8f, 0.0f, 0.0f, 1.0f});
    feed.material(GL_BACK, GL_DIFFUSE, {0.0f, 0.0f, 0.8f, 1.0f});
    lighting.quad();
    feed.run([](CallWriter& w) { w.op(op::glFrontFace), w.put<GLenum>(GL_CW); });
    lighting.quad();
    std::vector<TrackedBatch> batches;
    lighting.tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 2u);
    const glm::vec4 front = batches[0].vertices[0].color, back = batches[1].vertices[0].color;
    EXPECT_GT(front.r, 0.5f);
    EXPECT_LT(front.b, 0.1f);
    EXPECT_GT(back.b, 0.5f) << "the back material";
    EXPECT_LT(back.r, 0.1f);
}

// A positional light whose attenuation brightens it near a surface (a constant factor of 0.1:
// ten times its colour one unit away, antmaze's lights) lights the surface's lit side that
// much brighter, as GL does before it clamps: the styles' colour for it was the material's
// at one light's strength, darker than GL's picture (antmaze's floor).
TEST(StateTracker, ALightAttenuatedBelowOneBrightensTheLitSide)
{
    auto litColour = [](float constant) {
        LitFeed lighting;
        Feed& feed = lighting.feed;
        feed.run([&](CallWriter& w) {
            const std::array<float, 4> position = {0.0f, 0.0f, 1.0f, 1.0f}; // at the eye
            vectorCall(w, op::glLightfv, GL_LIGHT0, GL_POSITION, position.data(),
                       sizeof position);
            vectorCall(w, op::glLightfv, GL_LIGHT0, GL_CONSTANT_ATTENUATION, &constant,
                       sizeof constant);
        });
        feed.material(GL_FRONT_AND_BACK, GL_DIFFUSE, {0.3f, 0.3f, 0.3f, 1.0f});
        lighting.quad();
        std::vector<TrackedBatch> batches;
        lighting.tracker.takeBatches(batches);
        return batches.size() == 1 ? batches[0].vertices[0].color.r : -1.0f;
    };
    const float plain = litColour(1.0f);
    ASSERT_GT(plain, 0.0f);
    EXPECT_NEAR(plain, 0.3f, 0.05f) << "the material's colour at one light's strength";
    EXPECT_GT(litColour(0.1f), 0.9f) << "ten times the light: GL's clamped white";
}

// What the toon's bands need to follow GL's own light (ToonStyle, toon.bands=program): how
// much the brightest light adds facing a surface head-on, as a share of the lit colour; GL's
// highlight colour and exponent; two-sided lighting. A black material's share is 1 (no light
// makes it lighter): before it was "not known", and the thesis's highlight band, white mixed
// into its colour, drew sonar's black disc grey.
TEST(StateTracker, LitBatchesCarryWhatTheBandsFollowOfGlsLight)
{
    LitFeed lighting;
    Feed& feed = lighting.feed;
    auto quad = [&] { lighting.quad(); };
    auto light = [&](GLenum pname, std::array<float, 4> v) {
        feed.run([&](CallWriter& w) {
            vectorCall(w, op::glLightfv, GL_LIGHT0, pname, v.data(), sizeof v);
        });
    };
    light(GL_SPECULAR, {0.5f, 1.0f, 1.0f, 1.0f});
    quad(); // GL's default material: no specular
    feed.material(GL_FRONT_AND_BACK, GL_SPECULAR, {1.0f, 0.5f, 1.0f, 1.0f});
    feed.run([](CallWriter& w) {
        const float shininess = 20.0f;
        vectorCall(w, op::glMaterialfv, GL_FRONT_AND_BACK, GL_SHININESS, &shininess,
                   sizeof shininess);
    });
    light(GL_DIFFUSE, {0.5f, 0.5f, 0.5f, 1.0f});
    quad();
    feed.material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, {0.0f, 0.0f, 0.0f, 1.0f});
    quad();
    feed.run([](CallWriter& w) {
        const float on = 1.0f;
        w.op(op::glLightModelfv);
        const size_t mark = w.beginPayload();
        w.put<GLenum>(GL_LIGHT_MODEL_TWO_SIDE);
        w.putBytes(&on, sizeof on);
        w.endPayload(mark);
    });
    quad();
    std::vector<TrackedBatch> batches;
    lighting.tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 4u);
    const styles::SceneLights& matte = batches[0].lights;
    const styles::SceneLights& shiny = batches[1].lights;
    EXPECT_EQ(matte.shine, glm::vec3(0.0f)) << "a material without specular shines";
    EXPECT_NEAR(shiny.shine.r, 0.5f, 1e-5f);
    EXPECT_NEAR(shiny.shine.g, 0.5f, 1e-5f);
    EXPECT_NEAR(shiny.shine.b, 1.0f, 1e-5f);
    EXPECT_FLOAT_EQ(shiny.shininess, 20.0f);
    // The default material's diffuse 0.8 in the white light against its lit colour (the
    // light at full strength); half as much under the half-bright light, whose lit colour
    // the styles get at full strength too.
    const float lit = batches[0].vertices[0].color.r;
    EXPECT_NEAR(matte.diffuseShare, 0.8f / lit, 0.02f);
    EXPECT_NEAR(shiny.diffuseShare, 0.5f * matte.diffuseShare, 0.02f);
    EXPECT_FLOAT_EQ(batches[2].lights.ambientShare, 1.0f) << "a black material's share";
    EXPECT_FALSE(batches[2].lights.twoSide);
    EXPECT_TRUE(batches[3].lights.twoSide);
}

// glMaterial(GL_AMBIENT_AND_DIFFUSE) between glBegin and glEnd sets the ambient of the
// vertices after it too, and the vertices before the first change have the material of
// glBegin, not the one left after glEnd (skytentacles colours its tentacles vertex by vertex;
// the replica lit their shadowed sides with the last material's ambient).
TEST(StateTracker, MaterialsInsideBeginEndSetTheAmbientToo)
{
    StateTracker tracker;
    tracker.setHolding(true);
    tracker.setProgramLighting(true);
    Feed feed{tracker};
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true);
    feed.material(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, {0.0f, 0.0f, 1.0f, 1.0f}); // at glBegin
    const std::array<float, 4> red = {1.0f, 0.0f, 0.0f, 1.0f}, green = {0.0f, 1.0f, 0.0f, 1.0f};
    feed.run([&](CallWriter& w) {
        auto material = [&](const std::array<float, 4>& v) {
            w.op(op::glMaterialfv);
            const size_t mark = w.beginPayload();
            w.put<GLenum>(GL_FRONT);
            w.put<GLenum>(GL_AMBIENT_AND_DIFFUSE);
            w.putBytes(v.data(), sizeof v);
            w.endPayload(mark);
        };
        w.op(op::glBegin);
        w.put<GLenum>(GL_QUADS);
        for (int k = 0; k < 4; ++k) {
            if (k == 1) material(red);
            if (k == 3) material(green);
            // Turned from the light (at +z): GL shows the ambient terms alone.
            w.op(op::glNormal3f);
            for (float c : {0.0f, 0.0f, -1.0f}) w.put<float>(c);
            w.op(op::glVertex3f);
            for (float c : {k == 1 || k == 2 ? 1.0f : 0.0f, k >= 2 ? 1.0f : 0.0f, -2.0f}) {
                w.put<float>(c);
            }
        }
        w.op(op::glEnd);
    });
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    const auto& v = batches[0].vertices;
    ASSERT_EQ(v.size(), 4u);
    // GL's scene ambient 0.2 on each vertex's ambient material.
    EXPECT_NEAR(v[0].color.b, 0.2f, 0.01f) << "the material at glBegin";
    EXPECT_NEAR(v[0].color.g, 0.0f, 0.01f) << "the material left after glEnd";
    EXPECT_NEAR(v[1].color.r, 0.2f, 0.01f);
    EXPECT_NEAR(v[2].color.r, 0.2f, 0.01f);
    EXPECT_NEAR(v[3].color.g, 0.2f, 0.01f);
    EXPECT_NEAR(v[3].color.r, 0.0f, 0.01f);
}

TEST(StateTracker, ProgramLightingGivesGlsColoursPerVertex)
{
    StateTracker tracker;
    tracker.setHolding(true);
    tracker.setProgramLighting(true);
    Feed feed{tracker};
    auto material = [&](GLenum pname, std::array<float, 4> v) {
        feed.material(GL_FRONT_AND_BACK, pname, v);
    };
    // A quad at z -2 whose vertices' normals turn from the eye (0 degrees) to 60 degrees off
    // it, and the last one away from it.
    const float s60 = std::sqrt(3.0f) / 2.0f;
    const std::array<glm::vec3, 4> normals = {glm::vec3(0, 0, 1), glm::vec3(s60, 0, 0.5f),
                                              glm::vec3(1, 0, 0), glm::vec3(0, 0, -1)};
    auto quad = [&] { feed.quad(normals); };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true);
    material(GL_AMBIENT, {0.2f, 0.1f, 0.1f, 1.0f});
    material(GL_DIFFUSE, {0.5f, 0.2f, 0.1f, 1.0f});
    material(GL_EMISSION, {0.0f, 0.0f, 0.25f, 1.0f});
    quad();
    feed.run([](CallWriter& w) {
        w.op(op::glLightModeli);
        w.put<GLenum>(GL_LIGHT_MODEL_TWO_SIDE);
        w.put<GLint>(1);
    });
    quad();
    feed.run([](CallWriter& w) {
        w.op(op::glShadeModel);
        w.put<GLenum>(GL_FLAT);
    });
    quad();
    // The back's own material lights the side the window shows wound clockwise
    // (splodesic's yellow insides), from the other side of the normal.
    feed.run([](CallWriter& w) { w.op(op::glShadeModel), w.put<GLenum>(GL_SMOOTH); });
    feed.material(GL_BACK, GL_DIFFUSE, {0.0f, 1.0f, 0.0f, 1.0f});
    feed.run([](CallWriter& w) { w.op(op::glFrontFace), w.put<GLenum>(GL_CW); });
    quad();
    feed.run([](CallWriter& w) { w.op(op::glFrontFace), w.put<GLenum>(GL_CCW); });
    // A strip folded over itself: its second triangle shows its back, whatever its normals
    // say (extrusion's tubes face the eye with normals pointing out of their backs).
    feed.run([](CallWriter& w) {
        w.op(op::glBegin);
        w.put<GLenum>(GL_TRIANGLE_STRIP);
        w.op(op::glNormal3f);
        for (float c : {0.0f, 0.0f, 1.0f}) w.put<float>(c);
        for (const glm::vec2 p : {glm::vec2(0, 0), glm::vec2(1, 0), glm::vec2(0, 1),
                                  glm::vec2(-1, 0)}) {
            w.op(op::glVertex3f);
            for (float c : {p.x, p.y, -2.0f}) w.put<float>(c);
        }
        w.op(op::glEnd);
    });
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 5u);
    // The scene's ambient (GL's 0.2) on the material's ambient, plus N·L on the diffuse.
    auto expected = [](float nl) {
        return glm::vec3(0.2f * 0.2f, 0.2f * 0.1f, 0.2f * 0.1f + 0.25f) +
               nl * glm::vec3(0.5f, 0.2f, 0.1f);
    };
    const glm::vec4 inside = batches[3].vertices[3].color;
    EXPECT_GT(inside.g, 0.9f) << "the back material, lit along the reversed normal";
    EXPECT_LT(inside.r, 0.1f);
    // Its first vertex's normal faces the eye: the back is lit from behind, ambient only.
    EXPECT_NEAR(batches[3].vertices[0].color.r, expected(0.0f).r, 1e-4f);
    EXPECT_NEAR(batches[3].vertices[0].color.g, expected(0.0f).g, 1e-4f);
    const std::vector<TrackedVertex>& folded = batches[4].vertices;
    ASSERT_EQ(folded.size(), 6u) << "the strip's triangles apart";
    EXPECT_EQ(batches[4].mode, GLenum(GL_TRIANGLES));
    for (size_t k = 0; k < 3; ++k) {
        EXPECT_NEAR(folded[k].color.r, expected(1.0f).r, 1e-4f) << "front " << k;
        EXPECT_NEAR(folded[3 + k].color.r, expected(0.0f).r, 1e-4f) << "back " << k;
        EXPECT_NEAR(folded[3 + k].color.g, expected(0.0f).g, 1e-4f) << "back " << k;
    }
    const std::vector<TrackedVertex>& one = batches[0].vertices;
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(one[0].color[c], expected(1.0f)[c], 1e-4f) << c;
        EXPECT_NEAR(one[1].color[c], expected(0.5f)[c], 1e-4f) << c;
        EXPECT_NEAR(one[2].color[c], expected(0.0f)[c], 1e-4f) << c;
        EXPECT_NEAR(one[3].color[c], expected(0.0f)[c], 1e-4f) << "one-sided: unlit back";
        EXPECT_NEAR(batches[1].vertices[3].color[c], expected(0.0f)[c], 1e-4f)
            << "two-sided: the front faces the window, so its front is lit, dark there";
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(batches[2].vertices[size_t(k)].color[c], expected(0.0f)[c], 1e-4f)
                << "flat: the quad's last vertex (its front turned from the light) provokes "
                   "its colour";
        }
    }
}

// glColorMaterial(GL_BACK, ...) leaves the front its material: extrusion names the front,
// then the back, and its yellow material came out in its cyan glColor in every style.
TEST(StateTracker, ColourMaterialOnTheBackLeavesTheFrontItsMaterial)
{
    for (const bool program : {false, true}) {
        StateTracker tracker;
        tracker.setHolding(true);
        tracker.setProgramLighting(program);
        Feed feed{tracker};
        feed.enable(GL_DEPTH_TEST, true);
        feed.enable(GL_LIGHTING, true);
        feed.enable(GL_LIGHT0, true);
        feed.enable(GL_COLOR_MATERIAL, true);
        feed.material(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, {0.6f, 0.6f, 0.2f, 1.0f});
        feed.run([](CallWriter& w) {
            for (const GLenum face : {GLenum(GL_FRONT), GLenum(GL_BACK)}) {
                w.op(op::glColorMaterial);
                w.put<GLenum>(face);
                w.put<GLenum>(GL_DIFFUSE);
            }
            w.op(op::glColor3f);
            for (float c : {0.1f, 0.6f, 0.6f}) w.put<float>(c);
            w.op(op::glBegin);
            w.put<GLenum>(GL_TRIANGLES);
            for (int k = 0; k < 3; ++k) {
                w.op(op::glNormal3f);
                for (float c : {0.0f, 0.0f, 1.0f}) w.put<float>(c);
                w.op(op::glVertex3f);
                for (float c : {k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f, -2.0f}) w.put<float>(c);
            }
            w.op(op::glEnd);
        });
        std::vector<TrackedBatch> batches;
        tracker.takeBatches(batches);
        ASSERT_EQ(batches.size(), 1u);
        const glm::vec4 c = batches[0].vertices[0].color;
        EXPECT_GT(c.r, c.b + 0.2f) << (program ? "replica: " : "styles: ")
                                   << "the front took the glColor (" << c.r << ", " << c.g
                                   << ", " << c.b << ")";
    }
}

// A lit batch whose every vertex shows the program's specular light shows it all over (a flat
// face near the mirror angle: sproingies' pale lavender stairs, a dark navy material made pale
// by its shine, were dark navy in every style): the least of it over the batch is added to
// its colours. Where one vertex has none (a curved surface turning from the light) nothing
// is added: that highlight is the styles' own band. A light without specular adds none.
TEST(StateTracker, ASpecularLightShownEvenlyOverABatchBrightensIt)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    // glMaterialfv or glLightfv: (which, pname, four values).
    auto vector = [&](uint16_t opcode, GLenum which, GLenum pname, std::array<float, 4> v) {
        feed.run([&](CallWriter& w) {
            w.op(opcode);
            const size_t mark = w.beginPayload();
            w.put<GLenum>(which);
            w.put<GLenum>(pname);
            w.putBytes(v.data(), sizeof v);
            w.endPayload(mark);
        });
    };
    auto material = [&](GLenum pname, std::array<float, 4> v) {
        feed.material(GL_FRONT_AND_BACK, pname, v);
    };
    // A flat triangle facing the eye, and one whose third normal turns across the light
    // (the default light 0 shines along the view: its half-vector is the view's).
    auto triangle = [&](bool turning) {
        feed.run([&](CallWriter& w) {
            w.op(op::glBegin);
            w.put<GLenum>(GL_TRIANGLES);
            for (int k = 0; k < 3; ++k) {
                w.op(op::glNormal3f);
                for (float c : {turning && k == 2 ? 1.0f : 0.0f, 0.0f,
                                turning && k == 2 ? 0.0f : 1.0f}) {
                    w.put<float>(c);
                }
                w.op(op::glVertex3f);
                for (float c : {k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f, -2.0f}) w.put<float>(c);
            }
            w.op(op::glEnd);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true);
    material(GL_AMBIENT_AND_DIFFUSE, {0.15f, 0.15f, 0.4f, 1.0f});
    triangle(false);
    material(GL_SPECULAR, {0.5f, 0.5f, 0.5f, 1.0f});
    feed.run([](CallWriter& w) {
        w.op(op::glMateriali);
        w.put<GLenum>(GL_FRONT_AND_BACK);
        w.put<GLenum>(GL_SHININESS);
        w.put<GLint>(50);
    });
    triangle(false);
    triangle(true);
    vector(op::glLightfv, GL_LIGHT0, GL_SPECULAR, {0.0f, 0.0f, 0.0f, 1.0f});
    triangle(false);
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 4u);
    const glm::vec4 matte = batches[0].vertices[0].color;
    const glm::vec4 shiny = batches[1].vertices[2].color;
    EXPECT_LT(matte.r, 0.5f) << "no dark material: no test";
    EXPECT_NEAR(shiny.r, std::min(matte.r + 0.5f, 1.0f), 0.02f) << "the even shine is missing";
    EXPECT_NEAR(shiny.b, std::min(matte.b + 0.5f, 1.0f), 0.02f);
    EXPECT_NEAR(batches[2].vertices[0].color.r, matte.r, 0.02f) << "an uneven shine was added";
    EXPECT_NEAR(batches[3].vertices[0].color.r, matte.r, 0.02f) << "a light without specular";
}

// glMateriali sets the shininess as glMaterialf does (xscreensaver's cubestorm and the
// involute gears set it so, 128). Not followed, the shininess stayed GL's default 0, whose
// specular term is 1 wherever a face is lit: their cyan specular light turned every face of
// cubestorm's many-coloured cubes cyan. Under 128 a face turned 30 degrees from the mirror
// angle shows no shine.
TEST(StateTracker, GlMaterialiSetsTheShininess)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto vector = [&](uint16_t opcode, GLenum which, GLenum pname, std::array<float, 4> v) {
        feed.run([&](CallWriter& w) { vectorCall(w, opcode, which, pname, v.data(), sizeof v); });
    };
    auto shininess = [&](GLint exponent) {
        feed.run([&](CallWriter& w) {
            w.op(op::glMateriali);
            w.put<GLenum>(GL_FRONT);
            w.put<GLenum>(GL_SHININESS);
            w.put<GLint>(exponent);
        });
    };
    // A flat triangle whose normal is 30 degrees off the view (and so off the default light
    // 0's half-vector, which is the view's).
    auto triangle = [&] {
        feed.run([&](CallWriter& w) {
            w.op(op::glBegin);
            w.put<GLenum>(GL_TRIANGLES);
            w.op(op::glNormal3f);
            for (float c : {0.5f, 0.0f, 0.8660254f}) w.put<float>(c);
            for (int k = 0; k < 3; ++k) {
                w.op(op::glVertex3f);
                for (float c : {k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f, -2.0f}) w.put<float>(c);
            }
            w.op(op::glEnd);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true);
    vector(op::glLightfv, GL_LIGHT0, GL_SPECULAR, {0.0f, 1.0f, 1.0f, 1.0f});
    vector(op::glMaterialfv, GL_FRONT, GL_SPECULAR, {1.0f, 1.0f, 1.0f, 1.0f});
    vector(op::glMaterialfv, GL_FRONT, GL_AMBIENT_AND_DIFFUSE, {0.8f, 0.2f, 0.8f, 1.0f});
    shininess(128);
    triangle();
    shininess(0);
    triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 2u);
    const glm::vec4 narrow = batches[0].vertices[0].color;
    const glm::vec4 broad = batches[1].vertices[0].color;
    EXPECT_GT(narrow.r, narrow.g + 0.3f) << "a shine far from the mirror angle was added";
    EXPECT_NEAR(broad.g, std::min(narrow.g + 1.0f, 1.0f), 0.02f) << "shininess 0 shines all over";
}

// GL clamps its light sum per channel: extremetuxracer's pinkish sun (1, 0.9, 1) over its
// bluish ambient (0.45, 0.53, 0.75), with a grey fill light, passes 1 in every channel on the
// lit side, and its snow is white there, not the lavender of the sum's hue (0.87, 0.86, 1).
TEST(StateTracker, LightsPassingOneInEveryChannelLightWhite)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto lightfv = [&](GLenum light, GLenum pname, std::array<float, 4> v) {
        feed.run(
            [&](CallWriter& w) { vectorCall(w, op::glLightfv, light, pname, v.data(), sizeof v); });
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.enable(GL_LIGHT0, true);
    feed.enable(GL_LIGHT1, true);
    lightfv(GL_LIGHT0, GL_AMBIENT, {0.45f, 0.53f, 0.75f, 1.0f});
    lightfv(GL_LIGHT0, GL_DIFFUSE, {1.0f, 0.9f, 1.0f, 1.0f});
    lightfv(GL_LIGHT1, GL_DIFFUSE, {0.3f, 0.3f, 0.3f, 1.0f});
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    // GL's default material (diffuse 0.8), brightened as GL's sum does, and untinted.
    const glm::vec4 snow = batches[0].vertices[0].color;
    EXPECT_GE(snow.r, 0.8f);
    EXPECT_NEAR(snow.g, snow.r, 0.01f) << "lavender";
    EXPECT_NEAR(snow.b, snow.r, 0.01f) << "lavender";
}

// A program that never names its textures keeps its image in unit 0's texture object 0
// (xscreensaver's gflux): the scene takes it as kDefaultTexture, not as "no texture" (enabled
// with no image, GL draws untextured: so does the scene). And texture coordinates move by
// their unit's texture matrix (gflux scales its checkerboard so), not by another unit's.
TEST(StateTracker, TheDefaultTextureAndItsTextureMatrixReachTheBatch)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto texturedTriangle = [&] {
        feed.run([](CallWriter& w) {
            w.op(op::glBegin);
            w.put<GLenum>(GL_TRIANGLES);
            for (float x : {0.0f, 1.0f, 0.0f}) {
                w.op(op::glTexCoord2f);
                w.put<float>(1.0f);
                w.put<float>(1.0f);
                w.op(op::glVertex3f);
                for (float c : {x, x == 0.0f ? 0.0f : 1.0f, 0.0f}) w.put<float>(c);
            }
            w.op(op::glEnd);
        });
    };
    auto texture = [&](GLenum mode, auto&& change) {
        feed.run([&](CallWriter& w) {
            w.op(op::glMatrixMode);
            w.put<GLenum>(GL_TEXTURE);
            change(w);
            w.op(op::glMatrixMode);
            w.put<GLenum>(mode);
        });
    };
    auto unit = [&](GLenum u) {
        feed.run([&](CallWriter& w) {
            w.op(op::glActiveTexture);
            w.put<GLenum>(u);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true);
    texturedTriangle(); // texture 0 without an image
    feed.run([](CallWriter& w) {
        const uint8_t pixels[4 * 4] = {255, 0,   0, 255, 0, 255, 0, 255,
                                       0,   0, 255, 255, 9, 9,   9, 255};
        rgbaImage(w, 2, 2, pixels);
    });
    texturedTriangle();
    texture(GL_MODELVIEW, [](CallWriter& w) {
        w.op(op::glScalef);
        for (float c : {0.5f, 0.25f, 1.0f}) w.put<float>(c);
    });
    texturedTriangle();
    unit(GL_TEXTURE1); // another unit's matrix moves another unit's coordinates
    texture(GL_MODELVIEW, [](CallWriter& w) {
        w.op(op::glTranslatef);
        for (float c : {5.0f, 5.0f, 0.0f}) w.put<float>(c);
    });
    unit(GL_TEXTURE0);
    texturedTriangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 4u);
    EXPECT_EQ(batches[0].texture, 0u) << "an imageless texture 0 drawn as a texture";
    EXPECT_EQ(batches[1].texture, styles::kDefaultTexture) << "the default texture dropped";
    EXPECT_EQ(batches[1].vertices[0].texcoord, glm::vec2(1.0f, 1.0f));
    EXPECT_EQ(batches[2].vertices[0].texcoord, glm::vec2(0.5f, 0.25f)) << "matrix not applied";
    EXPECT_EQ(batches[3].vertices[0].texcoord, glm::vec2(0.5f, 0.25f)) << "unit 1's applied";
}

// How fine an alpha-tested texture's cut is (the median run of kept texels or of the clear
// ones they enclose, whichever is shorter, over rows and columns, in texture coordinates):
// what the edge style asks before outlining a cut-out along its cut.
TEST(StateTracker, ACutOutsTextureTellsHowFineItsCutIs)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    // 8 x 8: columns kept two, clear two (the last two clear runs end the rows, not enclosed)
    // and a left half kept.
    std::vector<uint8_t> bars(8 * 8 * 4, 255), half(8 * 8 * 4, 255);
    for (int y = 0; y < 8; ++y) {
        for (int x = 0; x < 8; ++x) {
            bars[size_t(y * 8 + x) * 4 + 3] = x % 4 >= 2 ? 0 : 255;
            half[size_t(y * 8 + x) * 4 + 3] = x >= 4 ? 0 : 255;
        }
    }
    auto draw = [&](GLuint texture, const std::vector<uint8_t>* image) {
        feed.run([&](CallWriter& w) {
            w.op(op::glBindTexture);
            w.put<GLenum>(GL_TEXTURE_2D);
            w.put<GLuint>(texture);
            if (image) rgbaImage(w, 8, 8, image->data());
            w.op(op::glBegin);
            w.put<GLenum>(GL_TRIANGLES);
            for (float x : {0.0f, 1.0f, 0.0f}) {
                w.op(op::glTexCoord2f);
                for (float c : {x, x == 0.0f ? 0.0f : 1.0f}) w.put<float>(c);
                w.op(op::glVertex3f);
                for (float c : {x, x == 0.0f ? 0.0f : 1.0f, 0.0f}) w.put<float>(c);
            }
            w.op(op::glEnd);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true);
    feed.run([](CallWriter& w) {
        w.op(op::glAlphaFunc);
        w.put<GLenum>(GL_GREATER);
        w.put<float>(0.5f);
    });
    draw(1, &bars); // no alpha test yet
    feed.enable(GL_ALPHA_TEST, true);
    draw(1, nullptr);
    draw(2, &half);
    // Made 8 x 8 without pixels, then its lower half filled by a part (SFML's way): the part's
    // runs measured against the whole level.
    feed.run([&](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLuint>(3);
        rgbaImageByPart(w, 8, 8, 4, half.data());
    });
    draw(3, nullptr);
    // Alpha 0.8 everywhere (a mostly opaque texture with soft alpha): the test keeps it whole;
    // drawn again faded by its colour's alpha, a surface fading as a whole.
    std::vector<uint8_t> soft(8 * 8 * 4, 255);
    for (size_t i = 3; i < soft.size(); i += 4) soft[i] = 204;
    draw(4, &soft);
    feed.run([](CallWriter& w) {
        w.op(op::glColor4f);
        for (float c : {1.0f, 1.0f, 1.0f, 0.3f}) w.put<float>(c);
    });
    draw(4, nullptr);
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 6u);
    EXPECT_EQ(batches[0].cutFeature, 0.0f) << "no alpha test, no cut";
    // Rows: 16 kept runs of 2/8 and 8 enclosed clear runs of 2/8; columns: 4 kept of 8/8.
    EXPECT_FLOAT_EQ(batches[1].cutFeature, 0.25f);
    // Rows: 8 kept runs of 4/8, none enclosed; columns: 4 kept runs of 8/8.
    EXPECT_FLOAT_EQ(batches[2].cutFeature, 0.5f);
    // Rows: 4 kept runs of 4/8; columns: 4 kept runs of 4 texels of the level's 8.
    EXPECT_FLOAT_EQ(batches[3].cutFeature, 0.5f);
    EXPECT_EQ(batches[4].cutFeature, kKeptWhole) << "a texture the test keeps whole";
    EXPECT_EQ(batches[5].cutFeature, 0.0f) << "faded by its colour: no shape known";
}

// An upload's rows as the recorder keeps them, each padded to the unpack alignment: the
// padding is no texel (here 0 bytes, where every texel is opaque white).
TEST(TextureImage, ReadsRowsWithoutTheirUnpackPadding)
{
    // 1 x 2 RGBA at an alignment of 8: 4 bytes of texel, 4 of padding a row.
    const uint8_t rgba[16] = {255, 255, 255, 255, 0, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 0};
    const TextureImage tall(1, 2, GL_RGBA, GL_UNSIGNED_BYTE, rgba, sizeof rgba);
    EXPECT_TRUE(tall.opaque()) << "the padding's zero bytes read as alpha";
    glm::vec3 mean(0.0f);
    ASSERT_TRUE(tall.mean(mean));
    EXPECT_FLOAT_EQ(mean.r, 1.0f);
    EXPECT_EQ(tall.cutFeature({1, 2}), kKeptWhole) << "nothing clear in it";
    // 3 x 2 RGB at an alignment of 4: 9 bytes of texels, 3 of padding (255) a row.
    uint8_t rgb[24] = {};
    for (int row = 0; row < 2; ++row) {
        for (int i = 9; i < 12; ++i) rgb[row * 12 + i] = 255;
    }
    ASSERT_TRUE(TextureImage(3, 2, GL_RGB, GL_UNSIGNED_BYTE, rgb, sizeof rgb).mean(mean));
    EXPECT_EQ(mean, glm::vec3(0.0f)) << "black texels; the padding counted";
    // Too few bytes for the image, or no pixels: nothing known.
    EXPECT_FALSE(TextureImage(3, 2, GL_RGB, GL_UNSIGNED_BYTE, rgb, 12).mean(mean));
    EXPECT_FALSE(TextureImage(1, 2, GL_RGBA, GL_UNSIGNED_BYTE, nullptr, 16).opaque());
    EXPECT_EQ(TextureImage(1, 2, GL_RGBA, GL_UNSIGNED_BYTE, rgba, 4).cutFeature({1, 2}), 0.0f);
}

// GL has one default 2D texture for all units (Mesa draws unit 0 with the image given to
// unit 1's texture 0): an image uploaded with texture 0 bound on another unit is the default
// texture of unit 0 too.
TEST(StateTracker, TheDefaultTextureIsOneForAllUnits)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.run([](CallWriter& w) {
        w.op(op::glActiveTexture);
        w.put<GLenum>(GL_TEXTURE1);
        const uint8_t pixel[4] = {255, 0, 0, 255};
        rgbaImage(w, 1, 1, pixel);
        w.op(op::glActiveTexture);
        w.put<GLenum>(GL_TEXTURE0);
    });
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true);
    feed.run([](CallWriter& w) {
        w.op(op::glBegin);
        w.put<GLenum>(GL_TRIANGLES);
        for (float x : {0.0f, 1.0f, 0.0f}) {
            w.op(op::glVertex3f);
            for (float c : {x, x == 0.0f ? 0.0f : 1.0f, 0.0f}) w.put<float>(c);
        }
        w.op(op::glEnd);
    });
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, styles::kDefaultTexture) << "unit 1's image not the default";
}

// Modes given as floats that name no mode (a hostile capture's 1.6e29, NaN) are refused, as
// the driver refuses them, and never converted out of range (undefined behaviour: the
// sanitizer build fails on it; a fuzzed capture found it).
TEST(StateTracker, FloatModesThatNameNoModeChangeNothing)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    const float hostile[] = {1.58459e29f, -3.0f, std::nanf("")};
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true);
    feed.enable(GL_FOG, true);
    feed.run([&](CallWriter& w) {
        w.op(op::glBindTexture);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLuint>(3);
        w.op(op::glFogi);
        w.put<GLenum>(GL_FOG_MODE);
        w.put<GLint>(GL_LINEAR);
        for (float f : hostile) {
            w.op(op::glFogf);
            w.put<GLenum>(GL_FOG_MODE);
            w.put<float>(f);
            w.op(op::glTexEnvf);
            w.put<GLenum>(GL_TEXTURE_ENV);
            w.put<GLenum>(GL_TEXTURE_ENV_MODE);
            w.put<float>(f);
            w.op(op::glTexGenf);
            w.put<GLenum>(GL_S);
            w.put<GLenum>(GL_TEXTURE_GEN_MODE);
            w.put<float>(f);
        }
    });
    // The texture environment is still GL_MODULATE: the surface's texture, held.
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    feed.enable(GL_TEXTURE_GEN_S, true);
    feed.enable(GL_TEXTURE_GEN_T, true);
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].fog.mode, GLenum(GL_LINEAR));
    EXPECT_EQ(batches[0].generated.mode[0], GLenum(GL_EYE_LINEAR)); // GL's default, kept
}

TEST(StateTracker, FramesReuseTheirVertexStorage)
{
    // A frame's vertex vectors come back to the tracker and serve the next frame's batches
    // of the same sizes: no allocation (and no page faults) per frame.
    capture::CaptureReader reader;
    std::string error;
    ASSERT_TRUE(reader.open(std::string(NPRGL_TEST_SOURCE_DIR) + "/fixtures/immediate.nprgl",
                            error))
        << error;
    ASSERT_GE(reader.frames().size(), 3u);
    CaptureBlobs blobs(reader);
    StateTracker tracker;
    std::vector<uint8_t> calls;
    std::set<const TrackedVertex*> previous;
    for (size_t i = 0; i < reader.frames().size(); ++i) {
        ASSERT_TRUE(reader.readFrame(i, calls, error)) << error;
        ASSERT_TRUE(tracker.runFrame(calls.data(), calls.size(), &blobs, error)) << error;
        std::set<const TrackedVertex*> storage;
        for (const TrackedBatch& b : tracker.frameBatches()) storage.insert(b.vertices.data());
        if (i > 0) {
            EXPECT_EQ(storage, previous) << "frame " << i;
        }
        previous = std::move(storage);
    }
}

// From a capture to meshes: the tracker's batches through the reconstruction.
#include "frame/FrameExport.h"

TEST(Reconstruction, EachGlxgearsGearIsOneClosedObject)
{
    reconstruct::Reconstructor reconstructor;
    std::vector<reconstruct::FrameObject> objects =
        reconstructor.build(reconstructionBatches(frameBatches("glxgears", 2)));
    ASSERT_EQ(objects.size(), 3u);
    for (const reconstruct::FrameObject& o : objects) {
        ASSERT_TRUE(o.mesh);
        EXPECT_EQ(o.mesh->borderEdgeCount(), 0u);
        EXPECT_TRUE(o.mesh->closed());
        EXPECT_EQ(o.mesh->eulerCharacteristic(), 0); // a gear is a ring: a torus
        EXPECT_EQ(o.mesh->stats.splitFaces, 0u);
        EXPECT_EQ(o.batchCount, 6u);
    }
    // The next frame only turns the gears: every object comes from the cache.
    reconstructor.build(reconstructionBatches(frameBatches("glxgears", 3)));
    EXPECT_EQ(reconstructor.cacheStats().hits, 3u);
    EXPECT_EQ(reconstructor.cacheStats().rebuilds, 3u);
}

TEST(Reconstruction, ImmediateModeShapesWeldAcrossTheirBatches)
{
    reconstruct::Reconstructor reconstructor;
    std::vector<reconstruct::FrameObject> objects =
        reconstructor.build(reconstructionBatches(frameBatches("immediate", 1)));
    ASSERT_EQ(objects.size(), 6u); // torus, sphere, cone, prism, cube, octahedron
    // The torus (quad strips) is a closed ring, every other shape a closed sphere-like mesh.
    EXPECT_EQ(objects[0].mesh->eulerCharacteristic(), 0);
    for (size_t i = 0; i < objects.size(); ++i) {
        EXPECT_TRUE(objects[i].mesh->closed()) << i << " split faces "
                                               << objects[i].mesh->stats.splitFaces
                                               << " degenerate "
                                               << objects[i].mesh->stats.degenerateTriangles;
        if (i > 0) {
            EXPECT_EQ(objects[i].mesh->eulerCharacteristic(), 2) << i;
        }
    }
}

TEST(Reconstruction, AnimatedCharactersKeepTheirTopology)
{
    // After its first frame, a character whose vertices move (morphing, skinning) is updated
    // in place, never rebuilt; a rigid figure's parts come from the cache. (The rigid figure
    // is followed from frame 2: in frame 1's rest pose some consecutive parts share one
    // transform and so, by design, one object.)
    const std::pair<const char*, uint64_t> cases[] = {
        {"character_morph", 1}, {"character_skin", 1}, {"character_rigid", 2}};
    for (const auto& [name, start] : cases) {
        reconstruct::Reconstructor reconstructor;
        std::vector<reconstruct::FrameObject> first =
            reconstructor.build(reconstructionBatches(frameBatches(name, start)));
        ASSERT_FALSE(first.empty()) << name;
        const uint64_t rebuilt = reconstructor.cacheStats().rebuilds;
        EXPECT_EQ(rebuilt, first.size()) << name;
        for (uint64_t frame = start + 1; frame <= 3; ++frame) {
            std::vector<reconstruct::FrameObject> objects =
                reconstructor.build(reconstructionBatches(frameBatches(name, frame)));
            EXPECT_EQ(objects.size(), first.size()) << name << " frame " << frame;
        }
        const reconstruct::CacheStats stats = reconstructor.cacheStats();
        EXPECT_EQ(stats.rebuilds, rebuilt) << name << ": topology changed";
        EXPECT_EQ(stats.hits + stats.updates, (3 - start) * first.size()) << name;
        if (std::string(name) == "character_rigid") {
            EXPECT_EQ(stats.updates, 0u) << name << ": rigid parts do not deform";
        } else {
            EXPECT_GT(stats.updates, 0u) << name << ": the mesh did not move";
        }
    }
}

// glPopAttrib restores exactly the groups its glPushAttrib saved, the program enables with
// the enable group (a fragment program enabled inside a push/pop must not outlive it).
TEST(AttribStack, PopRestoresOnlyTheSavedGroups)
{
    AttribStack stack;
    stack.push(GL_ENABLE_BIT);
    AttribState& a = stack.current();
    a.fragmentProgram = true;
    a.blend = true;
    a.colorMask = 0; // GL_COLOR_BUFFER_BIT: not saved
    a.viewport = {1, 2, 3, 4};
    stack.pop();
    EXPECT_FALSE(stack.current().fragmentProgram);
    EXPECT_FALSE(stack.current().blend);
    EXPECT_EQ(stack.current().colorMask, 0);
    EXPECT_EQ(stack.current().viewport, glm::ivec4(1, 2, 3, 4));
    stack.pop(); // underflow: nothing happens, as in the driver
    EXPECT_EQ(stack.depth(), 0u);
}

TEST(MatrixStacks, EachModeHasItsStack)
{
    MatrixStacks m;
    m.top() = glm::mat4(2.0f);
    m.setMode(GL_PROJECTION);
    m.push();
    m.top() = glm::mat4(3.0f);
    EXPECT_EQ(m.projection(), glm::mat4(3.0f));
    EXPECT_EQ(m.modelview(), glm::mat4(2.0f));
    m.pop();
    EXPECT_EQ(m.projection(), glm::mat4(1.0f));
    m.pop(); // the last matrix stays
    EXPECT_EQ(m.projection(), glm::mat4(1.0f));
    m.setMode(GL_MODELVIEW);
    for (int i = 0; i < 100; ++i) m.push(); // past the depth: refused, as in the driver
    for (int i = 0; i < 100; ++i) m.pop();
    EXPECT_EQ(m.modelview(), glm::mat4(2.0f));
}

// A HUD drawn with an orthographic projection and the depth test on but no depth writes
// (ioquake3 draws its status bar so) is 2D: not held, not styled. Writing depth, the same
// orthographic drawing is a 3D scene (CAD views are orthographic).
TEST(StateTracker, OrthographicDrawingWithoutDepthWritesIsTwoDimensional)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.projection([](CallWriter& w) {
        w.op(op::glOrtho);
        for (double v : {0.0, 640.0, 480.0, 0.0, 0.0, 1.0}) w.put<double>(v);
    });
    feed.depthMask(false);
    feed.enable(GL_DEPTH_TEST, true);
    EXPECT_FALSE(tracker.is3D());
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    feed.depthMask(true);
    EXPECT_TRUE(tracker.is3D());
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
}

// A program that puts its camera into the projection matrix (glFrustum, then the view's
// transforms on GL_PROJECTION, the modelview the identity: armagetronad) draws in perspective
// though the matrix's w element is not 0: its floor, drawn without the depth test or depth
// writes, is a 3D backdrop and styled, not 2D drawing left as it was (taken for 2D, it was
// neither styled nor counted, and the page went over it).
TEST(StateTracker, ACameraInTheProjectionMatrixIsStillAPerspective)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.projection([](CallWriter& w) {
        w.op(op::glFrustum);
        for (double v : {-1.0, 1.0, -0.75, 0.75, 1.0, 100.0}) w.put<double>(v);
        w.op(op::glTranslatef);
        for (float c : {-13.0f, -19.0f, -16.7f}) w.put<float>(c);
    });
    feed.depthMask(false);
    feed.enable(GL_DEPTH_TEST, false);
    EXPECT_TRUE(tracker.is3D());
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
}

// GL_ONE, GL_ZERO replaces what is behind: blending on with the default functions is no
// blending (trigger-rally leaves GL_BLEND on all frame and draws its car and terrain so; all
// of it was left as 'blending other than ...').
TEST(StateTracker, BlendingThatReplacesIsNoBlending)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_BLEND, true);
    feed.blendFunc(GL_ONE, GL_ZERO);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    EXPECT_FALSE(tracker.translucent());
    feed.blendFunc(GL_ONE, GL_ONE);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES)) << "additive blending held";
}

// Blending by alpha and the alpha test where no alpha of the draw can be below 1 change no
// pixel: such draws are opaque ones (extremetuxracer blends and alpha-tests all its drawing,
// with material alphas of 0.99999994 and textures made by glTexImage2D without pixels and
// filled by glTexSubImage2D, SFML's way). A texture with a transparent part stays a cut-out.
TEST(StateTracker, AlphaThatCannotBeBelowOneIsOpaque)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_BLEND, true);
    feed.enable(GL_ALPHA_TEST, true);
    feed.run([](CallWriter& w) {
        w.op(op::glBlendFunc);
        w.put<GLenum>(GL_SRC_ALPHA);
        w.put<GLenum>(GL_ONE_MINUS_SRC_ALPHA);
        w.op(op::glAlphaFunc);
        w.put<GLenum>(GL_GEQUAL);
        w.put<float>(0.5f);
        w.op(op::glColor4f);
        for (float c : {1.0f, 1.0f, 1.0f, 0.99999994f}) w.put<float>(c);
    });
    feed.triangle(); // untextured, alpha within rounding of 1
    // Two textures made without pixels and filled by a part: one opaque, one with a hole.
    auto upload = [&](GLuint name, uint8_t alpha) {
        std::vector<uint8_t> pixels(4 * 4 * 4, 200);
        for (size_t i = 3; i < pixels.size(); i += 4) pixels[i] = 255;
        pixels[7] = alpha; // one texel's alpha
        feed.run([&](CallWriter& w) {
            w.op(op::glBindTexture);
            w.put<GLenum>(GL_TEXTURE_2D);
            w.put<GLuint>(name);
            rgbaImageByPart(w, 4, 4, 4, pixels.data());
        });
    };
    // Each triangle somewhere else: the same triangle again would be a pass over the first.
    auto moveOn = [&] {
        feed.run([](CallWriter& w) {
            w.op(op::glTranslatef);
            for (float c : {2.0f, 0.0f, 0.0f}) w.put<float>(c);
        });
    };
    feed.enable(GL_TEXTURE_2D, true);
    upload(5, 255);
    moveOn();
    feed.triangle();
    upload(6, 0);
    moveOn();
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 3u);
    for (int i = 0; i < 2; ++i) {
        EXPECT_FALSE(batches[i].translucent) << i;
        EXPECT_EQ(batches[i].alphaFunc, GLenum(GL_ALWAYS)) << i;
    }
    EXPECT_EQ(batches[1].texture, 5u);
    EXPECT_EQ(batches[2].texture, 6u);
    EXPECT_TRUE(batches[2].translucent);
    EXPECT_EQ(batches[2].alphaFunc, GLenum(GL_GEQUAL));
}

// A texture's alpha is its internal format's, whatever the pixels it was made from (GL keeps
// the internal format's channels). xscreensaver's texfont gives its glyphs as GL_LUMINANCE
// bytes to a GL_INTENSITY texture, whose alpha is each byte: its labels, blended by that
// alpha, were taken for opaque (luminance has no alpha) and drawn as black squares. An RGB
// texture from RGBA bytes is opaque, whatever their alpha.
TEST(StateTracker, ATexturesAlphaIsItsInternalFormats)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_BLEND, true);
    feed.blendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    feed.enable(GL_ALPHA_TEST, true);
    feed.run([](CallWriter& w) {
        w.op(op::glAlphaFunc);
        w.put<GLenum>(GL_GREATER);
        w.put<float>(0.01f);
    });
    feed.enable(GL_TEXTURE_2D, true);
    // Texture `name`'s level 0, 4 x 4 texels of `format` bytes in `internalFormat`, then a
    // triangle drawn with it (each somewhere else: not a pass over the one before).
    auto draw = [&](GLuint name, GLint internalFormat, GLenum format,
                    const std::vector<uint8_t>& pixels) {
        feed.run([&](CallWriter& w) {
            w.op(op::glBindTexture);
            w.put<GLenum>(GL_TEXTURE_2D);
            w.put<GLuint>(name);
            w.op(op::glTexImage2D);
            const size_t mark = w.beginPayload();
            for (GLint v : {GLint(GL_TEXTURE_2D), 0, internalFormat, 4, 4, 0}) w.put<GLint>(v);
            w.put<GLenum>(format);
            w.put<GLenum>(GL_UNSIGNED_BYTE);
            w.put<uint8_t>(1);
            w.putBytes(pixels.data(), pixels.size());
            w.endPayload(mark);
            w.op(op::glTranslatef);
            for (float c : {2.0f, 0.0f, 0.0f}) w.put<float>(c);
        });
        feed.triangle();
    };
    std::vector<uint8_t> glyph(16, 0); // a bar of ink on a clear ground
    for (size_t i = 4; i < 8; ++i) glyph[i] = 255;
    draw(5, GL_INTENSITY, GL_LUMINANCE, glyph);
    draw(6, GL_INTENSITY, GL_LUMINANCE, std::vector<uint8_t>(16, 255));
    std::vector<uint8_t> clear(4 * 16, 200);
    for (size_t i = 3; i < clear.size(); i += 4) clear[i] = 0;
    draw(7, GL_RGB, GL_RGBA, clear);
    draw(8, GL_RGBA, GL_RGBA, clear);
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 4u);
    EXPECT_TRUE(batches[0].translucent) << "an intensity texture's clear texels were opaque";
    EXPECT_EQ(batches[0].alphaFunc, GLenum(GL_GREATER));
    EXPECT_FALSE(batches[1].translucent) << "intensity 1 is alpha 1";
    EXPECT_FALSE(batches[2].translucent) << "an RGB texture has no alpha to blend by";
    EXPECT_TRUE(batches[3].translucent);
}

// Multi-pass surfaces (ioquake3 draws each stage of a shader over the same vertices): a
// blended pass over geometry held just before is merged into that object, not drawn again
// nor styled twice. Other geometry, other culling, or nothing held: not a pass over it.
TEST(StateTracker, ABlendedPassOverHeldGeometryIsMergedIntoIt)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto triangle = [&](float dx) {
        feed.run([dx](CallWriter& w) {
            w.op(op::glBegin);
            w.put<GLenum>(GL_TRIANGLES);
            for (float x : {0.0f, 1.0f, 0.0f}) {
                w.op(op::glVertex3f);
                for (float c : {x + dx, x == 0.0f ? 0.0f : 1.0f, 0.0f}) w.put<float>(c);
            }
            w.op(op::glEnd);
        });
    };
    auto blend = [&](GLenum src, GLenum dst) { feed.blendFunc(src, dst); };
    // Asks as the compositor does before the driver sees the draw.
    auto pass = [&](float dx) {
        EXPECT_TRUE(tracker.mayLayer(GL_TRIANGLES));
        tracker.watchRepeats();
        triangle(dx);
        return tracker.repeatedAll();
    };
    feed.enable(GL_DEPTH_TEST, true);
    triangle(0.0f); // the surface, held
    feed.enable(GL_BLEND, true);
    blend(GL_ONE, GL_ONE);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    EXPECT_TRUE(pass(0.0f)) << "an additive stage over the surface";
    // A pass after the whole scene (a lightmap pass over a world) still finds its surface.
    feed.enable(GL_BLEND, false);
    for (int i = 1; i <= 40; ++i) triangle(float(i));
    feed.enable(GL_BLEND, true);
    EXPECT_TRUE(pass(0.0f)) << "a pass 40 held batches after its surface";
    EXPECT_FALSE(pass(0.5f)) << "another triangle";
    // A pass of two batches (a display list, say) is merged only when both repeat.
    tracker.watchRepeats();
    triangle(0.0f);
    triangle(0.5f);
    EXPECT_FALSE(tracker.repeatedAll()) << "half of it repeats the surface";
    feed.enable(GL_CULL_FACE, true);
    EXPECT_FALSE(pass(0.0f)) << "culled: it draws other triangles than the surface";
    feed.enable(GL_CULL_FACE, false);
    // Blended by an alpha of 1 everywhere, a pass is held, and merged without being asked.
    // At alpha 0.5 it is a layer with a picture of its own (water or paint over the ground):
    // held as an object of its own.
    blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    ASSERT_TRUE(tracker.wouldHold(GL_TRIANGLES));
    triangle(0.0f);
    EXPECT_EQ(tracker.mergedPasses(), 1u) << "an opaque pass over the surface was kept";
    feed.run([](CallWriter& w) {
        w.op(op::glColor4f);
        for (float c : {1.0f, 1.0f, 1.0f, 0.5f}) w.put<float>(c);
    });
    triangle(0.0f);
    EXPECT_EQ(tracker.mergedPasses(), 1u) << "a translucent layer merged into its surface";
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    EXPECT_EQ(batches.size(), 42u) << "the surface, the others and the layer, each once";
    // A scene drawn (the batches taken): the same pass has nothing held to merge into.
    blend(GL_ONE, GL_ONE);
    EXPECT_FALSE(pass(0.0f));
    // Two translucent passes over one mesh culling opposite faces are both kept.
    blend(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    feed.enable(GL_CULL_FACE, true);
    auto cull = [&](GLenum face) {
        feed.run([face](CallWriter& w) {
            w.op(op::glCullFace);
            w.put<GLenum>(face);
        });
    };
    cull(GL_FRONT);
    triangle(0.0f);
    cull(GL_BACK);
    triangle(0.0f);
    tracker.takeBatches(batches);
    EXPECT_EQ(batches.size(), 2u);
    EXPECT_EQ(tracker.mergedPasses(), 1u) << "one of them taken for a pass over the other";
}

// An alpha-blended layer the program lifts off its surface with a polygon offset is a decal
// (neverball's start arrow, drawn on the very quad of its floor tile); one without an offset
// whose alpha is not 1 is water or paint laid over the ground (cultivation's pools, a game's
// item lights); a layer over a translucent batch is the next layer of a layered decal: their
// pictures are their own, kept as objects, not merged as stages of what they cover. A pass
// blended by an alpha of 1 everywhere changes nothing over its surface and is merged.
TEST(StateTracker, DecalsAndLayersBlendedByTheirAlphaAreKeptNotMerged)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto alpha = [&](float a) {
        feed.run([a](CallWriter& w) {
            w.op(op::glColor4f);
            for (float c : {1.0f, 1.0f, 1.0f, a}) w.put<float>(c);
        });
    };
    std::vector<TrackedBatch> batches;
    feed.enable(GL_DEPTH_TEST, true);
    feed.triangle(); // the floor, opaque
    feed.run([](CallWriter& w) {
        w.op(op::glBlendFunc);
        w.put<GLenum>(GL_SRC_ALPHA);
        w.put<GLenum>(GL_ONE_MINUS_SRC_ALPHA);
        w.op(op::glPolygonOffset);
        w.put<float>(-1.0f);
        w.put<float>(-2.0f);
    });
    feed.enable(GL_BLEND, true);
    alpha(0.5f);
    feed.enable(GL_POLYGON_OFFSET_FILL, true);
    feed.triangle(); // the decal
    EXPECT_EQ(tracker.mergedPasses(), 0u) << "the decal was merged into its floor";
    feed.enable(GL_POLYGON_OFFSET_FILL, false);
    feed.triangle(); // a layer on the floor without an offset: its own too
    EXPECT_EQ(tracker.mergedPasses(), 0u) << "the layer was merged into its floor";
    alpha(1.0f);
    feed.triangle(); // an opaque stage of the floor: merged
    EXPECT_EQ(tracker.mergedPasses(), 1u);
    tracker.takeBatches(batches);
    EXPECT_EQ(batches.size(), 3u) << "the floor, its decal and its layer";

    alpha(0.5f);
    feed.triangle(); // a translucent pane
    feed.triangle(); // a second layer on it
    EXPECT_EQ(tracker.mergedPasses(), 1u) << "a layer merged into a translucent one";
    tracker.takeBatches(batches);
    EXPECT_EQ(batches.size(), 2u);
}

// A list that calls itself twice runs 2^64 times within the driver's nesting limit: a hostile
// capture (the replay fuzzer made one) must not hang the tracker. It follows a bounded number
// of list items a top-level call, says so once, and goes on with the next call.
TEST(StateTracker, AListCallingItselfOverAndOverIsFollowedOnlySoFar)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.enable(GL_DEPTH_TEST, true);
    feed.run([](CallWriter& w) {
        w.op(op::glNewList);
        w.put<GLuint>(1);
        w.put<GLenum>(GL_COMPILE);
        for (int k = 0; k < 2; ++k) {
            w.op(op::glCallList);
            w.put<GLuint>(1);
        }
        w.op(op::glEndList);
        w.op(op::glCallList);
        w.put<GLuint>(1);
    });
    feed.triangle(); // the next call is followed
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    EXPECT_EQ(batches.size(), 1u);
}

// glPopAttrib gives back what its groups saved beyond the enables: GL_TEXTURE_BIT each
// unit's binding and the active unit, GL_CURRENT_BIT the colour and every unit's
// coordinates. scorched3d binds and sets inside a push of all groups; the tracker kept the
// later values, and drew its tank previews' squares with a texture they did not have.
TEST(StateTracker, PopAttribRestoresBindingsAndCurrentAttributes)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto colour = [&](float r) {
        feed.run([&](CallWriter& w) {
            w.op(op::glColor4f);
            for (float c : {r, 0.5f, 0.5f, 1.0f}) w.put<float>(c);
        });
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_TEXTURE_2D, true);
    feed.bindTexture(5);
    colour(0.25f);
    feed.run([](CallWriter& w) {
        w.op(op::glPushAttrib);
        w.put<GLbitfield>(GL_TEXTURE_BIT | GL_CURRENT_BIT);
    });
    feed.activeTexture(GL_TEXTURE1);
    feed.activeTexture(GL_TEXTURE0);
    feed.bindTexture(9);
    colour(0.75f);
    feed.triangle(); // inside: texture 9, red 0.75
    feed.run([](CallWriter& w) { w.op(op::glPopAttrib); });
    feed.triangle(); // after: texture 5, red 0.25 again
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 2u);
    EXPECT_EQ(batches[0].texture, 9u);
    EXPECT_EQ(batches[1].texture, 5u) << "the binding inside the push outlived its pop";
    ASSERT_FALSE(batches[1].vertices.empty());
    EXPECT_FLOAT_EQ(batches[1].vertices[0].color.r, 0.25f)
        << "the colour inside the push outlived its pop";
}

// A list compiled with GL_COMPILE_AND_EXECUTE that calls another holds that call, not a copy
// of what the call ran besides: called later, the inner list draws once, moved once, with the
// normal it set itself. billard-gl's cue ball was drawn twice, the copy with the caller's
// normal on every vertex, and came out in the shadow band all over.
TEST(StateTracker, AListCalledWhileAnotherCompilesAndExecutesIsNotCopiedIntoIt)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    auto normal = [](CallWriter& w, float x, float y, float z) {
        w.op(op::glNormal3f);
        for (float c : {x, y, z}) w.put<float>(c);
    };
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_LIGHTING, true);
    feed.run([&](CallWriter& w) {
        w.op(op::glNewList);
        w.put<GLuint>(1);
        w.put<GLenum>(GL_COMPILE);
        w.op(op::glTranslatef);
        for (float c : {1.0f, 0.0f, 0.0f}) w.put<float>(c);
        w.op(op::glBegin);
        w.put<GLenum>(GL_TRIANGLES);
        normal(w, 1.0f, 0.0f, 0.0f);
        for (float x : {0.0f, 1.0f, 0.0f}) {
            w.op(op::glVertex3f);
            for (float c : {x, x == 0.0f ? 0.0f : 1.0f, -2.0f}) w.put<float>(c);
        }
        w.op(op::glEnd);
        w.op(op::glEndList);
        w.op(op::glNewList);
        w.put<GLuint>(2);
        w.put<GLenum>(GL_COMPILE_AND_EXECUTE);
        w.op(op::glCallList);
        w.put<GLuint>(1);
        w.op(op::glEndList);
    });
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches); // what compiling list 2 ran (left to the driver)
    batches.clear();
    feed.run([&](CallWriter& w) {
        w.op(op::glLoadIdentity);
        normal(w, 0.0f, 1.0f, 0.0f);
        w.op(op::glCallList);
        w.put<GLuint>(2);
    });
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u) << "list 2 holds a copy of list 1's triangle besides its call";
    EXPECT_FLOAT_EQ(batches[0].modelview[3][0], 1.0f);
    ASSERT_FALSE(batches[0].vertices.empty());
    EXPECT_EQ(batches[0].vertices[0].normal, glm::vec3(1.0f, 0.0f, 0.0f));
}

// A depth texture on a unit (a shadow map the fixed pipeline compares) is no surface texture
// and no lightmap: a draw with only it enabled is untextured, and opaque where its colour
// is; beside a colour texture it is a layer not drawn. scorched3d leaves its shadow map
// enabled on unit 2 into its menus: the styles sampled it, and its tank previews' squares
// vanished.
TEST(StateTracker, AShadowMapIsNeitherTheSurfacesTextureNorItsLight)
{
    StateTracker tracker;
    tracker.setHolding(true);
    Feed feed{tracker};
    feed.enable(GL_DEPTH_TEST, true);
    feed.enable(GL_BLEND, true);
    feed.blendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    feed.activeTexture(GL_TEXTURE2);
    feed.enable(GL_TEXTURE_2D, true);
    feed.bindTexture(78);
    feed.run([](CallWriter& w) {
        w.op(op::glTexImage2D);
        const size_t mark = w.beginPayload();
        for (GLint v : {GLint(GL_TEXTURE_2D), 0, GLint(GL_DEPTH_COMPONENT), 64, 64, 0}) {
            w.put<GLint>(v);
        }
        w.put<GLenum>(GL_DEPTH_COMPONENT);
        w.put<GLenum>(GL_UNSIGNED_INT);
        w.put<uint8_t>(0); // no pixels: a target to render depth into
        w.endPayload(mark);
    });
    feed.activeTexture(GL_TEXTURE0);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << tracker.unstylableState();
    EXPECT_EQ(tracker.droppedLayers(), 1u << 2);
    feed.triangle();
    std::vector<TrackedBatch> batches;
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, 0u) << "the shadow map was taken for the surface's texture";
    EXPECT_FALSE(batches[0].translucent) << "its colour's alpha is 1";

    // With a colour texture on unit 0, modulated by the shadow map: no lightmap.
    feed.enable(GL_TEXTURE_2D, true);
    feed.bindTexture(4);
    EXPECT_EQ(tracker.lightmapUnit(), -1) << "the shadow map was taken for a lightmap";
    EXPECT_EQ(tracker.droppedLayers(), 1u << 2);
    feed.triangle();
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, 4u);
    EXPECT_EQ(batches[0].lightmap, 0u);

    // The older way to make one: the depth buffer copied into a texture (here on unit 1).
    feed.activeTexture(GL_TEXTURE2);
    feed.enable(GL_TEXTURE_2D, false);
    feed.activeTexture(GL_TEXTURE1);
    feed.enable(GL_TEXTURE_2D, true);
    feed.bindTexture(79);
    feed.run([](CallWriter& w) {
        w.op(op::glCopyTexImage2D);
        w.put<GLenum>(GL_TEXTURE_2D);
        w.put<GLint>(0);
        w.put<GLenum>(GL_DEPTH_COMPONENT24);
        for (GLint v : {0, 0, 64, 64, 0}) w.put<GLint>(v);
    });
    feed.activeTexture(GL_TEXTURE0);
    EXPECT_EQ(tracker.lightmapUnit(), -1) << "the copied depth was taken for a lightmap";
    EXPECT_EQ(tracker.droppedLayers(), 1u << 1);

    // Alone on unit 0: untextured too.
    feed.activeTexture(GL_TEXTURE1);
    feed.enable(GL_TEXTURE_2D, false);
    feed.activeTexture(GL_TEXTURE0);
    feed.bindTexture(79);
    feed.triangle();
    tracker.takeBatches(batches);
    ASSERT_EQ(batches.size(), 1u);
    EXPECT_EQ(batches[0].texture, 0u) << "the shadow map on unit 0 was taken for the texture";
}
