// demo_state: the transparency check. Each frame draws a small lit, textured scene
// (immediate mode, client arrays, a display list) and a glBitmap/glDrawPixels overlay, sets a
// large set of state to non-default values and queries it back: after the scene's draws,
// after the overlay and after SwapBuffers/glFinish. Any answer that differs from what was
// set, or a lost or invented GL error, fails the run with exit code 1 and one stderr line.

// Declares the GL 1.3-2.0 functions; must precede every include that may pull in GL/gl.h.
#define GL_GLEXT_PROTOTYPES

#include "BitmapFont.h"
#include "Demo.h"
#include "GlslProbe.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace {

using Values = std::vector<double>;

// Passes an enum together with its name: setEnabled(NAMED(GL_FOG), true).
#define NAMED(e) e, #e

std::string formatValues(const Values& values)
{
    std::string text = "[";
    for (size_t i = 0; i < values.size(); ++i) {
        char number[32];
        std::snprintf(number, sizeof(number), "%s%.9g", i ? ", " : "", values[i]);
        text += number;
    }
    return text + "]";
}

Values getInts(GLenum pname, int count)
{
    std::array<GLint, 16> v{};
    glGetIntegerv(pname, v.data());
    return Values(v.begin(), v.begin() + count);
}

Values getFloats(GLenum pname, int count)
{
    std::array<GLfloat, 16> v{};
    glGetFloatv(pname, v.data());
    return Values(v.begin(), v.begin() + count);
}

Values getDoubles(GLenum pname, int count)
{
    std::array<GLdouble, 16> v{};
    glGetDoublev(pname, v.data());
    return Values(v.begin(), v.begin() + count);
}

Values getBooleans(GLenum pname, int count)
{
    std::array<GLboolean, 16> v{};
    glGetBooleanv(pname, v.data());
    return Values(v.begin(), v.begin() + count);
}

Values getPointer(GLenum pname)
{
    void* pointer = nullptr;
    glGetPointerv(pname, &pointer);
    return {static_cast<double>(reinterpret_cast<uintptr_t>(pointer))};
}

Values pointerValue(const void* pointer)
{
    return {static_cast<double>(reinterpret_cast<uintptr_t>(pointer))};
}

// Runs a query with another texture unit active and puts the application's unit back.
Values onUnit(GLenum unit, const std::function<Values()>& query)
{
    GLint old = GL_TEXTURE0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &old);
    glActiveTexture(unit);
    Values values = query();
    glActiveTexture(static_cast<GLenum>(old));
    return values;
}

Values onClientUnit(GLenum unit, const std::function<Values()>& query)
{
    GLint old = GL_TEXTURE0;
    glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &old);
    glClientActiveTexture(unit);
    Values values = query();
    glClientActiveTexture(static_cast<GLenum>(old));
    return values;
}

// Column-major 4x4 times a 4-vector, in double: GL transforms light positions in float, so
// these compare with a relative tolerance.
Values transformPoint(const std::array<float, 16>& m, const std::array<float, 4>& p)
{
    Values out(4, 0.0);
    for (int row = 0; row < 4; ++row) {
        for (int k = 0; k < 4; ++k) {
            out[row] += static_cast<double>(m[k * 4 + row]) * p[k];
        }
    }
    return out;
}

Values transformDirection(const std::array<float, 16>& m, const std::array<float, 3>& d)
{
    Values out(3, 0.0);
    for (int row = 0; row < 3; ++row) {
        for (int k = 0; k < 3; ++k) {
            out[row] += static_cast<double>(m[k * 4 + row]) * d[k];
        }
    }
    return out;
}

// A rotation about a unit axis plus a translation, column-major, in float as GL keeps it.
std::array<float, 16> rigidMatrix(double angleDegrees, double ax, double ay, double az,
                                  float tx, float ty, float tz)
{
    double a = angleDegrees * 3.14159265358979323846 / 180.0;
    double c = std::cos(a);
    double s = std::sin(a);
    double length = std::sqrt(ax * ax + ay * ay + az * az);
    ax /= length;
    ay /= length;
    az /= length;
    double r[3][3] = {{c + ax * ax * (1 - c), ax * ay * (1 - c) - az * s,
                       ax * az * (1 - c) + ay * s},
                      {ay * ax * (1 - c) + az * s, c + ay * ay * (1 - c),
                       ay * az * (1 - c) - ax * s},
                      {az * ax * (1 - c) - ay * s, az * ay * (1 - c) + ax * s,
                       c + az * az * (1 - c)}};
    std::array<float, 16> m{};
    for (int col = 0; col < 3; ++col) {
        for (int row = 0; row < 3; ++row) {
            m[col * 4 + row] = static_cast<float>(r[row][col]);
        }
    }
    m[12] = tx;
    m[13] = ty;
    m[14] = tz;
    m[15] = 1.0f;
    return m;
}

const char* errorName(GLenum error)
{
    switch (error) {
    case GL_NO_ERROR: return "GL_NO_ERROR";
    case GL_INVALID_ENUM: return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE: return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION: return "GL_INVALID_OPERATION";
    case GL_STACK_OVERFLOW: return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW: return "GL_STACK_UNDERFLOW";
    case GL_OUT_OF_MEMORY: return "GL_OUT_OF_MEMORY";
    default: return "unknown error";
    }
}

// One piece of state: how to query it and what the program set.
struct Item {
    std::string name;
    std::function<Values()> query;
    Values expected;
    bool transformed = false; // GL transformed it (light positions): 1e-5 relative
};

bool sameValues(const Values& expected, const Values& actual, bool transformed)
{
    if (expected.size() != actual.size()) {
        return false;
    }
    double scale = 1.0;
    for (double e : expected) {
        scale = std::max(scale, std::fabs(e));
    }
    for (size_t i = 0; i < expected.size(); ++i) {
        // Exact unless GL computed the value itself; NaN never equals anything.
        bool equal = transformed ? std::fabs(expected[i] - actual[i]) <= 1e-5 * scale
                                 : expected[i] == actual[i];
        if (!equal) {
            return false;
        }
    }
    return true;
}

constexpr int imageSize = 16; // the glDrawPixels badge


class StateScene : public demo::Scene {
public:
    bool init(const demo::Options& options, std::string& error) override
    {
        width_ = options.width;
        height_ = options.height;
        report_ = options.report;
        buildBadge();
        buildCube();

        glGenTextures(2, textures_);
        makeTexture(textures_[0], 0xd0, 0x40);
        makeTexture(textures_[1], 0x30, 0xf0);
        glGenBuffers(2, buffers_);
        glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
        glBufferData(GL_ARRAY_BUFFER, 4096, nullptr, GL_STATIC_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, 256, nullptr, GL_STATIC_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);

        listBase_ = glGenLists(2);
        if (listBase_ == 0) {
            error = "glGenLists failed";
            return false;
        }
        glNewList(listBase_, GL_COMPILE);
        demo::drawTorus(0.55f, 0.18f, 32, 12);
        glEndList();
        if (!glsl_.init(error)) return false;
        GLenum initError = glGetError();
        if (initError != GL_NO_ERROR) {
            error = std::string("setting up raised ") + errorName(initError);
            return false;
        }
        return true;
    }

