// A small program per kind of GL context: probe_contexts KIND, where KIND is one of
//   glx-compat  glXCreateNewContext + glXMakeCurrent on an X window (the legacy path)
//   glx-core    glXCreateContextAttribsARB, OpenGL 3.3 core profile, glXMakeContextCurrent
//   glx-es2     glXCreateContextAttribsARB, GLX_CONTEXT_ES2_PROFILE_BIT_EXT, OpenGL ES 2.0
//   glx-es3     the same, OpenGL ES 3.0
//   egl-es1     eglBindAPI(EGL_OPENGL_ES_API), OpenGL ES 1.x, a pbuffer (surfaceless Mesa)
//   egl-es2     the same, OpenGL ES 2.0
//   egl-es3     the same, OpenGL ES 3.0
//   egl-compat  eglBindAPI(EGL_OPENGL_API), a compatibility context
//   egl-core    eglBindAPI(EGL_OPENGL_API), OpenGL 3.3 core profile
//   osmesa-compat / osmesa-core  (built as probe_contexts_osmesa)
// It draws four frames of a 3D cube with what its API has (glBegin and client arrays, fixed
// arrays, shaders from client arrays or a vertex array object), uploads a texture, and asks
// glGetError after every call of its own: 0 where the call raised nothing. It raises errors
// on purpose too, and asks for them only after the swap, where GL answers the first of them
// (and 0 next). Prints every answer that is not what GL gives natively, a checksum of each
// frame's pixels and, at the end, state it set. Exit 0, or 3 when the driver does not offer
// the kind.
#define GL_GLEXT_PROTOTYPES 1
#include "tests/probes/CubeFaces.h"

#if defined(PROBE_OSMESA)
#include <GL/osmesa.h>
#else
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <GL/glx.h>
#include <GL/glxext.h>
#include <X11/Xlib.h>
#endif
#include <GL/glext.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

constexpr int kWidth = 160, kHeight = 120, kFrames = 4;
enum class Api { Compat, Core, Es1, Es2, Es3 };

int gFrame = -1;
int gUnexpected = 0;
bool gChecking = true;

// What glGetError answers now must be `want`.
void expect(GLenum want, const char* after)
{
    const GLenum got = glGetError();
    if (got == want) return;
    std::printf("frame %d: after %s: glGetError 0x%x, expected 0x%x\n", gFrame, after, got, want);
    ++gUnexpected;
}

