// A GLEW/SDL-era program: every extension it uses is reached through ARB and EXT names fetched
// with GetProcAddress, never linked. One lit 3D scene per frame, five objects in a 3x2 grid:
//   cell 0  a cube from ARB vertex and element buffers (glBindBufferARB, glDrawElements);
//   cell 1  a quad with ARB multitexture: a detail texture on unit 0 modulated by a lightmap on
//           unit 1 with its own texture coordinates (glActiveTextureARB, glMultiTexCoord2fARB);
//   cell 2  a quad showing a texture rendered this frame through an EXT framebuffer object
//           (glBindFramebufferEXT, glFramebufferTexture2DEXT, a depth renderbuffer);
//   cell 3  an octahedron from client arrays locked with glLockArraysEXT, drawn in two passes;
//   cell 4  a cube drawn by an ARB shader object program (glCreateProgramObjectARB ...).
// Built three times, by context: PROBE_OSMESA (OSMesaGetProcAddress), PROBE_GLX (an Xlib
// window, glXCreateContextAttribsARB with a compatibility profile, glXMakeContextCurrent,
// glXGetProcAddressARB), PROBE_EGL (a pbuffer, eglGetProcAddress).
//   --frames N   frames to draw (default 3)
//   --empty      draws the background only
//   --save FILE  writes the last frame's RGBA bytes (bottom row first), read before the swap
// Prints "getproc checksum C covered N cells a b c d e f" (pixels not of the clear colour,
// whole frame and per cell, cell 0 top left, row by row).
#include "tests/probes/CubeFaces.h"
#include "tests/probes/ProbeTexture.h"

#include <GL/gl.h>
#include <GL/glext.h>
#if defined(PROBE_OSMESA)
#include <GL/osmesa.h>
#elif defined(PROBE_GLX)
#include <GL/glx.h>
#include <X11/Xlib.h>
#elif defined(PROBE_EGL)
#include <EGL/egl.h>
#include <EGL/eglext.h>
#else
#error "define PROBE_OSMESA, PROBE_GLX or PROBE_EGL"
#endif

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

constexpr int kWidth = 240, kHeight = 160;
constexpr uint8_t kClear[3] = {20, 40, 70};

void* procAddress(const char* name)
{
#if defined(PROBE_OSMESA)
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
#elif defined(PROBE_GLX)
    return reinterpret_cast<void*>(glXGetProcAddressARB(reinterpret_cast<const GLubyte*>(name)));
#else
    return reinterpret_cast<void*>(eglGetProcAddress(name));
#endif
}

bool missing = false;

template <typename T> void fetch(T& fn, const char* name)
{
    fn = reinterpret_cast<T>(procAddress(name));
    if (!fn) {
        std::fprintf(stderr, "probe_getproc: no %s\n", name);
        missing = true;
    }
}

struct Ext {
    PFNGLGENBUFFERSARBPROC genBuffers;
    PFNGLBINDBUFFERARBPROC bindBuffer;
    PFNGLBUFFERDATAARBPROC bufferData;
    PFNGLACTIVETEXTUREARBPROC activeTexture;
    PFNGLCLIENTACTIVETEXTUREARBPROC clientActiveTexture;
    PFNGLMULTITEXCOORD2FARBPROC multiTexCoord2f;
    PFNGLGENFRAMEBUFFERSEXTPROC genFramebuffers;
    PFNGLBINDFRAMEBUFFEREXTPROC bindFramebuffer;
    PFNGLFRAMEBUFFERTEXTURE2DEXTPROC framebufferTexture2D;
    PFNGLGENRENDERBUFFERSEXTPROC genRenderbuffers;
    PFNGLBINDRENDERBUFFEREXTPROC bindRenderbuffer;
    PFNGLRENDERBUFFERSTORAGEEXTPROC renderbufferStorage;
    PFNGLFRAMEBUFFERRENDERBUFFEREXTPROC framebufferRenderbuffer;
    PFNGLCHECKFRAMEBUFFERSTATUSEXTPROC checkFramebufferStatus;
    PFNGLLOCKARRAYSEXTPROC lockArrays;
    PFNGLUNLOCKARRAYSEXTPROC unlockArrays;
    PFNGLCREATESHADEROBJECTARBPROC createShaderObject;
    PFNGLSHADERSOURCEARBPROC shaderSource;
    PFNGLCOMPILESHADERARBPROC compileShader;
    PFNGLCREATEPROGRAMOBJECTARBPROC createProgramObject;
    PFNGLATTACHOBJECTARBPROC attachObject;
    PFNGLLINKPROGRAMARBPROC linkProgram;
    PFNGLUSEPROGRAMOBJECTARBPROC useProgramObject;
    PFNGLGETUNIFORMLOCATIONARBPROC getUniformLocation;
    PFNGLUNIFORM3FARBPROC uniform3f;
    PFNGLGETOBJECTPARAMETERIVARBPROC getObjectParameteriv;
    PFNGLGETINFOLOGARBPROC getInfoLog;
};