    void draw(int frame) override
    {
        frame_ = frame;
        errorChecksThisFrame_ = 0;
        if (frame > 1) {
            // The state set at the end of the previous frame survived glFinish/SwapBuffers.
            expectError(GL_INVALID_ENUM, "made before the previous frame's SwapBuffers");
            verify("after the previous frame's glFinish/SwapBuffers");
            restoreBaseline();
        }

        glViewport(0, 0, width_, height_);
        glClearColor(0.2f, 0.22f, 0.3f, 1.0f);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

        // An error made before the draws must still be pending after them.
        glLineWidth(-1.0f);
        drawScene(frame);
        // A draw with the program's own GLSL, and what GL says of that program from here on.
        glsl_.draw(frame);
        const std::vector<GlslProbe::Answer> answers = glsl_.expected();
        for (size_t i = 0; i < answers.size(); ++i) {
            expect("GLSL " + answers[i].name, [this, i] { return glsl_.ask()[i].values; },
                   answers[i].values);
        }
        expectError(GL_INVALID_VALUE, "glLineWidth(-1) made before the scene's draws");

        applyState(frame);
        verify("after the scene's draws");

        glEndList(); // GL_INVALID_OPERATION: no list is being compiled
        drawOverlay(frame);
        expectError(GL_INVALID_OPERATION, "glEndList() made before the overlay");
        verify("after the overlay");

        // The frame loop reads pixels with the pack state, so only the alignment (which it
        // saves and restores) stays non-default across the swap.
        glPixelStorei(GL_PACK_ROW_LENGTH, 0);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_PACK_SKIP_ROWS, 0);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_FALSE);
        glPixelStorei(GL_PACK_LSB_FIRST, GL_FALSE);
        expectInts(NAMED(GL_PACK_ROW_LENGTH), {0});
        expectInts(NAMED(GL_PACK_SKIP_PIXELS), {0});
        expectInts(NAMED(GL_PACK_SKIP_ROWS), {0});
        expectInts(NAMED(GL_PACK_SWAP_BYTES), {0});
        expectInts(NAMED(GL_PACK_LSB_FIRST), {0});
        verify("before glFinish/SwapBuffers");
        glMatrixMode(0x1234); // GL_INVALID_ENUM, checked after the swap
        ++framesChecked_;
    }

    void shutdown() override
    {
        if (framesChecked_ > 0) {
            errorChecksThisFrame_ = 0; // the same check as at the start of a frame
            expectError(GL_INVALID_ENUM, "made before the last frame's SwapBuffers");
            verify("after the last frame's glFinish/SwapBuffers");
        }
        glsl_.shutdown();
        glDeleteLists(listBase_, 2);
        glDeleteTextures(2, textures_);
        glDeleteBuffers(2, buffers_);
    }

    bool failed() const { return failed_; }
    bool report() const { return report_; }
    std::string glslSummary() const { return glsl_.summary(); }
    int framesChecked() const { return framesChecked_; }
    size_t itemCount() const { return items_.size() + errorChecks_; }