// A call of the probe's own: it raises no error (asked at once, unless errors are pending).
#define CALL(x)                                                                                 \
    do {                                                                                        \
        x;                                                                                      \
        if (gChecking) expect(GL_NO_ERROR, #x);                                                 \
    } while (0)

struct Mat4 {
    float m[16];
};

Mat4 multiply(const Mat4& a, const Mat4& b)
{
    Mat4 r{};
    for (int c = 0; c < 4; ++c) {
        for (int row = 0; row < 4; ++row) {
            float s = 0.0f;
            for (int k = 0; k < 4; ++k) s += a.m[k * 4 + row] * b.m[c * 4 + k];
            r.m[c * 4 + row] = s;
        }
    }
    return r;
}

Mat4 perspective()
{
    const float n = 1.0f, f = 10.0f, t = 0.6f, r = t * float(kWidth) / float(kHeight);
    return {{n / r, 0, 0, 0, 0, n / t, 0, 0, 0, 0, -(f + n) / (f - n), -1, 0, 0,
             -2 * f * n / (f - n), 0}};
}

Mat4 modelview(int frame)
{
    const float a = 0.4f + 0.3f * float(frame), c = std::cos(a), s = std::sin(a);
    const float b = 0.5f, cb = std::cos(b), sb = std::sin(b);
    const Mat4 spin = {{c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1}};
    const Mat4 tilt = {{1, 0, 0, 0, 0, cb, sb, 0, 0, -sb, cb, 0, 0, 0, -4, 1}};
    return multiply(tilt, spin);
}

// A cube as 36 vertices (x y z) and a colour per vertex (r g b a).
void cube(std::vector<float>& positions, std::vector<float>& colours)
{
    const auto& kFaces = nprgl::probes::kCubeFaces;
    static const float kColours[6][3] = {{0.9f, 0.3f, 0.2f}, {0.2f, 0.7f, 0.3f},
                                         {0.2f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f},
                                         {0.7f, 0.3f, 0.8f}, {0.3f, 0.8f, 0.8f}};
    static const int kCorners[6] = {0, 1, 2, 0, 2, 3};
    for (int f = 0; f < 6; ++f) {
        for (int k : kCorners) {
            for (int i = 0; i < 3; ++i) positions.push_back(0.8f * float(kFaces[f][k][i]));
            colours.insert(colours.end(), {kColours[f][0], kColours[f][1], kColours[f][2], 1.0f});
        }
    }
}

struct Scene {
    Api api = Api::Compat;
    std::vector<float> positions, colours;
    std::vector<GLushort> indices; // the cube's second half, drawn with glDrawElements
    GLuint texture = 0, program = 0, vao = 0, vbo = 0;
    GLint mvp = -1;
};

GLuint shader(GLenum type, const char* source)
{
    GLuint s = 0;
    CALL(s = glCreateShader(type));
    CALL(glShaderSource(s, 1, &source, nullptr));
    CALL(glCompileShader(s));
    GLint ok = 0;
    CALL(glGetShaderiv(s, GL_COMPILE_STATUS, &ok));
    if (!ok) {
        char log[512] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        std::fprintf(stderr, "probe_contexts: shader: %s\n", log);
    }
    return s;
}

void setUp(Scene& s)
{
    cube(s.positions, s.colours);
    for (GLushort i = 18; i < 36; ++i) s.indices.push_back(i);
    // A texture, uploaded with a pixel store of the program's (bound, never sampled).
    const uint8_t texels[4 * 4 * 4] = {200, 40, 40, 255, 40, 200, 40, 255};
    CALL(glGenTextures(1, &s.texture));
    CALL(glBindTexture(GL_TEXTURE_2D, s.texture));
    CALL(glPixelStorei(GL_UNPACK_ALIGNMENT, 1));
    CALL(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST));
    CALL(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels));
    CALL(glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, texels));
    CALL(glDepthFunc(GL_LEQUAL));
    CALL(glFrontFace(GL_CCW));
    if (s.api == Api::Compat || s.api == Api::Es1) return;
    const char* vertex = nullptr;
    const char* fragment = nullptr;
    if (s.api == Api::Es2) {
        vertex = "attribute vec3 p; attribute vec4 c; uniform mat4 mvp; varying vec4 v;\n"
                 "void main() { v = c; gl_Position = mvp * vec4(p, 1.0); }\n";
        fragment = "precision mediump float; varying vec4 v;\n"
                   "void main() { gl_FragColor = v; }\n";
    } else if (s.api == Api::Es3) {
        vertex = "#version 300 es\nlayout(location = 0) in vec3 p;\n"
                 "layout(location = 1) in vec4 c; uniform mat4 mvp; out vec4 v;\n"
                 "void main() { v = c; gl_Position = mvp * vec4(p, 1.0); }\n";
        fragment = "#version 300 es\nprecision mediump float; in vec4 v; out vec4 o;\n"
                   "void main() { o = v; }\n";
    } else {
        vertex = "#version 330 core\nlayout(location = 0) in vec3 p;\n"
                 "layout(location = 1) in vec4 c; uniform mat4 mvp; out vec4 v;\n"
                 "void main() { v = c; gl_Position = mvp * vec4(p, 1.0); }\n";
        fragment = "#version 330 core\nin vec4 v; out vec4 o;\nvoid main() { o = v; }\n";
    }
    CALL(s.program = glCreateProgram());
    CALL(glAttachShader(s.program, shader(GL_VERTEX_SHADER, vertex)));
    CALL(glAttachShader(s.program, shader(GL_FRAGMENT_SHADER, fragment)));
    CALL(glBindAttribLocation(s.program, 0, "p"));
    CALL(glBindAttribLocation(s.program, 1, "c"));
    CALL(glLinkProgram(s.program));
    CALL(s.mvp = glGetUniformLocation(s.program, "mvp"));
    if (s.api != Api::Core) return;
    // A core profile draws from buffers through a vertex array object.
    CALL(glGenVertexArrays(1, &s.vao));
    CALL(glBindVertexArray(s.vao));
    CALL(glGenBuffers(1, &s.vbo));
    CALL(glBindBuffer(GL_ARRAY_BUFFER, s.vbo));
    const size_t pBytes = s.positions.size() * sizeof(float);
    const size_t cBytes = s.colours.size() * sizeof(float);
    CALL(glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(pBytes + cBytes), nullptr, GL_STATIC_DRAW));
    CALL(glBufferSubData(GL_ARRAY_BUFFER, 0, GLsizeiptr(pBytes), s.positions.data()));
    CALL(glBufferSubData(GL_ARRAY_BUFFER, GLintptr(pBytes), GLsizeiptr(cBytes),
                         s.colours.data()));
    CALL(glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr));
    CALL(glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0,
                               reinterpret_cast<const void*>(pBytes)));
    CALL(glEnableVertexAttribArray(0));
    CALL(glEnableVertexAttribArray(1));
}