void fetchAll(Ext& e)
{
    fetch(e.genBuffers, "glGenBuffersARB");
    fetch(e.bindBuffer, "glBindBufferARB");
    fetch(e.bufferData, "glBufferDataARB");
    fetch(e.activeTexture, "glActiveTextureARB");
    fetch(e.clientActiveTexture, "glClientActiveTextureARB");
    fetch(e.multiTexCoord2f, "glMultiTexCoord2fARB");
    fetch(e.genFramebuffers, "glGenFramebuffersEXT");
    fetch(e.bindFramebuffer, "glBindFramebufferEXT");
    fetch(e.framebufferTexture2D, "glFramebufferTexture2DEXT");
    fetch(e.genRenderbuffers, "glGenRenderbuffersEXT");
    fetch(e.bindRenderbuffer, "glBindRenderbufferEXT");
    fetch(e.renderbufferStorage, "glRenderbufferStorageEXT");
    fetch(e.framebufferRenderbuffer, "glFramebufferRenderbufferEXT");
    fetch(e.checkFramebufferStatus, "glCheckFramebufferStatusEXT");
    fetch(e.lockArrays, "glLockArraysEXT");
    fetch(e.unlockArrays, "glUnlockArraysEXT");
    fetch(e.createShaderObject, "glCreateShaderObjectARB");
    fetch(e.shaderSource, "glShaderSourceARB");
    fetch(e.compileShader, "glCompileShaderARB");
    fetch(e.createProgramObject, "glCreateProgramObjectARB");
    fetch(e.attachObject, "glAttachObjectARB");
    fetch(e.linkProgram, "glLinkProgramARB");
    fetch(e.useProgramObject, "glUseProgramObjectARB");
    fetch(e.getUniformLocation, "glGetUniformLocationARB");
    fetch(e.uniform3f, "glUniform3fARB");
    fetch(e.getObjectParameteriv, "glGetObjectParameterivARB");
    fetch(e.getInfoLog, "glGetInfoLogARB");
}

// A unit cube as 24 vertices (normal, position per face corner) and 36 indices.
void cube(std::vector<float>& vertices, std::vector<GLushort>& indices)
{
    const auto& kFaces = nprgl::probes::kCubeFaces;
    static const float kNormals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0},
                                         {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    for (int f = 0; f < 6; ++f) {
        for (const auto& corner : kFaces[f]) {
            vertices.insert(vertices.end(), {kNormals[f][0], kNormals[f][1], kNormals[f][2]});
            for (int k = 0; k < 3; ++k) vertices.push_back(0.5f * float(corner[k]));
        }
        const GLushort b = GLushort(f * 4);
        indices.insert(indices.end(), {b, GLushort(b + 1), GLushort(b + 2), b, GLushort(b + 2),
                                       GLushort(b + 3)});
    }
}

GLuint texture(int size, bool lightmap)
{
    std::vector<uint8_t> texels(size_t(size) * size * 3);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            uint8_t* t = &texels[(size_t(y) * size + x) * 3];
            if (lightmap) { // a bright spot fading to dark: baked light
                const float dx = float(x) / float(size) - 0.3f, dy = float(y) / float(size) - 0.6f;
                const float v = std::fmax(0.15f, 1.0f - 2.0f * std::sqrt(dx * dx + dy * dy));
                t[0] = t[1] = t[2] = uint8_t(255.0f * v);
            } else { // a warm checker
                const bool on = ((x / 4) + (y / 4)) % 2 != 0;
                t[0] = on ? 230 : 160;
                t[1] = on ? 200 : 110;
                t[2] = on ? 120 : 60;
            }
        }
    }
    return nprgl::probes::uploadRgbTexture(texels, size, GL_LINEAR);
}