private:
    // ---- checking ---------------------------------------------------------------------

    void fail(const std::string& message)
    {
        if (!failed_) {
            std::fprintf(stderr, "demo_state: frame %d: %s\n", frame_, message.c_str());
            std::fflush(stderr);
        }
        failed_ = true;
    }

    // Adds an item, or replaces the one with the same name.
    void expect(const std::string& name, std::function<Values()> query, Values expected,
                bool transformed = false)
    {
        for (Item& item : items_) {
            if (item.name == name) {
                item.query = std::move(query);
                item.expected = std::move(expected);
                item.transformed = transformed;
                return;
            }
        }
        items_.push_back({name, std::move(query), std::move(expected), transformed});
    }

    void expectInts(GLenum pname, const char* name, Values expected)
    {
        int n = static_cast<int>(expected.size());
        expect(name, [=] { return getInts(pname, n); }, std::move(expected));
    }

    void expectFloats(GLenum pname, const char* name, Values expected)
    {
        int n = static_cast<int>(expected.size());
        expect(name, [=] { return getFloats(pname, n); }, std::move(expected));
    }

    void expectDoubles(GLenum pname, const char* name, Values expected)
    {
        int n = static_cast<int>(expected.size());
        expect(name, [=] { return getDoubles(pname, n); }, std::move(expected));
    }

    void expectBooleans(GLenum pname, const char* name, Values expected)
    {
        int n = static_cast<int>(expected.size());
        expect(name, [=] { return getBooleans(pname, n); }, std::move(expected));
    }

    void setEnabled(GLenum cap, const char* name, bool on)
    {
        on ? glEnable(cap) : glDisable(cap);
        expect(std::string("glIsEnabled(") + name + ")",
               [cap] { return Values{static_cast<double>(glIsEnabled(cap))}; },
               {on ? 1.0 : 0.0});
    }

    void setClientEnabled(GLenum array, const char* name, bool on)
    {
        on ? glEnableClientState(array) : glDisableClientState(array);
        expect(std::string("glIsEnabled(") + name + ")",
               [array] { return Values{static_cast<double>(glIsEnabled(array))}; },
               {on ? 1.0 : 0.0});
    }

    // glGetError must answer the error made on purpose, then GL_NO_ERROR.
    void expectError(GLenum expected, const char* what)
    {
        if (failed_) {
            return;
        }
        errorChecks_ = std::max(errorChecks_, ++errorChecksThisFrame_);
        GLenum first = glGetError();
        GLenum second = glGetError();
        if (first != expected || second != GL_NO_ERROR) {
            char message[256];
            std::snprintf(message, sizeof(message),
                          "glGetError after %s: set %s then GL_NO_ERROR, got %s (0x%x) "
                          "then %s (0x%x)",
                          what, errorName(expected), errorName(first), first,
                          errorName(second), second);
            fail(message);
        }
    }

    void verify(const char* when)
    {
        if (failed_) {
            return;
        }
        GLenum pending = glGetError();
        if (pending != GL_NO_ERROR) {
            fail(std::string(when) + ": unexpected pending " + errorName(pending));
            return;
        }
        for (const Item& item : items_) {
            Values actual = item.query();
            if (!sameValues(item.expected, actual, item.transformed)) {
                fail(std::string(when) + ": " + item.name + " differs: set "
                     + formatValues(item.expected) + ", got " + formatValues(actual));
                return;
            }
        }
        GLenum raised = glGetError();
        if (raised != GL_NO_ERROR) {
            fail(std::string(when) + ": the queries raised " + errorName(raised));
        }
    }

    // ---- the deliberately non-default state -----------------------------------------------

    // Everything set here is undone by restoreBaseline: attribute stacks cover most of it,
    // the matrix stacks are popped by hand.
    void applyState(int frame)
    {
        // Values vary a little per frame so a stale cache shows; all are exact in float.
        const float f = static_cast<float>(frame % 4) / 16.0f;

        // Deliberate errors, each answered once and then GL_NO_ERROR.
        glEnable(0x1234);
        expectError(GL_INVALID_ENUM, "glEnable(0x1234)");
        glPointSize(-2.0f);
        expectError(GL_INVALID_VALUE, "glPointSize(-2)");
        glPopAttrib();
        expectError(GL_STACK_UNDERFLOW, "glPopAttrib() on an empty stack");

        glPushAttrib(GL_ALL_ATTRIB_BITS);
        glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
        pushed_ = true;
        expectInts(NAMED(GL_ATTRIB_STACK_DEPTH), {1});
        expectInts(NAMED(GL_CLIENT_ATTRIB_STACK_DEPTH), {1});

        // Raster position first, with lighting and texturing off so its colour is the
        // current colour, and with the default depth range. Colour material off: while it
        // tracks a material, glMaterial cannot change that one.
        glDisable(GL_COLOR_MATERIAL);
        glDisable(GL_LIGHTING);
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_FOG);
        glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
        glWindowPos3f(37.0f + frame, 21.5f, 0.25f);
        expectFloats(NAMED(GL_CURRENT_RASTER_POSITION), {37.0 + frame, 21.5, 0.25, 1.0});
        expectBooleans(NAMED(GL_CURRENT_RASTER_POSITION_VALID), {1});
        expectFloats(NAMED(GL_CURRENT_RASTER_COLOR), {0.25, 0.5, 0.75, 1.0});

        // Matrices: modelview identity for light 0 and the clip plane, then two pushes.
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        const std::array<float, 4> light0Position = {1.0f, 2.0f, 4.0f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, light0Position.data());
        expect("GL_LIGHT0 GL_POSITION", [] { return getLight(GL_LIGHT0, GL_POSITION, 4); },
               {1.0, 2.0, 4.0, 0.0}, true);
        const GLdouble plane[] = {0.5, -0.25, 1.0, 2.0 + f};
        glClipPlane(GL_CLIP_PLANE0, plane);
        expect("GL_CLIP_PLANE0", [] {
                   GLdouble p[4];
                   glGetClipPlane(GL_CLIP_PLANE0, p);
                   return Values(p, p + 4);
               },
               {0.5, -0.25, 1.0, 2.0 + f}, true);

        glPushMatrix();
        modelview1_ = rigidMatrix(30.0 + frame, 1.0, 2.0, 0.5, 0.5f, -1.0f, -6.0f);
        glLoadMatrixf(modelview1_.data());
        const std::array<float, 4> light1Position = {-2.0f, 3.0f, 1.5f + f, 1.0f};
        const std::array<float, 3> spotDirection = {0.25f, -1.0f, -0.5f};
        glLightfv(GL_LIGHT1, GL_POSITION, light1Position.data());
        glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, spotDirection.data());
        expect("GL_LIGHT1 GL_POSITION", [] { return getLight(GL_LIGHT1, GL_POSITION, 4); },
               transformPoint(modelview1_, light1Position), true);
        expect("GL_LIGHT1 GL_SPOT_DIRECTION",
               [] { return getLight(GL_LIGHT1, GL_SPOT_DIRECTION, 3); },
               transformDirection(modelview1_, spotDirection), true);

        glPushMatrix();
        std::array<float, 16> modelview = rigidMatrix(-12.5, 0.0, 1.0, 1.0, 1.25f, 0.5f, -3.0f);
        modelview[0] = 2.0f; // not rigid: GL must keep it as given
        modelview[5] += f;
        glLoadMatrixf(modelview.data());
        expectFloats(NAMED(GL_MODELVIEW_MATRIX), Values(modelview.begin(), modelview.end()));
        Values transposed(16);
        for (int i = 0; i < 16; ++i) {
            transposed[i] = modelview[(i % 4) * 4 + i / 4];
        }
        expectFloats(NAMED(GL_TRANSPOSE_MODELVIEW_MATRIX), transposed);
        expectInts(NAMED(GL_MODELVIEW_STACK_DEPTH), {3});

        glMatrixMode(GL_PROJECTION);
        glPushMatrix();
        const std::array<float, 16> projection = {1.5f, 0, 0, 0, 0, 2.0f + f, 0, 0,
                                                  0.25f, -0.125f, -1.0625f, -1.0f,
                                                  0, 0, -0.5f, 0};
        glLoadMatrixf(projection.data());
        expectFloats(NAMED(GL_PROJECTION_MATRIX), Values(projection.begin(), projection.end()));
        expectInts(NAMED(GL_PROJECTION_STACK_DEPTH), {2});

        // Texture matrices on units 0 (pushed once) and 1.
        glActiveTexture(GL_TEXTURE0);
        glMatrixMode(GL_TEXTURE);
        glPushMatrix();
        const std::array<float, 16> texture0 = {2, 0, 0, 0, 0, 3, 0, 0,
                                                0, 0, 1, 0, 0.5f + f, 0.25f, 0, 1};
        glLoadMatrixf(texture0.data());
        glActiveTexture(GL_TEXTURE1);
        const std::array<float, 16> texture1 = {0, 1, 0, 0, -1, 0, 0, 0,
                                                0, 0, 1, 0, 0.125f, 0, 0, 1};
        glLoadMatrixf(texture1.data());
        auto unitMatrix = [](GLenum unit, GLenum pname, int n) {
            return [=] { return onUnit(unit, [=] { return getFloats(pname, n); }); };
        };
        expect("GL_TEXTURE_MATRIX (unit 0)", unitMatrix(GL_TEXTURE0, GL_TEXTURE_MATRIX, 16),
               Values(texture0.begin(), texture0.end()));
        expect("GL_TEXTURE_STACK_DEPTH (unit 0)",
               unitMatrix(GL_TEXTURE0, GL_TEXTURE_STACK_DEPTH, 1), {2});
        expect("GL_TEXTURE_MATRIX (unit 1)", unitMatrix(GL_TEXTURE1, GL_TEXTURE_MATRIX, 16),
               Values(texture1.begin(), texture1.end()));
        expect("GL_TEXTURE_STACK_DEPTH (unit 1)",
               unitMatrix(GL_TEXTURE1, GL_TEXTURE_STACK_DEPTH, 1), {1});

        // Texture bindings and environment per unit; unit 1 stays active.
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, textures_[1]);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
        const float envColour[] = {0.125f, 0.25f + f, 0.375f, 0.5f};
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envColour);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glEnable(GL_TEXTURE_GEN_S);
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
        glEnable(GL_TEXTURE_2D);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, textures_[0]);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
        glEnable(GL_TEXTURE_2D);
        auto unitQuery = [](GLenum unit, std::function<Values()> query) {
            return [=] { return onUnit(unit, query); };
        };
        auto texEnv = [](GLenum pname, int n) {
            return [=] {
                GLfloat v[4];
                glGetTexEnvfv(GL_TEXTURE_ENV, pname, v);
                return Values(v, v + n);
            };
        };
        auto texParameter = [](GLenum pname) {
            return [=] {
                GLint v = 0;
                glGetTexParameteriv(GL_TEXTURE_2D, pname, &v);
                return Values{static_cast<double>(v)};
            };
        };
        expect("GL_TEXTURE_BINDING_2D (unit 0)",
               unitQuery(GL_TEXTURE0, [] { return getInts(GL_TEXTURE_BINDING_2D, 1); }),
               {static_cast<double>(textures_[1])});
        expect("GL_TEXTURE_BINDING_2D (unit 1)",
               unitQuery(GL_TEXTURE1, [] { return getInts(GL_TEXTURE_BINDING_2D, 1); }),
               {static_cast<double>(textures_[0])});
        expect("GL_TEXTURE_ENV_MODE (unit 0)", unitQuery(GL_TEXTURE0, texEnv(
                   GL_TEXTURE_ENV_MODE, 1)), {GL_DECAL});
        expect("GL_TEXTURE_ENV_COLOR (unit 0)", unitQuery(GL_TEXTURE0, texEnv(
                   GL_TEXTURE_ENV_COLOR, 4)), Values(envColour, envColour + 4));
        expect("GL_TEXTURE_ENV_MODE (unit 1)", unitQuery(GL_TEXTURE1, texEnv(
                   GL_TEXTURE_ENV_MODE, 1)), {GL_ADD});
        auto isEnabled = [](GLenum cap) {
            return [=] { return Values{static_cast<double>(glIsEnabled(cap))}; };
        };
        expect("glIsEnabled(GL_TEXTURE_2D) (unit 0)",
               unitQuery(GL_TEXTURE0, isEnabled(GL_TEXTURE_2D)), {1});
        expect("glIsEnabled(GL_TEXTURE_GEN_S) (unit 0)",
               unitQuery(GL_TEXTURE0, isEnabled(GL_TEXTURE_GEN_S)), {1});
        expect("glIsEnabled(GL_TEXTURE_2D) (unit 1)",
               unitQuery(GL_TEXTURE1, isEnabled(GL_TEXTURE_2D)), {1});
        expect("glIsEnabled(GL_TEXTURE_GEN_S) (unit 1)",
               unitQuery(GL_TEXTURE1, isEnabled(GL_TEXTURE_GEN_S)), {0});
        expect("GL_TEXTURE_MIN_FILTER (unit 0 texture)",
               unitQuery(GL_TEXTURE0, texParameter(GL_TEXTURE_MIN_FILTER)), {GL_NEAREST});
        expect("GL_TEXTURE_WRAP_S (unit 0 texture)",
               unitQuery(GL_TEXTURE0, texParameter(GL_TEXTURE_WRAP_S)), {GL_CLAMP_TO_EDGE});
        expect("GL_TEXTURE_GEN_MODE (unit 0, S)", unitQuery(GL_TEXTURE0, [] {
                   GLint v = 0;
                   glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &v);
                   return Values{static_cast<double>(v)};
               }), {GL_SPHERE_MAP});
        expectInts(NAMED(GL_ACTIVE_TEXTURE), {GL_TEXTURE1});

        // Current values (unit 1 is active, so the texcoord query answers unit 1's).
        glColor4f(0.75f, 0.5f + f, 0.25f, 0.5f);
        glNormal3f(0.0f, -0.5f, 2.0f);
        glMultiTexCoord4f(GL_TEXTURE0, 0.25f, 0.75f, 0.0f, 1.0f);
        glMultiTexCoord4f(GL_TEXTURE1, -1.0f, 0.5f, 0.125f + f, 2.0f);
        glSecondaryColor3f(0.125f, 0.25f, 0.5f);
        glFogCoordf(3.5f);
        glEdgeFlag(GL_FALSE);
        expectFloats(NAMED(GL_CURRENT_COLOR), {0.75, 0.5 + f, 0.25, 0.5});
        expectFloats(NAMED(GL_CURRENT_NORMAL), {0.0, -0.5, 2.0});
        expect("GL_CURRENT_TEXTURE_COORDS (unit 0)",
               unitQuery(GL_TEXTURE0, [] { return getFloats(GL_CURRENT_TEXTURE_COORDS, 4); }),
               {0.25, 0.75, 0.0, 1.0});
        expect("GL_CURRENT_TEXTURE_COORDS (unit 1)",
               unitQuery(GL_TEXTURE1, [] { return getFloats(GL_CURRENT_TEXTURE_COORDS, 4); }),
               {-1.0, 0.5, 0.125 + f, 2.0});
        expectFloats(NAMED(GL_CURRENT_SECONDARY_COLOR), {0.125, 0.25, 0.5, 1.0});
        expectFloats(NAMED(GL_CURRENT_FOG_COORD), {3.5});
        expectBooleans(NAMED(GL_EDGE_FLAG), {0});

        // Enables.
        setEnabled(NAMED(GL_DEPTH_TEST), true);
        setEnabled(NAMED(GL_LIGHTING), true);
        setEnabled(NAMED(GL_LIGHT0), false);
        setEnabled(NAMED(GL_LIGHT1), true);
        setEnabled(NAMED(GL_LIGHT2), true);
        setEnabled(NAMED(GL_CULL_FACE), true);
        setEnabled(NAMED(GL_BLEND), true);
        setEnabled(NAMED(GL_NORMALIZE), frame % 2 == 0);
        setEnabled(NAMED(GL_RESCALE_NORMAL), true);
        setEnabled(NAMED(GL_FOG), true);
        setEnabled(NAMED(GL_POLYGON_OFFSET_FILL), true);
        setEnabled(NAMED(GL_POLYGON_OFFSET_LINE), true);
        setEnabled(NAMED(GL_SCISSOR_TEST), true);
        setEnabled(NAMED(GL_STENCIL_TEST), true);
        setEnabled(NAMED(GL_ALPHA_TEST), true);
        setEnabled(NAMED(GL_LINE_SMOOTH), true);
        setEnabled(NAMED(GL_POINT_SMOOTH), true);
        setEnabled(NAMED(GL_LINE_STIPPLE), true);
        setEnabled(NAMED(GL_POLYGON_STIPPLE), true);
        setEnabled(NAMED(GL_DITHER), false);
        setEnabled(NAMED(GL_CLIP_PLANE0), true);
        setEnabled(NAMED(GL_COLOR_SUM), true);
        setEnabled(NAMED(GL_AUTO_NORMAL), true);
        setEnabled(NAMED(GL_COLOR_LOGIC_OP), frame % 2 == 1);

        // Materials, then colour material: enabling it copies the current colour into the
        // back specular at once.
        const float ambient[] = {0.125f, 0.25f, 0.375f, 1.0f};
        const float diffuse[] = {0.5f, 0.625f + f, 0.75f, 0.875f};
        const float specular[] = {1.0f, 0.75f, 0.5f, 1.0f};
        const float emission[] = {0.0625f, 0.0f, 0.125f, 1.0f};
        const float backDiffuse[] = {0.25f, 0.75f, 0.25f, 1.0f};
        glMaterialfv(GL_FRONT, GL_AMBIENT, ambient);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
        glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
        glMaterialfv(GL_FRONT, GL_EMISSION, emission);
        glMaterialf(GL_FRONT, GL_SHININESS, 37.5f + frame % 8);
        glMaterialfv(GL_BACK, GL_DIFFUSE, backDiffuse);
        glMaterialf(GL_BACK, GL_SHININESS, 3.0f);
        glColorMaterial(GL_BACK, GL_SPECULAR);
        setEnabled(NAMED(GL_COLOR_MATERIAL), true);
        auto material = [](GLenum face, GLenum pname, int n) {
            return [=] {
                GLfloat v[4];
                glGetMaterialfv(face, pname, v);
                return Values(v, v + n);
            };
        };
        expect("GL_FRONT GL_AMBIENT", material(GL_FRONT, GL_AMBIENT, 4), Values(ambient,
               ambient + 4));
        expect("GL_FRONT GL_DIFFUSE", material(GL_FRONT, GL_DIFFUSE, 4), Values(diffuse,
               diffuse + 4));
        expect("GL_FRONT GL_SPECULAR", material(GL_FRONT, GL_SPECULAR, 4), Values(specular,
               specular + 4));
        expect("GL_FRONT GL_EMISSION", material(GL_FRONT, GL_EMISSION, 4), Values(emission,
               emission + 4));
        expect("GL_FRONT GL_SHININESS", material(GL_FRONT, GL_SHININESS, 1),
               {37.5 + frame % 8});
        expect("GL_BACK GL_DIFFUSE", material(GL_BACK, GL_DIFFUSE, 4), Values(backDiffuse,
               backDiffuse + 4));
        expect("GL_BACK GL_SHININESS", material(GL_BACK, GL_SHININESS, 1), {3.0});
        expect("GL_BACK GL_SPECULAR (colour material)", material(GL_BACK, GL_SPECULAR, 4),
               {0.75, 0.5 + f, 0.25, 0.5});
        expectInts(NAMED(GL_COLOR_MATERIAL_FACE), {GL_BACK});
        expectInts(NAMED(GL_COLOR_MATERIAL_PARAMETER), {GL_SPECULAR});

        // Lights (positions above) and the light model.
        const float light0Diffuse[] = {0.875f, 0.75f, 0.625f, 1.0f};
        const float light0Specular[] = {0.5f, 0.5f, 0.25f, 1.0f};
        const float light1Ambient[] = {0.0625f, 0.125f, 0.1875f, 1.0f};
        const float light1Diffuse[] = {0.25f, 0.5f + f, 1.0f, 1.0f};
        const float light1Specular[] = {0.0f, 0.25f, 0.0f, 0.5f};
        const float light0Ambient[] = {0.0625f, 0.0625f, 0.125f, 1.0f};
        glLightfv(GL_LIGHT0, GL_AMBIENT, light0Ambient);
        glLightfv(GL_LIGHT0, GL_DIFFUSE, light0Diffuse);
        glLightfv(GL_LIGHT0, GL_SPECULAR, light0Specular);
        glLightfv(GL_LIGHT1, GL_AMBIENT, light1Ambient);
        glLightfv(GL_LIGHT1, GL_DIFFUSE, light1Diffuse);
        glLightfv(GL_LIGHT1, GL_SPECULAR, light1Specular);
        glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 12.0f);
        glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 33.5f);
        glLightf(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 0.75f);
        glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.125f + f);
        glLightf(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 0.03125f);
        auto light = [](GLenum lightName, GLenum pname, int n) {
            return [=] { return getLight(lightName, pname, n); };
        };
        expect("GL_LIGHT0 GL_DIFFUSE", light(GL_LIGHT0, GL_DIFFUSE, 4),
               Values(light0Diffuse, light0Diffuse + 4));
        expect("GL_LIGHT0 GL_SPECULAR", light(GL_LIGHT0, GL_SPECULAR, 4),
               Values(light0Specular, light0Specular + 4));
        expect("GL_LIGHT0 GL_AMBIENT", light(GL_LIGHT0, GL_AMBIENT, 4),
               Values(light0Ambient, light0Ambient + 4));
        expect("GL_LIGHT1 GL_AMBIENT", light(GL_LIGHT1, GL_AMBIENT, 4),
               Values(light1Ambient, light1Ambient + 4));
        expect("GL_LIGHT1 GL_DIFFUSE", light(GL_LIGHT1, GL_DIFFUSE, 4),
               Values(light1Diffuse, light1Diffuse + 4));
        expect("GL_LIGHT1 GL_SPECULAR", light(GL_LIGHT1, GL_SPECULAR, 4),
               Values(light1Specular, light1Specular + 4));
        expect("GL_LIGHT1 GL_SPOT_EXPONENT", light(GL_LIGHT1, GL_SPOT_EXPONENT, 1), {12.0});
        expect("GL_LIGHT1 GL_SPOT_CUTOFF", light(GL_LIGHT1, GL_SPOT_CUTOFF, 1), {33.5});
        expect("GL_LIGHT1 GL_CONSTANT_ATTENUATION",
               light(GL_LIGHT1, GL_CONSTANT_ATTENUATION, 1), {0.75});
        expect("GL_LIGHT1 GL_LINEAR_ATTENUATION", light(GL_LIGHT1, GL_LINEAR_ATTENUATION, 1),
               {0.125 + f});
        expect("GL_LIGHT1 GL_QUADRATIC_ATTENUATION",
               light(GL_LIGHT1, GL_QUADRATIC_ATTENUATION, 1), {0.03125});
        const float modelAmbient[] = {0.25f, 0.125f, 0.0625f + f, 1.0f};
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, modelAmbient);
        glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
        expectFloats(NAMED(GL_LIGHT_MODEL_AMBIENT), Values(modelAmbient, modelAmbient + 4));
        expectBooleans(NAMED(GL_LIGHT_MODEL_LOCAL_VIEWER), {1});
        expectBooleans(NAMED(GL_LIGHT_MODEL_TWO_SIDE), {1});
        expectInts(NAMED(GL_LIGHT_MODEL_COLOR_CONTROL), {GL_SEPARATE_SPECULAR_COLOR});

        // Rasterisation and per-fragment state.
        glPolygonMode(GL_FRONT, GL_LINE);
        glPolygonMode(GL_BACK, GL_POINT);
        glShadeModel(GL_FLAT);
        glFrontFace(GL_CW);
        glCullFace(GL_FRONT_AND_BACK);
        glDepthFunc(GL_GEQUAL);
        glDepthRange(0.25, 0.75);
        glDepthMask(GL_FALSE);
        glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_DST_COLOR, GL_ZERO);
        glBlendEquationSeparate(GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
        glBlendColor(0.5f, 0.25f, 0.125f, 1.0f);
        glAlphaFunc(GL_GREATER, 0.375f + f);
        glStencilFunc(GL_NOTEQUAL, 5, 0x3c);
        glStencilOp(GL_INCR, GL_DECR_WRAP, GL_INVERT);
        glStencilMask(0x5a);
        glLogicOp(GL_XOR);
        glScissor(7, 9 + frame, 123, 45);
        glViewport(3, 4, width_ - 10, height_ - 20 + frame % 3);
        glLineWidth(2.5f + f);
        glPointSize(4.0f);
        glLineStipple(3, 0xf0f0);
        glPolygonOffset(1.5f, 2.0f + f);
        glPointParameterf(GL_POINT_SIZE_MIN, 1.5f);
        glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 2.5f);
        const float attenuation[] = {1.0f, 0.25f, 0.0625f};
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, attenuation);
        glPixelZoom(2.0f, -1.5f);
        expectInts(NAMED(GL_POLYGON_MODE), {GL_LINE, GL_POINT});
        expectInts(NAMED(GL_SHADE_MODEL), {GL_FLAT});
        expectInts(NAMED(GL_FRONT_FACE), {GL_CW});
        expectInts(NAMED(GL_CULL_FACE_MODE), {GL_FRONT_AND_BACK});
        expectInts(NAMED(GL_DEPTH_FUNC), {GL_GEQUAL});
        expectDoubles(NAMED(GL_DEPTH_RANGE), {0.25, 0.75});
        expectBooleans(NAMED(GL_DEPTH_WRITEMASK), {0});
        expectBooleans(NAMED(GL_COLOR_WRITEMASK), {1, 0, 1, 0});
        expectInts(NAMED(GL_BLEND_SRC_RGB), {GL_SRC_ALPHA});
        expectInts(NAMED(GL_BLEND_DST_RGB), {GL_ONE});
        expectInts(NAMED(GL_BLEND_SRC_ALPHA), {GL_ONE_MINUS_DST_COLOR});
        expectInts(NAMED(GL_BLEND_DST_ALPHA), {GL_ZERO});
        expectInts(NAMED(GL_BLEND_EQUATION_RGB), {GL_FUNC_REVERSE_SUBTRACT});
        expectInts(NAMED(GL_BLEND_EQUATION_ALPHA), {GL_MAX});
        expectFloats(NAMED(GL_BLEND_COLOR), {0.5, 0.25, 0.125, 1.0});
        expectInts(NAMED(GL_ALPHA_TEST_FUNC), {GL_GREATER});
        expectFloats(NAMED(GL_ALPHA_TEST_REF), {0.375 + f});
        expectInts(NAMED(GL_STENCIL_FUNC), {GL_NOTEQUAL});
        // GL answers the reference clamped to the stencil buffer's range (GLX: no stencil).
        GLint stencilBits = 0;
        glGetIntegerv(GL_STENCIL_BITS, &stencilBits);
        expectInts(NAMED(GL_STENCIL_REF), {std::min(5.0, std::ldexp(1.0, stencilBits) - 1)});
        expectInts(NAMED(GL_STENCIL_VALUE_MASK), {0x3c});
        expectInts(NAMED(GL_STENCIL_WRITEMASK), {0x5a});
        expectInts(NAMED(GL_STENCIL_FAIL), {GL_INCR});
        expectInts(NAMED(GL_STENCIL_PASS_DEPTH_FAIL), {GL_DECR_WRAP});
        expectInts(NAMED(GL_STENCIL_PASS_DEPTH_PASS), {GL_INVERT});
        expectInts(NAMED(GL_LOGIC_OP_MODE), {GL_XOR});
        expectInts(NAMED(GL_SCISSOR_BOX), {7, 9.0 + frame, 123, 45});
        expectInts(NAMED(GL_VIEWPORT), {3, 4, width_ - 10.0, height_ - 20.0 + frame % 3});
        expectFloats(NAMED(GL_LINE_WIDTH), {2.5 + f});
        expectFloats(NAMED(GL_POINT_SIZE), {4.0});
        expectInts(NAMED(GL_LINE_STIPPLE_REPEAT), {3});
        expectInts(NAMED(GL_LINE_STIPPLE_PATTERN), {0xf0f0});
        expectFloats(NAMED(GL_POLYGON_OFFSET_FACTOR), {1.5});
        expectFloats(NAMED(GL_POLYGON_OFFSET_UNITS), {2.0 + f});
        expectFloats(NAMED(GL_POINT_SIZE_MIN), {1.5});
        expectFloats(NAMED(GL_POINT_FADE_THRESHOLD_SIZE), {2.5});
        expectFloats(NAMED(GL_POINT_DISTANCE_ATTENUATION), {1.0, 0.25, 0.0625});
        expectFloats(NAMED(GL_ZOOM_X), {2.0});
        expectFloats(NAMED(GL_ZOOM_Y), {-1.5});

        // Fog.
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_DENSITY, 0.5f);
        glFogf(GL_FOG_START, 2.0f + f);
        glFogf(GL_FOG_END, 11.5f);
        const float fogColour[] = {0.375f, 0.25f, 0.125f, 0.0f};
        glFogfv(GL_FOG_COLOR, fogColour);
        glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
        expectInts(NAMED(GL_FOG_MODE), {GL_LINEAR});
        expectFloats(NAMED(GL_FOG_DENSITY), {0.5});
        expectFloats(NAMED(GL_FOG_START), {2.0 + f});
        expectFloats(NAMED(GL_FOG_END), {11.5});
        expectFloats(NAMED(GL_FOG_COLOR), Values(fogColour, fogColour + 4));
        expectInts(NAMED(GL_FOG_COORD_SRC), {GL_FOG_COORD});

        // Clear values, hints, lists, program.
        glClearColor(0.125f, 0.25f + f, 0.5f, 0.75f);
        glClearDepth(0.625);
        glClearStencil(3);
        glClearAccum(0.5f, 0.0f, 0.25f, 1.0f);
        glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
        glHint(GL_POINT_SMOOTH_HINT, GL_FASTEST);
        glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
        glHint(GL_POLYGON_SMOOTH_HINT, GL_FASTEST);
        glHint(GL_FOG_HINT, GL_NICEST);
        glListBase(listBase_ + 1000 + frame);
        glUseProgram(0);
        expectFloats(NAMED(GL_COLOR_CLEAR_VALUE), {0.125, 0.25 + f, 0.5, 0.75});
        expectDoubles(NAMED(GL_DEPTH_CLEAR_VALUE), {0.625});
        expectInts(NAMED(GL_STENCIL_CLEAR_VALUE), {3});
        expectFloats(NAMED(GL_ACCUM_CLEAR_VALUE), {0.5, 0.0, 0.25, 1.0});
        expectInts(NAMED(GL_PERSPECTIVE_CORRECTION_HINT), {GL_NICEST});
        expectInts(NAMED(GL_POINT_SMOOTH_HINT), {GL_FASTEST});
        expectInts(NAMED(GL_LINE_SMOOTH_HINT), {GL_NICEST});
        expectInts(NAMED(GL_POLYGON_SMOOTH_HINT), {GL_FASTEST});
        expectInts(NAMED(GL_FOG_HINT), {GL_NICEST});
        expectInts(NAMED(GL_LIST_BASE), {listBase_ + 1000.0 + frame});
        expectInts(NAMED(GL_CURRENT_PROGRAM), {0});

        // Pixel store.
        glPixelStorei(GL_PACK_ALIGNMENT, 2);
        glPixelStorei(GL_PACK_ROW_LENGTH, 17 + frame);
        glPixelStorei(GL_PACK_SKIP_PIXELS, 3);
        glPixelStorei(GL_PACK_SKIP_ROWS, 5);
        glPixelStorei(GL_PACK_SWAP_BYTES, GL_TRUE);
        glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 33);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 7 + frame);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_TRUE);
        glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
        glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 64);
        expectInts(NAMED(GL_PACK_ALIGNMENT), {2});
        expectInts(NAMED(GL_PACK_ROW_LENGTH), {17.0 + frame});
        expectInts(NAMED(GL_PACK_SKIP_PIXELS), {3});
        expectInts(NAMED(GL_PACK_SKIP_ROWS), {5});
        expectInts(NAMED(GL_PACK_SWAP_BYTES), {1});
        expectInts(NAMED(GL_PACK_LSB_FIRST), {1});
        expectInts(NAMED(GL_UNPACK_ALIGNMENT), {8});
        expectInts(NAMED(GL_UNPACK_ROW_LENGTH), {33});
        expectInts(NAMED(GL_UNPACK_SKIP_PIXELS), {2});
        expectInts(NAMED(GL_UNPACK_SKIP_ROWS), {7.0 + frame});
        expectInts(NAMED(GL_UNPACK_SWAP_BYTES), {1});
        expectInts(NAMED(GL_UNPACK_LSB_FIRST), {1});
        expectInts(NAMED(GL_UNPACK_IMAGE_HEIGHT), {64});

        // Client arrays: vertices from a buffer object, the rest from client memory; the
        // texcoord arrays of both units; client unit 1 stays active.
        glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
        glVertexPointer(3, GL_FLOAT, 24, reinterpret_cast<const void*>(48));
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glNormalPointer(GL_SHORT, 10, cube_.data() + 1);
        glColorPointer(4, GL_UNSIGNED_BYTE, 12, cube_.data() + 2);
        glClientActiveTexture(GL_TEXTURE0);
        glTexCoordPointer(2, GL_FLOAT, 20, cube_.data() + 3);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glClientActiveTexture(GL_TEXTURE1);
        glTexCoordPointer(3, GL_DOUBLE, 0, cube_.data() + 4);
        setClientEnabled(NAMED(GL_TEXTURE_COORD_ARRAY), false);
        setClientEnabled(NAMED(GL_VERTEX_ARRAY), true);
        setClientEnabled(NAMED(GL_NORMAL_ARRAY), true);
        setClientEnabled(NAMED(GL_COLOR_ARRAY), frame % 2 == 0);
        setClientEnabled(NAMED(GL_SECONDARY_COLOR_ARRAY), false);
        glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
        expectInts(NAMED(GL_ARRAY_BUFFER_BINDING), {static_cast<double>(buffers_[0])});
        expectInts(NAMED(GL_ELEMENT_ARRAY_BUFFER_BINDING), {static_cast<double>(buffers_[1])});
        expectInts(NAMED(GL_VERTEX_ARRAY_BUFFER_BINDING), {static_cast<double>(buffers_[0])});
        expectInts(NAMED(GL_NORMAL_ARRAY_BUFFER_BINDING), {0});
        expectInts(NAMED(GL_VERTEX_ARRAY_SIZE), {3});
        expectInts(NAMED(GL_VERTEX_ARRAY_TYPE), {GL_FLOAT});
        expectInts(NAMED(GL_VERTEX_ARRAY_STRIDE), {24});
        expect("GL_VERTEX_ARRAY_POINTER", [] { return getPointer(GL_VERTEX_ARRAY_POINTER); },
               {48});
        expectInts(NAMED(GL_NORMAL_ARRAY_TYPE), {GL_SHORT});
        expectInts(NAMED(GL_NORMAL_ARRAY_STRIDE), {10});
        expect("GL_NORMAL_ARRAY_POINTER", [] { return getPointer(GL_NORMAL_ARRAY_POINTER); },
               pointerValue(cube_.data() + 1));
        expectInts(NAMED(GL_COLOR_ARRAY_SIZE), {4});
        expectInts(NAMED(GL_COLOR_ARRAY_TYPE), {GL_UNSIGNED_BYTE});
        expectInts(NAMED(GL_COLOR_ARRAY_STRIDE), {12});
        expect("GL_COLOR_ARRAY_POINTER", [] { return getPointer(GL_COLOR_ARRAY_POINTER); },
               pointerValue(cube_.data() + 2));
        auto clientUnit = [](GLenum unit, std::function<Values()> query) {
            return [=] { return onClientUnit(unit, query); };
        };
        expect("glIsEnabled(GL_TEXTURE_COORD_ARRAY) (client unit 0)",
               clientUnit(GL_TEXTURE0, [] {
                   return Values{static_cast<double>(glIsEnabled(GL_TEXTURE_COORD_ARRAY))};
               }), {1});
        expect("GL_TEXTURE_COORD_ARRAY_SIZE (client unit 0)",
               clientUnit(GL_TEXTURE0, [] { return getInts(GL_TEXTURE_COORD_ARRAY_SIZE, 1); }),
               {2});
        expect("GL_TEXTURE_COORD_ARRAY_TYPE (client unit 0)",
               clientUnit(GL_TEXTURE0, [] { return getInts(GL_TEXTURE_COORD_ARRAY_TYPE, 1); }),
               {GL_FLOAT});
        expect("GL_TEXTURE_COORD_ARRAY_STRIDE (client unit 0)", clientUnit(GL_TEXTURE0, [] {
                   return getInts(GL_TEXTURE_COORD_ARRAY_STRIDE, 1);
               }), {20});
        expect("GL_TEXTURE_COORD_ARRAY_POINTER (client unit 0)", clientUnit(GL_TEXTURE0, [] {
                   return getPointer(GL_TEXTURE_COORD_ARRAY_POINTER);
               }), pointerValue(cube_.data() + 3));
        expect("GL_TEXTURE_COORD_ARRAY_SIZE (client unit 1)",
               clientUnit(GL_TEXTURE1, [] { return getInts(GL_TEXTURE_COORD_ARRAY_SIZE, 1); }),
               {3});
        expect("GL_TEXTURE_COORD_ARRAY_TYPE (client unit 1)",
               clientUnit(GL_TEXTURE1, [] { return getInts(GL_TEXTURE_COORD_ARRAY_TYPE, 1); }),
               {GL_DOUBLE});
        expect("GL_TEXTURE_COORD_ARRAY_POINTER (client unit 1)", clientUnit(GL_TEXTURE1, [] {
                   return getPointer(GL_TEXTURE_COORD_ARRAY_POINTER);
               }), pointerValue(cube_.data() + 4));
        expectInts(NAMED(GL_CLIENT_ACTIVE_TEXTURE), {GL_TEXTURE1});

        // Matrix mode last, so every matrix call above left it somewhere else.
        const GLenum modes[] = {GL_TEXTURE, GL_PROJECTION, GL_MODELVIEW};
        glMatrixMode(modes[frame % 3]);
        expectInts(NAMED(GL_MATRIX_MODE), {static_cast<double>(modes[frame % 3])});
    }

    static Values getLight(GLenum lightName, GLenum pname, int n)
    {
        GLfloat v[4];
        glGetLightfv(lightName, pname, v);
        return Values(v, v + n);
    }

    // Undoes applyState: the attribute stacks restore the scene's state, the matrix stacks
    // are popped by hand.
    void restoreBaseline()
    {
        if (!pushed_) {
            return;
        }
        glPopClientAttrib();
        glPopAttrib();
        pushed_ = false;
        glMatrixMode(GL_PROJECTION);
        glPopMatrix();
        glActiveTexture(GL_TEXTURE1);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glActiveTexture(GL_TEXTURE0);
        glPopMatrix();
        glMatrixMode(GL_MODELVIEW);
        glPopMatrix();
        glPopMatrix();
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
        items_.clear();
    }

    // ---- drawing ------------------------------------------------------------------------

    void drawScene(int frame)
    {
        demo::setPerspective(40.0, static_cast<double>(width_) / height_, 1.0, 30.0);
        glLoadIdentity();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_NORMALIZE);
        glEnable(GL_CULL_FACE);
        const float lightDirection[] = {0.4f, 0.8f, 1.0f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
        const float specular[] = {0.6f, 0.6f, 0.6f, 1.0f};
        glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
        glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, textures_[0]);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        glEnable(GL_TEXTURE_2D);

        glTranslatef(0.0f, 0.0f, -7.0f);
        glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(frame * 3.0f, 0.0f, 1.0f, 0.0f);

        // Immediate mode: a textured sphere.
        glPushMatrix();
        glTranslatef(-1.4f, 0.0f, 0.0f);
        glColor3f(0.95f, 0.6f, 0.3f);
        demo::drawSphere(0.8f, 16, 24, 2.0f);
        glPopMatrix();

        // Client arrays: a textured cube.
        glPushMatrix();
        glTranslatef(1.4f, 0.0f, 0.0f);
        glRotatef(frame * 5.0f, 1.0f, 1.0f, 0.0f);
        glColor3f(0.4f, 0.8f, 0.5f);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glVertexPointer(3, GL_FLOAT, 8 * sizeof(float), cube_.data());
        glNormalPointer(GL_FLOAT, 8 * sizeof(float), cube_.data() + 3);
        glTexCoordPointer(2, GL_FLOAT, 8 * sizeof(float), cube_.data() + 6);
        glDrawArrays(GL_QUADS, 0, 24);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_NORMAL_ARRAY);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glPopMatrix();

        // Display list: an untextured torus.
        glDisable(GL_TEXTURE_2D);
        glPushMatrix();
        glTranslatef(0.0f, 1.3f, -0.5f);
        glRotatef(70.0f, 1.0f, 0.0f, 0.0f);
        glColor3f(0.5f, 0.55f, 0.95f);
        glCallList(listBase_);
        glPopMatrix();
    }

    // A 2D overlay on top: glBitmap text and a glDrawPixels badge. Everything it changes is
    // pushed and popped, so the state the checks expect is back afterwards.
    void drawOverlay(int frame)
    {
        glPushAttrib(GL_ALL_ATTRIB_BITS);
        glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
        glActiveTexture(GL_TEXTURE1);
        glDisable(GL_TEXTURE_2D);
        glActiveTexture(GL_TEXTURE0);
        glDisable(GL_TEXTURE_2D);
        demo::pushPixelProjection(width_, height_);
        for (GLenum cap : {GL_DEPTH_TEST, GL_LIGHTING, GL_BLEND, GL_FOG, GL_SCISSOR_TEST,
                           GL_STENCIL_TEST, GL_ALPHA_TEST, GL_COLOR_LOGIC_OP, GL_CLIP_PLANE0}) {
            glDisable(cap);
        }
        glViewport(0, 0, width_, height_);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glPixelZoom(1.0f, 1.0f);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
        glPixelStorei(GL_UNPACK_SWAP_BYTES, GL_FALSE);
        glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);

        // Colour sum stays on: Mesa's glPopAttrib does not restore GL_COLOR_SUM, so a black
        // secondary colour neutralises it instead.
        glSecondaryColor3f(0.0f, 0.0f, 0.0f);
        glColor3f(1.0f, 0.95f, 0.4f);
        glRasterPos2i(12, height_ - 26);
        font_.draw("STATE");
        glRasterPos2i(width_ - imageSize * 2 - 12, 12 + (frame % 4) * 4);
        glPixelZoom(2.0f, 2.0f);
        glDrawPixels(imageSize, imageSize, GL_RGBA, GL_UNSIGNED_BYTE, badge_.data());

        glMatrixMode(GL_MODELVIEW);
        glPopMatrix();
        glMatrixMode(GL_PROJECTION);
        glPopMatrix();
        glPopClientAttrib();
        glPopAttrib();
    }

    void buildBadge()
    {
        for (int y = 0; y < imageSize; ++y) {
            for (int x = 0; x < imageSize; ++x) {
                uint8_t* p = badge_.data() + (y * imageSize + x) * 4;
                bool border = x == 0 || y == 0 || x == imageSize - 1 || y == imageSize - 1;
                p[0] = border ? 255 : static_cast<uint8_t>(x * 16);
                p[1] = border ? 255 : static_cast<uint8_t>(y * 16);
                p[2] = border ? 255 : 128;
                p[3] = 255;
            }
        }
    }

    // 6 faces x 4 corners of position, normal and texcoord.
    void buildCube()
    {
        const float faces[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                   {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        const float half = 0.6f;
        cube_.clear();
        for (const auto& n : faces) {
            // Two axes spanning the face, ordered so the quad winds counter-clockwise.
            int axis = n[0] != 0 ? 0 : n[1] != 0 ? 1 : 2;
            float sign = n[axis];
            int a = (axis + 1) % 3;
            int b = (axis + 2) % 3;
            for (const auto& c : corners) {
                float p[3];
                p[axis] = sign * half;
                p[a] = c[0] * half;
                p[b] = c[1] * half * sign;
                cube_.insert(cube_.end(), {p[0], p[1], p[2], n[0], n[1], n[2],
                                           (c[0] + 1) / 2, (c[1] + 1) / 2});
            }
        }
    }

    static void makeTexture(GLuint texture, uint8_t light, uint8_t dark)
    {
        uint8_t texels[16 * 16 * 3];
        for (int y = 0; y < 16; ++y) {
            for (int x = 0; x < 16; ++x) {
                uint8_t v = ((x / 4 + y / 4) % 2) ? light : dark;
                texels[(y * 16 + x) * 3 + 0] = v;
                texels[(y * 16 + x) * 3 + 1] = v;
                texels[(y * 16 + x) * 3 + 2] = static_cast<uint8_t>(255 - v / 2);
            }
        }
        glBindTexture(GL_TEXTURE_2D, texture);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    int width_ = 0;
    int height_ = 0;
    int frame_ = 0;
    bool report_ = false;
    bool failed_ = false;
    bool pushed_ = false;
    int framesChecked_ = 0;
    size_t errorChecks_ = 0;
    size_t errorChecksThisFrame_ = 0;
    GLuint textures_[2] = {};
    GLuint buffers_[2] = {};
    GLuint listBase_ = 0;
    std::array<float, 16> modelview1_{};
    std::vector<float> cube_;
    demo::BitmapFont font_;
    std::array<uint8_t, imageSize * imageSize * 4> badge_{};
    std::vector<Item> items_;
    GlslProbe glsl_;
};

} // namespace

int main(int argc, char** argv)
{
    StateScene scene;
    int status = demo::run(argc, argv, "state", scene);
    if (status != 0) {
        return status;
    }
    if (scene.failed()) {
        return 1;
    }
    if (scene.report()) {
        std::printf("state checks: %zu items x %d frames, all equal\n", scene.itemCount(),
                    scene.framesChecked());
        std::printf("%s\n", scene.glslSummary().c_str());
    }
    return 0;
}