// The cube: half from one draw call, half from another.
void drawCube(Scene& s, int frame)
{
    const Mat4 mv = modelview(frame);
    if (s.api == Api::Compat || s.api == Api::Es1) {
        CALL(glMatrixMode(GL_PROJECTION));
        CALL(glLoadMatrixf(perspective().m));
        CALL(glMatrixMode(GL_MODELVIEW));
        CALL(glLoadMatrixf(mv.m));
        if (s.api == Api::Compat) {
            // Immediate mode (no glGetError inside glBegin..glEnd: it is an error there).
            glBegin(GL_TRIANGLES);
            for (size_t v = 0; v < 18; ++v) {
                glColor4fv(&s.colours[v * 4]);
                glVertex3fv(&s.positions[v * 3]);
            }
            CALL(glEnd());
        } else {
            CALL(glColor4f(0.5f, 0.5f, 0.5f, 1.0f));
        }
        CALL(glEnableClientState(GL_VERTEX_ARRAY));
        CALL(glEnableClientState(GL_COLOR_ARRAY));
        CALL(glVertexPointer(3, GL_FLOAT, 0, s.positions.data()));
        CALL(glColorPointer(4, GL_FLOAT, 0, s.colours.data()));
        if (s.api == Api::Es1) CALL(glDrawArrays(GL_TRIANGLES, 0, 18));
        CALL(glDrawElements(GL_TRIANGLES, GLsizei(s.indices.size()), GL_UNSIGNED_SHORT,
                            s.indices.data()));
        CALL(glDisableClientState(GL_COLOR_ARRAY));
        CALL(glDisableClientState(GL_VERTEX_ARRAY));
        return;
    }
    const Mat4 mvp = multiply(perspective(), mv);
    CALL(glUseProgram(s.program));
    CALL(glUniformMatrix4fv(s.mvp, 1, GL_FALSE, mvp.m));
    if (s.api != Api::Core) {
        CALL(glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, s.positions.data()));
        CALL(glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 0, s.colours.data()));
        CALL(glEnableVertexAttribArray(0));
        CALL(glEnableVertexAttribArray(1));
        CALL(glDrawArrays(GL_TRIANGLES, 0, 18));
        CALL(glDrawElements(GL_TRIANGLES, GLsizei(s.indices.size()), GL_UNSIGNED_SHORT,
                            s.indices.data()));
        CALL(glDisableVertexAttribArray(1));
        CALL(glDisableVertexAttribArray(0));
    } else {
        CALL(glDrawArrays(GL_TRIANGLES, 0, 36));
    }
    CALL(glUseProgram(0));
}

void clearFrame(int frame)
{
    CALL(glViewport(0, 0, kWidth, kHeight));
    CALL(glClearColor(0.1f, 0.15f + 0.05f * float(frame), 0.2f, 1.0f));
    CALL(glEnable(GL_DEPTH_TEST));
    CALL(glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT));
}

void printPixels()
{
    std::vector<uint8_t> pixels(size_t(kWidth) * kHeight * 4);
    CALL(glPixelStorei(GL_PACK_ALIGNMENT, 4));
    CALL(glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data()));
    uint64_t sum = 1469598103934665603ull;
    for (uint8_t p : pixels) sum = (sum ^ p) * 1099511628211ull;
    std::printf("frame %d: pixels %016llx\n", gFrame, static_cast<unsigned long long>(sum));
}

// Errors raised on purpose: the invalid enum of a glEnable, the invalid value of a width.
void raiseEnum() { glEnable(GLenum(0x1234)); }
void raiseValue() { glLineWidth(-1.0f); }