GLhandleARB shaderProgram(const Ext& e)
{
    static const char* kVertex = "void main() {\n"
                                 "    vec3 n = normalize(gl_NormalMatrix * gl_Normal);\n"
                                 "    gl_FrontColor = vec4(vec3(0.3 + 0.7 * max(n.z, 0.0)), 1.0);\n"
                                 "    gl_Position = ftransform();\n"
                                 "}\n";
    static const char* kFragment =
        "uniform vec3 tint;\n"
        "void main() { gl_FragColor = vec4(tint * gl_Color.rgb, 1.0); }\n";
    GLhandleARB program = e.createProgramObject();
    for (int i = 0; i < 2; ++i) {
        GLhandleARB shader =
            e.createShaderObject(i == 0 ? GL_VERTEX_SHADER_ARB : GL_FRAGMENT_SHADER_ARB);
        const char* text = i == 0 ? kVertex : kFragment;
        e.shaderSource(shader, 1, &text, nullptr);
        e.compileShader(shader);
        GLint ok = 0;
        e.getObjectParameteriv(shader, GL_OBJECT_COMPILE_STATUS_ARB, &ok);
        if (!ok) {
            char log[512] = {};
            e.getInfoLog(shader, sizeof log, nullptr, log);
            std::fprintf(stderr, "probe_getproc: shader: %s\n", log);
        }
        e.attachObject(program, shader);
    }
    e.linkProgram(program);
    return program;
}

// Places the next object in cell (column, row) of a 3x2 grid seen through one perspective.
void cell(int column, int row, float angle)
{
    glLoadIdentity();
    glTranslatef(-1.6f + 1.6f * float(column), 0.55f - 1.1f * float(row), -4.0f);
    glRotatef(angle, 0.6f, 1.0f, 0.2f);
    glScalef(0.75f, 0.75f, 0.75f);
}

struct Scene {
    GLuint buffers[2] = {};
    GLsizei cubeIndices = 0;
    GLuint detail = 0, lightmap = 0;
    GLuint fbo = 0, target = 0, depth = 0;
    std::vector<float> octahedron;
    std::vector<GLubyte> octahedronIndices;
    GLhandleARB program = 0;
    GLint tint = -1;
};

void setUp(const Ext& e, Scene& s)
{
    std::vector<float> vertices;
    std::vector<GLushort> indices;
    cube(vertices, indices);
    s.cubeIndices = GLsizei(indices.size());
    e.genBuffers(2, s.buffers);
    e.bindBuffer(GL_ARRAY_BUFFER_ARB, s.buffers[0]);
    e.bufferData(GL_ARRAY_BUFFER_ARB, GLsizeiptrARB(vertices.size() * sizeof(float)),
                 vertices.data(), GL_STATIC_DRAW_ARB);
    e.bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, s.buffers[1]);
    e.bufferData(GL_ELEMENT_ARRAY_BUFFER_ARB, GLsizeiptrARB(indices.size() * sizeof(GLushort)),
                 indices.data(), GL_STATIC_DRAW_ARB);
    e.bindBuffer(GL_ARRAY_BUFFER_ARB, 0);
    e.bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, 0);

    s.detail = texture(32, false);
    s.lightmap = texture(16, true);

    // The render target: a 64x64 colour texture and a depth renderbuffer.
    glGenTextures(1, &s.target);
    glBindTexture(GL_TEXTURE_2D, s.target);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    e.genFramebuffers(1, &s.fbo);
    e.bindFramebuffer(GL_FRAMEBUFFER_EXT, s.fbo);
    e.framebufferTexture2D(GL_FRAMEBUFFER_EXT, GL_COLOR_ATTACHMENT0_EXT, GL_TEXTURE_2D, s.target,
                           0);
    e.genRenderbuffers(1, &s.depth);
    e.bindRenderbuffer(GL_RENDERBUFFER_EXT, s.depth);
    e.renderbufferStorage(GL_RENDERBUFFER_EXT, GL_DEPTH_COMPONENT24, 64, 64);
    e.framebufferRenderbuffer(GL_FRAMEBUFFER_EXT, GL_DEPTH_ATTACHMENT_EXT, GL_RENDERBUFFER_EXT,
                              s.depth);
    if (e.checkFramebufferStatus(GL_FRAMEBUFFER_EXT) != GL_FRAMEBUFFER_COMPLETE_EXT)
        std::fprintf(stderr, "probe_getproc: framebuffer incomplete\n");
    e.bindFramebuffer(GL_FRAMEBUFFER_EXT, 0);

    // An octahedron: 6 vertices (position = normal direction), 8 triangles.
    s.octahedron = {0.6f, 0, 0, -0.6f, 0, 0, 0, 0.6f, 0, 0, -0.6f, 0, 0, 0, 0.6f, 0, 0, -0.6f};
    s.octahedronIndices = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
                           2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};

    s.program = shaderProgram(e);
    s.tint = e.getUniformLocation(s.program, "tint");
}

// The render-to-texture pass: a coloured triangle on a light background, in the FBO.
void renderTarget(const Ext& e, const Scene& s, float angle)
{
    e.bindFramebuffer(GL_FRAMEBUFFER_EXT, s.fbo);
    glViewport(0, 0, 64, 64);
    glClearColor(0.9f, 0.9f, 0.8f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1, 1, -1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(angle, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.1f, 0.1f);
    glVertex2f(-0.8f, -0.7f);
    glColor3f(0.1f, 0.7f, 0.1f);
    glVertex2f(0.8f, -0.7f);
    glColor3f(0.1f, 0.2f, 0.9f);
    glVertex2f(0.0f, 0.8f);
    glEnd();
    e.bindFramebuffer(GL_FRAMEBUFFER_EXT, 0);
}

void quad()
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex3f(-0.6f, -0.5f, 0);
    glTexCoord2f(1, 0);
    glVertex3f(0.6f, -0.5f, 0);
    glTexCoord2f(1, 1);
    glVertex3f(0.6f, 0.5f, 0);
    glTexCoord2f(0, 1);
    glVertex3f(-0.6f, 0.5f, 0);
    glEnd();
}

void drawFrame(const Ext& e, const Scene& s, int frame, bool empty)
{
    const float angle = 20.0f + 12.0f * float(frame);
    if (!empty) renderTarget(e, s, angle);
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(kClear[0] / 255.0f, kClear[1] / 255.0f, kClear[2] / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.4, 0.4, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    if (empty) return;
    const GLfloat light[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);

    // Cell 0: the cube from ARB buffers.
    cell(0, 0, angle);
    glColor3f(0.3f, 0.6f, 0.9f);
    e.bindBuffer(GL_ARRAY_BUFFER_ARB, s.buffers[0]);
    glNormalPointer(GL_FLOAT, 6 * sizeof(float), reinterpret_cast<const void*>(0));
    glVertexPointer(3, GL_FLOAT, 6 * sizeof(float),
                    reinterpret_cast<const void*>(3 * sizeof(float)));
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_VERTEX_ARRAY);
    e.bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, s.buffers[1]);
    glDrawElements(GL_TRIANGLES, s.cubeIndices, GL_UNSIGNED_SHORT, nullptr);
    e.bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, 0);
    e.bindBuffer(GL_ARRAY_BUFFER_ARB, 0);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);

    // Cell 1: detail texture on unit 0, lightmap on unit 1 (its own coordinates), unlit.
    glDisable(GL_LIGHTING);
    cell(1, 0, angle * 0.5f);
    glColor3f(1, 1, 1);
    e.activeTexture(GL_TEXTURE0_ARB);
    glBindTexture(GL_TEXTURE_2D, s.detail);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    e.activeTexture(GL_TEXTURE1_ARB);
    glBindTexture(GL_TEXTURE_2D, s.lightmap);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glBegin(GL_QUADS);
    const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (const auto& c : corners) {
        e.multiTexCoord2f(GL_TEXTURE0_ARB, 3.0f * c[0], 3.0f * c[1]);
        e.multiTexCoord2f(GL_TEXTURE1_ARB, c[0], c[1]);
        glVertex3f(1.2f * c[0] - 0.6f, c[1] - 0.5f, 0);
    }
    glEnd();
    glDisable(GL_TEXTURE_2D);
    e.activeTexture(GL_TEXTURE0_ARB);
    glDisable(GL_TEXTURE_2D);

    // Cell 2: the texture rendered through the framebuffer object, on a tilted quad.
    cell(2, 0, angle * 0.5f);
    glBindTexture(GL_TEXTURE_2D, s.target);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    quad();
    glDisable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_LIGHTING);

    // Cell 3: locked client arrays, drawn twice (a base pass and a decal-like second pass).
    cell(0, 1, angle);
    glVertexPointer(3, GL_FLOAT, 0, s.octahedron.data());
    glNormalPointer(GL_FLOAT, 0, s.octahedron.data());
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    e.lockArrays(0, 6);
    glColor3f(0.9f, 0.7f, 0.2f);
    glDrawElements(GL_TRIANGLES, 12, GL_UNSIGNED_BYTE, s.octahedronIndices.data());
    glColor3f(0.8f, 0.3f, 0.6f);
    glDrawElements(GL_TRIANGLES, 12, GL_UNSIGNED_BYTE, s.octahedronIndices.data() + 12);
    e.unlockArrays();
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);

    // Cell 4: a cube drawn by the shader program (immediate mode, its normals per face).
    cell(1, 1, -angle);
    e.useProgramObject(s.program);
    e.uniform3f(s.tint, 0.4f, 0.9f, 0.5f);
    std::vector<float> vertices;
    std::vector<GLushort> indices;
    cube(vertices, indices);
    glBegin(GL_TRIANGLES);
    for (GLushort i : indices) {
        glNormal3fv(&vertices[size_t(i) * 6]);
        glVertex3fv(&vertices[size_t(i) * 6 + 3]);
    }
    glEnd();
    e.useProgramObject(0);
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
}