template <typename Swap> void frames(Scene& s, Swap swap)
{
    for (gFrame = 0; gFrame < kFrames; ++gFrame) {
        GLenum pending = GL_NO_ERROR;
        if (gFrame == 1) {
            // An error before everything the frame draws: GL keeps it through the frame.
            raiseEnum();
            pending = GL_INVALID_ENUM;
            gChecking = false;
        }
        clearFrame(gFrame);
        drawCube(s, gFrame);
        if (gFrame == 3) {
            // Two errors around a barrier between draws: GL answers the first, drops the second.
            raiseEnum();
            pending = GL_INVALID_ENUM;
            gChecking = false;
            CALL(glClear(GL_DEPTH_BUFFER_BIT));
            raiseValue();
            drawCube(s, gFrame);
        }
        if (pending == GL_NO_ERROR) printPixels();
        if (gFrame == 2) {
            raiseValue(); // just before the swap
            pending = GL_INVALID_VALUE;
            gChecking = false;
        }
        swap();
        expect(pending, "the swap");
        expect(GL_NO_ERROR, "the swap, asked again");
        gChecking = true;
    }
}

void printState(Api api)
{
    const bool fixed = api == Api::Compat || api == Api::Es1;
    const bool es = api == Api::Es1 || api == Api::Es2 || api == Api::Es3;
    std::string out = "state:";
    auto ints = [&](const char* name, GLenum e, int n) {
        GLint v[16] = {};
        CALL(glGetIntegerv(e, v));
        out += std::string(" ") + name + "=";
        for (int i = 0; i < n; ++i) out += (i ? "," : "") + std::to_string(v[i]);
    };
    auto floats = [&](const char* name, GLenum e, int n) {
        GLfloat v[16] = {};
        CALL(glGetFloatv(e, v));
        out += std::string(" ") + name + "=";
        char buf[32];
        for (int i = 0; i < n; ++i) {
            std::snprintf(buf, sizeof buf, "%s%g", i ? "," : "", double(v[i]));
            out += buf;
        }
    };
    auto enabled = [&](const char* name, GLenum e) {
        GLboolean on = GL_FALSE;
        CALL(on = glIsEnabled(e));
        out += std::string(" ") + name + "=" + (on ? "on" : "off");
    };
    ints("viewport", GL_VIEWPORT, 4);
    ints("scissor", GL_SCISSOR_BOX, 4);
    floats("clear", GL_COLOR_CLEAR_VALUE, 4);
    ints("depthFunc", GL_DEPTH_FUNC, 1);
    ints("frontFace", GL_FRONT_FACE, 1);
    ints("cullFace", GL_CULL_FACE_MODE, 1);
    ints("texture", GL_TEXTURE_BINDING_2D, 1);
    ints("activeTexture", GL_ACTIVE_TEXTURE, 1);
    ints("arrayBuffer", GL_ARRAY_BUFFER_BINDING, 1);
    ints("elementBuffer", GL_ELEMENT_ARRAY_BUFFER_BINDING, 1);
    ints("unpackAlignment", GL_UNPACK_ALIGNMENT, 1);
    ints("packAlignment", GL_PACK_ALIGNMENT, 1);
    floats("lineWidth", GL_LINE_WIDTH, 1);
    enabled("depthTest", GL_DEPTH_TEST);
    enabled("blend", GL_BLEND);
    enabled("cull", GL_CULL_FACE);
    enabled("scissorTest", GL_SCISSOR_TEST);
    if (fixed) {
        ints("matrixMode", GL_MATRIX_MODE, 1);
        floats("modelview", GL_MODELVIEW_MATRIX, 16);
        floats("projection", GL_PROJECTION_MATRIX, 16);
        floats("colour", GL_CURRENT_COLOR, 4);
        ints("shadeModel", GL_SHADE_MODEL, 1);
        ints("clientActiveTexture", GL_CLIENT_ACTIVE_TEXTURE, 1);
        enabled("lighting", GL_LIGHTING);
        enabled("texture2D", GL_TEXTURE_2D);
        enabled("vertexArray", GL_VERTEX_ARRAY);
    } else {
        ints("program", GL_CURRENT_PROGRAM, 1);
    }
    if (api == Api::Compat) {
        ints("attribStack", GL_ATTRIB_STACK_DEPTH, 1);
        ints("clientAttribStack", GL_CLIENT_ATTRIB_STACK_DEPTH, 1);
        ints("polygonMode", GL_POLYGON_MODE, 2);
    }
    if (!es) {
        ints("drawBuffer", GL_DRAW_BUFFER, 1);
        ints("readBuffer", GL_READ_BUFFER, 1);
    }
    if (api == Api::Es2) ints("framebuffer", GL_FRAMEBUFFER_BINDING, 1);
    if (api == Api::Core || api == Api::Es3 || api == Api::Compat) {
        ints("vertexArray", GL_VERTEX_ARRAY_BINDING, 1);
        ints("drawFramebuffer", GL_DRAW_FRAMEBUFFER_BINDING, 1);
        ints("readFramebuffer", GL_READ_FRAMEBUFFER_BINDING, 1);
        ints("renderbuffer", GL_RENDERBUFFER_BINDING, 1);
        ints("packBuffer", GL_PIXEL_PACK_BUFFER_BINDING, 1);
        ints("unpackBuffer", GL_PIXEL_UNPACK_BUFFER_BINDING, 1);
        ints("unpackRowLength", GL_UNPACK_ROW_LENGTH, 1);
    }
    std::printf("%s\n", out.c_str());
}

Api apiOf(const std::string& kind)
{
    const std::string tail = kind.substr(kind.find('-') + 1);
    return tail == "core"  ? Api::Core
           : tail == "es1" ? Api::Es1
           : tail == "es2" ? Api::Es2
           : tail == "es3" ? Api::Es3
                           : Api::Compat;
}

int run(Api api, const char* kind, void (*swap)(void*), void* data)
{
    gFrame = -1;
    // The very first answer: nothing raised yet (nprgl's own start-up calls must not show).
    expect(GL_NO_ERROR, "MakeCurrent");
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    std::printf("probe_contexts %s: %s\n", kind, version ? version : "(none)");
    Scene s;
    s.api = api;
    setUp(s);
    frames(s, [&] { swap(data); });
    gFrame = kFrames;
    printState(api);
    std::printf("unexpected errors: %d\n", gUnexpected);
    return 0;
}

#if defined(PROBE_OSMESA)

int runOSMesa(const std::string& kind)
{
    const bool core = apiOf(kind) == Api::Core;
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE, core ? OSMESA_CORE_PROFILE : OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, core ? 3 : 2,
                           OSMESA_CONTEXT_MINOR_VERSION, core ? 3 : 1, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    std::vector<uint8_t> buffer(size_t(kWidth) * kHeight * 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
        std::fprintf(stderr, "probe_contexts: no %s context\n", kind.c_str());
        return 3;
    }
    run(apiOf(kind), kind.c_str(), [](void*) { glFinish(); }, nullptr);
    OSMesaDestroyContext(ctx);
    return 0;
}

#else

struct GlxWindow {
    Display* dpy = nullptr;
    GLXDrawable drawable = 0;
};