// What the program prints and saves, from the frame it has just drawn.
void report(const char* save)
{
    std::vector<uint8_t> pixels(size_t(kWidth) * kHeight * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    uint64_t sum = 0;
    int covered = 0, cells[6] = {};
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const uint8_t* p = &pixels[(size_t(y) * kWidth + x) * 4];
            for (int c = 0; c < 3; ++c) sum = sum * 31 + p[c];
            const bool drawn = p[0] != kClear[0] || p[1] != kClear[1] || p[2] != kClear[2];
            covered += drawn;
            const int row = y < kHeight / 2 ? 1 : 0; // bottom row first in memory
            cells[row * 3 + x * 3 / kWidth] += drawn;
        }
    }
    if (save) {
        if (FILE* f = std::fopen(save, "wb")) {
            std::fwrite(pixels.data(), 1, pixels.size(), f);
            std::fclose(f);
        }
    }
    std::printf("getproc checksum %016llx covered %d cells %d %d %d %d %d %d error 0x%x\n",
                static_cast<unsigned long long>(sum), covered, cells[0], cells[1], cells[2],
                cells[3], cells[4], cells[5], glGetError());
}

} // namespace

int main(int argc, char** argv)
{
    int frames = 3;
    bool empty = false;
    const char* save = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) frames = std::atoi(argv[++i]);
        if (std::strcmp(argv[i], "--empty") == 0) empty = true;
        if (std::strcmp(argv[i], "--save") == 0 && i + 1 < argc) save = argv[++i];
    }
#if defined(PROBE_OSMESA)
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    std::vector<uint8_t> buffer(size_t(kWidth) * kHeight * 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) {
        std::fprintf(stderr, "probe_getproc: no OSMesa context\n");
        return 2;
    }
    auto swap = [] { glFinish(); };