int runGlx(const std::string& kind)
{
    const Api api = apiOf(kind);
    GlxWindow w;
    w.dpy = XOpenDisplay(nullptr);
    if (!w.dpy) {
        std::fprintf(stderr, "probe_contexts: no X display\n");
        return 2;
    }
    const int fbAttribs[] = {GLX_X_RENDERABLE, True, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT,
                             GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8,
                             GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 24, GLX_DOUBLEBUFFER, True, None};
    int count = 0;
    GLXFBConfig* configs = glXChooseFBConfig(w.dpy, DefaultScreen(w.dpy), fbAttribs, &count);
    if (!configs || count == 0) {
        std::fprintf(stderr, "probe_contexts: no GLX framebuffer config\n");
        return 2;
    }
    XVisualInfo* visual = glXGetVisualFromFBConfig(w.dpy, configs[0]);
    XSetWindowAttributes wa = {};
    wa.colormap =
        XCreateColormap(w.dpy, RootWindow(w.dpy, visual->screen), visual->visual, AllocNone);
    Window window = XCreateWindow(w.dpy, RootWindow(w.dpy, visual->screen), 0, 0, kWidth,
                                  kHeight, 0, visual->depth, InputOutput, visual->visual,
                                  CWColormap, &wa);
    XMapWindow(w.dpy, window);
    XFree(visual);
    GLXContext ctx = nullptr;
    GLXWindow glxWindow = 0;
    bool current = false;
    if (api == Api::Compat) {
        ctx = glXCreateNewContext(w.dpy, configs[0], GLX_RGBA_TYPE, nullptr, True);
        w.drawable = window;
        current = ctx && glXMakeCurrent(w.dpy, window, ctx);
    } else {
        auto create = reinterpret_cast<PFNGLXCREATECONTEXTATTRIBSARBPROC>(
            glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glXCreateContextAttribsARB")));
        const int major = api == Api::Core ? 3 : api == Api::Es3 ? 3 : 2;
        const int minor = api == Api::Core ? 3 : 0;
        const int profile = api == Api::Core ? GLX_CONTEXT_CORE_PROFILE_BIT_ARB
                                             : GLX_CONTEXT_ES2_PROFILE_BIT_EXT;
        const int attribs[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, major,
                               GLX_CONTEXT_MINOR_VERSION_ARB, minor,
                               GLX_CONTEXT_PROFILE_MASK_ARB, profile, None};
        if (create) ctx = create(w.dpy, configs[0], nullptr, True, attribs);
        if (ctx) {
            glxWindow = glXCreateWindow(w.dpy, configs[0], window, nullptr);
            w.drawable = glxWindow;
            current = glXMakeContextCurrent(w.dpy, glxWindow, glxWindow, ctx);
        }
    }
    XFree(configs);
    if (!current) {
        std::fprintf(stderr, "probe_contexts: no %s context\n", kind.c_str());
        return 3;
    }
    run(api, kind.c_str(),
        [](void* p) {
            auto* win = static_cast<GlxWindow*>(p);
            glXSwapBuffers(win->dpy, win->drawable);
        },
        &w);
    glXMakeContextCurrent(w.dpy, None, None, nullptr);
    glXDestroyContext(w.dpy, ctx);
    if (glxWindow) glXDestroyWindow(w.dpy, glxWindow);
    XDestroyWindow(w.dpy, window);
    XCloseDisplay(w.dpy);
    return 0;
}

struct EglSurface {
    EGLDisplay dpy = EGL_NO_DISPLAY;
    EGLSurface surface = EGL_NO_SURFACE;
};

int runEgl(const std::string& kind)
{
    const Api api = apiOf(kind);
    const bool es = api == Api::Es1 || api == Api::Es2 || api == Api::Es3;
    // Mesa's surfaceless platform: no window system, so the run does not depend on one.
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EglSurface e;
    e.dpy = getPlatformDisplay
                ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)
                : EGL_NO_DISPLAY;
    EGLint major = 0, minor = 0;
    if (e.dpy == EGL_NO_DISPLAY || !eglInitialize(e.dpy, &major, &minor) ||
        !eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API)) {
        std::fprintf(stderr, "probe_contexts: no EGL display (EGL error 0x%x)\n", eglGetError());
        return 2;
    }
    const EGLint renderable = api == Api::Es1   ? EGL_OPENGL_ES_BIT
                              : api == Api::Es2 ? EGL_OPENGL_ES2_BIT
                              : api == Api::Es3 ? EGL_OPENGL_ES3_BIT
                                                : EGL_OPENGL_BIT;
    const EGLint cfgAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                 renderable, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                 EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    EGLContext ctx = EGL_NO_CONTEXT;
    if (eglChooseConfig(e.dpy, cfgAttribs, &config, 1, &count) && count > 0) {
        const EGLint surfAttribs[] = {EGL_WIDTH, kWidth, EGL_HEIGHT, kHeight, EGL_NONE};
        e.surface = eglCreatePbufferSurface(e.dpy, config, surfAttribs);
        const EGLint esAttribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                    api == Api::Es1 ? 1 : api == Api::Es2 ? 2 : 3, EGL_NONE};
        const EGLint coreAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
        const EGLint* attribs = es ? esAttribs : api == Api::Core ? coreAttribs : nullptr;
        ctx = eglCreateContext(e.dpy, config, EGL_NO_CONTEXT, attribs);
    }
    if (e.surface == EGL_NO_SURFACE || ctx == EGL_NO_CONTEXT ||
        !eglMakeCurrent(e.dpy, e.surface, e.surface, ctx)) {
        std::fprintf(stderr, "probe_contexts: no %s context (EGL error 0x%x)\n", kind.c_str(),
                     eglGetError());
        return 3;
    }
    run(api, kind.c_str(),
        [](void* p) {
            auto* s = static_cast<EglSurface*>(p);
            eglSwapBuffers(s->dpy, s->surface);
        },
        &e);
    eglMakeCurrent(e.dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(e.dpy, ctx);
    eglDestroySurface(e.dpy, e.surface);
    eglTerminate(e.dpy);
    return 0;
}

#endif

} // namespace

int main(int argc, char** argv)
{
    const std::string kind = argc > 1 ? argv[1] : "";
#if defined(PROBE_OSMESA)
    if (kind == "osmesa-compat" || kind == "osmesa-core") return runOSMesa(kind);
#else
    if (kind.rfind("glx-", 0) == 0) return runGlx(kind);
    if (kind.rfind("egl-", 0) == 0) return runEgl(kind);
#endif
    std::fprintf(stderr, "probe_contexts: unknown kind '%s'\n", kind.c_str());
    return 2;
}