#elif defined(PROBE_GLX)
    Display* dpy = XOpenDisplay(nullptr);
    if (!dpy) {
        std::fprintf(stderr, "probe_getproc: no X display\n");
        return 2;
    }
    const int fbAttribs[] = {GLX_X_RENDERABLE, True, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT,
                             GLX_RENDER_TYPE, GLX_RGBA_BIT, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8,
                             GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 24, GLX_DOUBLEBUFFER, True, None};
    int count = 0;
    GLXFBConfig* configs = glXChooseFBConfig(dpy, DefaultScreen(dpy), fbAttribs, &count);
    if (!configs || count == 0) {
        std::fprintf(stderr, "probe_getproc: no GLX framebuffer config\n");
        return 2;
    }
    XVisualInfo* visual = glXGetVisualFromFBConfig(dpy, configs[0]);
    XSetWindowAttributes wa = {};
    wa.colormap = XCreateColormap(dpy, RootWindow(dpy, visual->screen), visual->visual, AllocNone);
    Window window = XCreateWindow(dpy, RootWindow(dpy, visual->screen), 0, 0, kWidth, kHeight, 0,
                                  visual->depth, InputOutput, visual->visual, CWColormap, &wa);
    XMapWindow(dpy, window);
    GLXWindow drawable = glXCreateWindow(dpy, configs[0], window, nullptr);
    auto createContext = reinterpret_cast<PFNGLXCREATECONTEXTATTRIBSARBPROC>(
        procAddress("glXCreateContextAttribsARB"));
    const int ctxAttribs[] = {GLX_CONTEXT_MAJOR_VERSION_ARB, 2, GLX_CONTEXT_MINOR_VERSION_ARB, 1,
                              GLX_CONTEXT_PROFILE_MASK_ARB,
                              GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB, None};
    GLXContext ctx =
        createContext ? createContext(dpy, configs[0], nullptr, True, ctxAttribs) : nullptr;
    if (!ctx || !glXMakeContextCurrent(dpy, drawable, drawable, ctx)) {
        std::fprintf(stderr, "probe_getproc: no GLX context\n");
        return 2;
    }
    XFree(visual);
    XFree(configs);
    auto swap = [&] { glXSwapBuffers(dpy, drawable); };
#else
    // Mesa's surfaceless platform: no window system, so the run does not depend on one.
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    EGLDisplay dpy = getPlatformDisplay
                         ? getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY,
                                              nullptr)
                         : EGL_NO_DISPLAY;
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor) ||
        !eglBindAPI(EGL_OPENGL_API)) {
        std::fprintf(stderr, "probe_getproc: no EGL display (EGL error 0x%x)\n", eglGetError());
        return 2;
    }
    const EGLint cfgAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                 EGL_OPENGL_BIT, EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8,
                                 EGL_BLUE_SIZE, 8, EGL_DEPTH_SIZE, 24, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(dpy, cfgAttribs, &config, 1, &count) || count == 0) {
        std::fprintf(stderr, "probe_getproc: no EGL pbuffer config\n");
        return 2;
    }
    const EGLint surfAttribs[] = {EGL_WIDTH, kWidth, EGL_HEIGHT, kHeight, EGL_NONE};
    EGLSurface surface = eglCreatePbufferSurface(dpy, config, surfAttribs);
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, nullptr);
    if (surface == EGL_NO_SURFACE || ctx == EGL_NO_CONTEXT ||
        !eglMakeCurrent(dpy, surface, surface, ctx)) {
        std::fprintf(stderr, "probe_getproc: no EGL context\n");
        return 2;
    }
    auto swap = [&] { eglSwapBuffers(dpy, surface); };
#endif
    Ext e{};
    fetchAll(e);
    if (missing) return 2;
    Scene scene;
    setUp(e, scene);
    for (int frame = 0; frame < frames; ++frame) {
        drawFrame(e, scene, frame, empty);
        if (frame + 1 == frames) report(save);
        swap();
    }
#if defined(PROBE_OSMESA)
    OSMesaDestroyContext(ctx);
#elif defined(PROBE_GLX)
    glXMakeContextCurrent(dpy, None, None, nullptr);
    glXDestroyContext(dpy, ctx);
    glXDestroyWindow(dpy, drawable);
    XDestroyWindow(dpy, window);
    XCloseDisplay(dpy);
#else
    eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy, ctx);
    eglDestroySurface(dpy, surface);
    eglTerminate(dpy);
#endif
    return 0;
}
