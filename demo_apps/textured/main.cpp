// demo_textured: a lit cube, sphere and floor with procedurally generated textures
// (GL_MODULATE, no mipmaps, glTexCoord2f per vertex); --sphere-map gives the sphere a
// sphere-mapped reflection (generated coordinates) instead of its own, --linear-map object|eye
// stripes on generated linear coordinates; --face-textures gives
// each face of the cube its own texture (six glBegin/glEnd, one object); --translucent
// blends the sphere over the scene (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), --additive adds it
// to the scene (GL_ONE, GL_ONE, a glow); --cutout cuts round holes into the cube's faces by
// its texture's alpha and the alpha test (GL_GREATER 0.5), --cutout-blend blends it too
// (foliage's soft rims, depth written), --cutout-fine makes it a fine grille; --pushed-back
// draws the cube with a small positive polygon offset; --fog fades the
// scene into a pale linear fog between eye distances 6 and 11; --depth-prepass draws the
// scene twice, depth only (colour mask off), then colours at equal depth; --depth-occluder
// first draws a square in front of the scene into depth alone (colour mask off), a hole the
// scene does not show in; --depth-after draws the floor a second time, into depth alone, right
// after it (no change natively); --decal lays a yellow square on the floor with glPolygonOffset; --inset clears the top right quarter (scissored, colour and
// depth) and draws the scene again there, turned, like a rear-view mirror; --stale-panel
// leaves frame 1's panel in the buffer by clearing only depth later; --hud-bar draws a bar
// over the scene in 2D with the depth test (GL_LEQUAL): a white frame, then a blue gradient in
// it at the same depth; --late-shader makes a GLSL program of its own in frame 2 and draws an
// orange pane with it from then on, as games make theirs while they load; --alpha-mask draws
// the scene with alpha writes off over a colour cleared to alpha 0.25 and prints the
// destination alpha; --replace draws the cube's texture with GL_REPLACE under a blue
// material, which its picture then does not show (timetunnel's tunnel); --far-backdrop draws
// a dark blue gradient over the window at the far plane (identity matrices, z = 1, depth test
// GL_LEQUAL) before the scene, as xscreensaver's atlantis draws its water; --env-map first
// draws the scene into a 64x64 corner, copies it into a texture (glCopyTexSubImage2D, as
// foobillardplus makes its balls' environment maps), clears again, and after the scene shows
// that texture in 2D in the top-left corner (GL_REPLACE); --env-map-line draws a line over the
// corner's scene before the copy (a draw the styles leave: it flushes the scene first).

// Declares the GL 1.3-2.0 functions (glWindowPos); must precede every include of GL/gl.h.
#define GL_GLEXT_PROTOTYPES

#include "Demo.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <vector>

namespace {

constexpr float pi = std::numbers::pi_v<float>;
constexpr int textureSize = 64;

// Two-colour checkerboard with a thin darker border per cell.
std::vector<uint8_t> makeChecker(const uint8_t* a, const uint8_t* b, int cells)
{
    std::vector<uint8_t> pixels(textureSize * textureSize * 3);
    int cell = textureSize / cells;
    for (int y = 0; y < textureSize; ++y) {
        for (int x = 0; x < textureSize; ++x) {
            const uint8_t* colour = ((x / cell) + (y / cell)) % 2 == 0 ? a : b;
            bool border = x % cell == 0 || y % cell == 0;
            for (int c = 0; c < 3; ++c) {
                pixels[(y * textureSize + x) * 3 + c] =
                    static_cast<uint8_t>(border ? colour[c] * 3 / 4 : colour[c]);
            }
        }
    }
    return pixels;
}

// Diagonal stripes blending from orange to white, for the sphere.
std::vector<uint8_t> makeStripes()
{
    std::vector<uint8_t> pixels(textureSize * textureSize * 3);
    for (int y = 0; y < textureSize; ++y) {
        for (int x = 0; x < textureSize; ++x) {
            bool stripe = ((x + y) / 8) % 2 == 0;
            uint8_t* p = &pixels[(y * textureSize + x) * 3];
            p[0] = 255;
            p[1] = stripe ? 140 : 240;
            p[2] = stripe ? 20 : 220;
        }
    }
    return pixels;
}

// An image of textureSize squared, repeated: RGB filtered linearly, or RGBA nearest-filtered
// (cut-outs keep sharp edges).
GLuint uploadTexture(const std::vector<uint8_t>& pixels, GLenum format = GL_RGB)
{
    const GLint filter = format == GL_RGBA ? GL_NEAREST : GL_LINEAR;
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexImage2D(GL_TEXTURE_2D, 0, GLint(format), textureSize, textureSize, 0, format,
                 GL_UNSIGNED_BYTE, pixels.data());
    return texture;
}

// Red and white checks with a round hole (alpha 0) in the middle of each of 2 x 2 cells.
GLuint uploadHoles()
{
    std::vector<uint8_t> pixels(textureSize * textureSize * 4);
    const int cell = textureSize / 2;
    for (int y = 0; y < textureSize; ++y) {
        for (int x = 0; x < textureSize; ++x) {
            const float dx = float(x % cell) - 0.5f * float(cell) + 0.5f;
            const float dy = float(y % cell) - 0.5f * float(cell) + 0.5f;
            const bool hole = dx * dx + dy * dy < 0.1f * float(cell * cell);
            const bool red = ((x / cell) + (y / cell)) % 2 == 0;
            uint8_t* p = &pixels[(y * textureSize + x) * 4];
            p[0] = red ? 200 : 235;
            p[1] = red ? 40 : 235;
            p[2] = red ? 40 : 235;
            p[3] = hole ? 0 : 255;
        }
    }
    return uploadTexture(pixels, GL_RGBA);
}

// A grille: bars two texels wide around square holes two texels wide, red on white rows.
GLuint uploadGrille()
{
    std::vector<uint8_t> pixels(textureSize * textureSize * 4);
    for (int y = 0; y < textureSize; ++y) {
        for (int x = 0; x < textureSize; ++x) {
            const bool hole = x % 4 >= 2 && y % 4 >= 2;
            uint8_t* p = &pixels[(y * textureSize + x) * 4];
            p[0] = 200;
            p[1] = (y / 16) % 2 ? 40 : 200;
            p[2] = (y / 16) % 2 ? 40 : 200;
            p[3] = hole ? 0 : 255;
        }
    }
    return uploadTexture(pixels, GL_RGBA);
}

// White, opaque in a round patch and clear around it: a pool laid over the floor.
GLuint uploadPool()
{
    std::vector<uint8_t> pixels(textureSize * textureSize * 4, 255);
    for (int y = 0; y < textureSize; ++y) {
        for (int x = 0; x < textureSize; ++x) {
            const float dx = float(x) + 0.5f - 0.35f * textureSize;
            const float dy = float(y) + 0.5f - 0.4f * textureSize;
            const bool inside = dx * dx + dy * dy < 0.09f * textureSize * textureSize;
            pixels[(y * textureSize + x) * 4 + 3] = inside ? 255 : 0;
        }
    }
    return uploadTexture(pixels, GL_RGBA);
}

// With `faceTextures`, each face binds its own texture (outside glBegin/glEnd, as GL wants).
// The floor: a 6 x 6 quad at y = -1, its texture repeated `repeat` times each way.
void drawFloorQuad(float repeat)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-3.0f, -1.0f, 3.0f);
    glTexCoord2f(repeat, 0.0f);
    glVertex3f(3.0f, -1.0f, 3.0f);
    glTexCoord2f(repeat, repeat);
    glVertex3f(3.0f, -1.0f, -3.0f);
    glTexCoord2f(0.0f, repeat);
    glVertex3f(-3.0f, -1.0f, -3.0f);
    glEnd();
}

void drawCube(float half, const GLuint* faceTextures = nullptr)
{
    // Each face: normal, then the in-face s and t axes.
    const float faces[6][3][3] = {
        {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
        {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
    };
    const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    if (!faceTextures) glBegin(GL_QUADS);
    for (int f = 0; f < 6; ++f) {
        const auto& face = faces[f];
        if (faceTextures) {
            glBindTexture(GL_TEXTURE_2D, faceTextures[f]);
            glBegin(GL_QUADS);
        }
        glNormal3f(face[0][0], face[0][1], face[0][2]);
        for (const auto& st : corners) {
            float s = (2.0f * st[0] - 1.0f) * half;
            float t = (2.0f * st[1] - 1.0f) * half;
            glTexCoord2f(st[0], st[1]);
            glVertex3f(face[0][0] * half + face[1][0] * s + face[2][0] * t,
                       face[0][1] * half + face[1][1] * s + face[2][1] * t,
                       face[0][2] * half + face[1][2] * s + face[2][2] * t);
        }
        if (faceTextures) glEnd();
    }
    if (!faceTextures) glEnd();
}

class TexturedScene : public demo::Scene {
public:
    std::vector<demo::ExtraOption> extraOptions() const override
    {
        return {{"sphere-map", demo::ExtraOption::Kind::Flag,
                 "the sphere reflects its stripes by GL_SPHERE_MAP coordinates"},
                {"linear-map", demo::ExtraOption::Kind::Text,
                 "object or eye: the sphere's stripes on GL_OBJECT_LINEAR planes (turning with "
                 "it) or GL_EYE_LINEAR planes (fixed in the world, the sphere turning under "
                 "them)"},
                {"texgen-matrix", demo::ExtraOption::Kind::Flag,
                 "with --linear-map: the texture matrix doubles S (twice the stripes across)"},
                {"face-textures", demo::ExtraOption::Kind::Flag,
                 "each face of the cube has its own texture"},
                {"translucent", demo::ExtraOption::Kind::Flag,
                 "the sphere is blended over the scene at 60% opacity"},
                {"additive", demo::ExtraOption::Kind::Flag,
                 "the sphere is added to the scene (GL_ONE, GL_ONE)"},
                {"glow-alpha-test", demo::ExtraOption::Kind::Flag,
                 "with --additive: the alpha test on (GL_GREATER 0.01), as glowing text keeps "
                 "its glyphs' shape"},
                {"glow-list-plain", demo::ExtraOption::Kind::Flag,
                 "with --additive: the sphere is a display list that turns texturing (and "
                 "lighting) off inside it and glows plain blue, as glowing parts of a scene "
                 "compiled with their own state do"},
                {"late-floor", demo::ExtraOption::Kind::Flag,
                 "the floor gets a texture of its own made in frame 2, after the first frame "
                 "was drawn (games load textures as they go)"},
                {"alpha-mask", demo::ExtraOption::Kind::Flag,
                 "the scene drawn with glColorMask(1, 1, 1, 0) over a colour cleared to alpha "
                 "0.25 (as briquolo draws); after each frame prints the destination alpha at "
                 "five points of the scene"},
                {"late-shader", demo::ExtraOption::Kind::Flag,
                 "from frame 2, an orange pane beside the cube drawn with a GLSL program the "
                 "demo makes in that frame (its own shaders)"},
                {"backdrop-floor", demo::ExtraOption::Kind::Flag,
                 "the floor is a backdrop in the clear colour: unlit, untextured, drawn first "
                 "without the depth test or depth writes (a dark arena floor)"},
                {"backdrop-haze", demo::ExtraOption::Kind::Flag,
                 "with --backdrop-floor: a haze over the floor's far half, white at 25% "
                 "opacity, blended by alpha, also without the depth test (a sky's clouds)"},
                {"cutout", demo::ExtraOption::Kind::Flag,
                 "round holes in the cube's faces (texture alpha and the alpha test)"},
                {"pushed-back", demo::ExtraOption::Kind::Flag,
                 "the cube drawn with glPolygonOffset(0.005, 0), pushed back a little (as "
                 "megaglest draws its models, behind marks drawn over them)"},
                {"far-backdrop", demo::ExtraOption::Kind::Flag,
                 "a dark blue gradient over the window at the far plane (z = 1, identity "
                 "matrices, GL_LEQUAL) before the scene"},
                {"env-map", demo::ExtraOption::Kind::Flag,
                 "the scene drawn into a 64x64 corner first and copied into a texture, then "
                 "cleared; the texture shown in 2D in the top-left corner after the scene"},
                {"env-map-line", demo::ExtraOption::Kind::Flag,
                 "with --env-map: a line drawn over the corner's scene before the copy"},
                {"replace", demo::ExtraOption::Kind::Flag,
                 "the cube's texture drawn with GL_REPLACE under a blue material: the picture "
                 "shows the texture alone"},
                {"cutout-fine", demo::ExtraOption::Kind::Flag,
                 "the cube a fine grille instead: bars and square holes two texels wide "
                 "(about two pixels on screen at 320x240)"},
                {"cutout-blend", demo::ExtraOption::Kind::Flag,
                 "with --cutout: the cube also blended by its alpha (GL_SRC_ALPHA, "
                 "GL_ONE_MINUS_SRC_ALPHA) with depth writes, as foliage is drawn"},
                {"fog", demo::ExtraOption::Kind::Flag, "linear fog from 6 to 11 units"},
                {"depth-occluder", demo::ExtraOption::Kind::Flag,
                 "a square in front of the scene drawn into depth alone first: a hole in it"},
                {"depth-after", demo::ExtraOption::Kind::Flag,
                 "the floor drawn again into depth alone right after it: no change natively"},
                {"depth-prepass", demo::ExtraOption::Kind::Flag,
                 "draw the scene's depth first with the colour mask off, then its colours"},
                {"decal", demo::ExtraOption::Kind::Flag,
                 "a yellow square on the floor, coplanar, drawn with glPolygonOffset"},
                {"translucent-decal", demo::ExtraOption::Kind::Flag,
                 "the decal blended by its alpha (0.85) without depth writes, as games paint "
                 "marks on their floors"},
                {"weapon", demo::ExtraOption::Kind::Flag,
                 "a first-person weapon: a cube far behind the scene drawn in a depth range of "
                 "its own (glDepthRange 0 to 0.1), so that it is in front of everything"},
                {"inset", demo::ExtraOption::Kind::Flag,
                 "the scene again, turned, in the top right quarter (scissor and clear)"},
                {"floor-layer", demo::ExtraOption::Kind::Flag,
                 "the floor drawn again, unlit blue through a second texture's alpha (a round "
                 "pool), blended by alpha at equal depth (GL_LEQUAL): water or paint a program "
                 "lays over its ground"},
                {"pick", demo::ExtraOption::Kind::Flag,
                 "after the scene (before --weapon), draws the floor, cube and sphere "
                 "colour-coded (1, 2, 3 in red) into a framebuffer object, reads its pixels "
                 "back and prints the ids under a row of points (mouse picking as games do "
                 "it)"},
                {"hud-bar", demo::ExtraOption::Kind::Flag,
                 "after the scene (before --pick), a bar in the top left corner drawn "
                 "orthographically with depth test and writes (GL_LEQUAL): a white frame, then "
                 "a blue gradient inside it at the same depth, which covers it as in GL"},
                {"stale-panel", demo::ExtraOption::Kind::Flag,
                 "frame 1 puts a red panel in the bottom left corner with glDrawPixels; later "
                 "frames clear only depth (as engines whose world covers the screen do), so the "
                 "panel's pixels are what the buffer kept from before"}};
    }

    bool init(const demo::Options& options, std::string& error) override
    {
        sphereMap_ = options.has("sphere-map");
        const std::string linear = options.textValue("linear-map", "");
        if (!linear.empty() && linear != "object" && linear != "eye") {
            error = "--linear-map takes object or eye, not " + linear;
            return false;
        }
        linearMap_ = linear == "object" ? GL_OBJECT_LINEAR : linear == "eye" ? GL_EYE_LINEAR : 0;
        texgenMatrix_ = options.has("texgen-matrix");
        translucent_ = options.has("translucent");
        additive_ = options.has("additive");
        glowAlphaTest_ = options.has("glow-alpha-test");
        glowListPlain_ = options.has("glow-list-plain");
        lateFloor_ = options.has("late-floor");
        lateShader_ = options.has("late-shader");
        alphaMask_ = options.has("alpha-mask");
        backdropFloor_ = options.has("backdrop-floor");
        backdropHaze_ = options.has("backdrop-haze");
        depthPrepass_ = options.has("depth-prepass");
        depthOccluder_ = options.has("depth-occluder");
        depthAfter_ = options.has("depth-after");
        decal_ = options.has("decal") || options.has("translucent-decal");
        translucentDecal_ = options.has("translucent-decal");
        inset_ = options.has("inset");
        stalePanel_ = options.has("stale-panel");
        hudBar_ = options.has("hud-bar");
        if (options.has("floor-layer")) poolTexture_ = uploadPool();
        weapon_ = options.has("weapon");
        width_ = options.width;
        height_ = options.height;
        if (options.has("pick")) makePickTarget();
        if (options.has("cutout")) cutoutTexture_ = uploadHoles();
        cutoutBlend_ = options.has("cutout-blend");
        pushedBack_ = options.has("pushed-back");
        replace_ = options.has("replace");
        envMapLine_ = options.has("env-map-line");
        farBackdrop_ = options.has("far-backdrop");
        if (options.has("env-map")) {
            glGenTextures(1, &envTexture_);
            glBindTexture(GL_TEXTURE_2D, envTexture_);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, kEnvSize, kEnvSize, 0, GL_RGB,
                         GL_UNSIGNED_BYTE, nullptr);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
        if (options.has("cutout-fine")) cutoutTexture_ = uploadGrille();
        if (options.has("fog")) {
            const float fogColour[] = {0.7f, 0.72f, 0.78f, 1.0f};
            glEnable(GL_FOG);
            glFogi(GL_FOG_MODE, GL_LINEAR);
            glFogf(GL_FOG_START, 6.0f);
            glFogf(GL_FOG_END, 11.0f);
            glFogfv(GL_FOG_COLOR, fogColour);
        }
        if (options.has("face-textures")) {
            // Red, green, blue, yellow, magenta, cyan checks on white.
            const uint8_t colours[6][3] = {{200, 40, 40}, {40, 170, 40},  {40, 60, 210},
                                           {220, 200, 30}, {190, 40, 190}, {30, 190, 200}};
            for (int f = 0; f < 6; ++f) {
                faceTextures_[f] = uploadTexture(makeChecker(white_, colours[f], 2));
            }
        }
        const uint8_t* white = white_;
        const uint8_t red[] = {200, 40, 40};
        const uint8_t blue[] = {60, 90, 200};
        const uint8_t grey[] = {150, 150, 160};
        cubeTexture_ = uploadTexture(makeChecker(white, red, 4));
        floorTexture_ = uploadTexture(makeChecker(grey, blue, 2));
        sphereTexture_ = uploadTexture(makeStripes());

        glViewport(0, 0, options.width, options.height);
        demo::setPerspective(45.0, static_cast<double>(options.width) / options.height, 1.0,
                             50.0);
        glClearColor(0.15f, 0.15f, 0.18f, alphaMask_ ? 0.25f : 1.0f);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_TEXTURE_2D);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        const float material[] = {1.0f, 1.0f, 1.0f, 1.0f};
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, material);
        const float ambient[] = {0.25f, 0.25f, 0.25f, 1.0f};
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
        return true;
    }

    void draw(int frame) override
    {
        if (alphaMask_) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glClear(stalePanel_ && frame > 1 ? GL_DEPTH_BUFFER_BIT
                                         : GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (alphaMask_) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
        if (stalePanel_ && frame == 1) drawPanel();
        if (envTexture_) makeEnvMap(frame);
        if (farBackdrop_) drawFarBackdrop();
        if (depthOccluder_) {
            // The middle fifth of the window at the near end of the depth range, depth only.
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            demo::pushIdentityMatrices();
            glBegin(GL_QUADS);
            glVertex3f(-0.2f, -0.2f, -0.9f);
            glVertex3f(0.2f, -0.2f, -0.9f);
            glVertex3f(0.2f, 0.2f, -0.9f);
            glVertex3f(-0.2f, 0.2f, -0.9f);
            glEnd();
            demo::popMatrices();
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        if (depthPrepass_) {
            // Depth first, colour off; then the colours on equal depth.
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            drawScene(frame);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDepthFunc(GL_LEQUAL);
            drawScene(frame);
            glDepthFunc(GL_LESS);
            return;
        }
        drawScene(frame);
        if (alphaMask_) printAlpha(frame);
        if (lateShader_ && frame >= 2) drawShaderPane();
        if (hudBar_) drawHudBar();
        if (envTexture_) showEnvMap();
        // Between the scene and the weapon: another framebuffer's colour is cleared.
        if (pickFbo_) pick(frame);
        if (weapon_) {
            // As engines draw their weapon: whatever its distance, in front of the world.
            glDepthRange(0.0, 0.1);
            glMatrixMode(GL_MODELVIEW);
            glLoadIdentity();
            glTranslatef(0.4f, -0.9f, -14.0f);
            glRotatef(30.0f, 1.0f, 1.0f, 0.0f);
            glBindTexture(GL_TEXTURE_2D, cubeTexture_);
            drawCube(1.2f, nullptr);
            glDepthRange(0.0, 1.0);
        }
        if (inset_) {
            glScissor(width_ / 2, height_ / 2, width_ - width_ / 2, height_ - height_ / 2);
            glEnable(GL_SCISSOR_TEST);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            drawScene(frame + 240);
            glDisable(GL_SCISSOR_TEST);
        }
    }

    void makePickTarget()
    {
        GLuint buffers[2];
        glGenRenderbuffers(2, buffers);
        glBindRenderbuffer(GL_RENDERBUFFER, buffers[0]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
        glBindRenderbuffer(GL_RENDERBUFFER, buffers[1]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
        glBindRenderbuffer(GL_RENDERBUFFER, 0);
        glGenFramebuffers(1, &pickFbo_);
        glBindFramebuffer(GL_FRAMEBUFFER, pickFbo_);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                                  buffers[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  buffers[1]);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
            std::fprintf(stderr, "pick framebuffer incomplete\n");
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    // The scene's shapes in flat id colours, read back along the middle row.
    void pick(int frame)
    {
        glBindFramebuffer(GL_FRAMEBUFFER, pickFbo_);
        glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT | GL_COLOR_BUFFER_BIT);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDisable(GL_LIGHTING);
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_BLEND);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(0.0f, -0.3f, -8.0f);
        glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(frame * 0.5f, 0.0f, 1.0f, 0.0f);
        glColor3ub(1, 0, 0);
        drawFloorQuad(1.0f);
        glColor3ub(2, 0, 0);
        glPushMatrix();
        glTranslatef(-1.3f, 0.0f, 0.0f);
        glRotatef(frame * 2.0f, 0.3f, 1.0f, 0.2f);
        drawCube(0.8f, nullptr);
        glPopMatrix();
        glColor3ub(3, 0, 0);
        glPushMatrix();
        glTranslatef(1.3f, 0.0f, 0.0f);
        demo::drawSphere(0.95f, 24, 32, 2.0f);
        glPopMatrix();
        // Ten points across the window, a third of the way up.
        std::printf("pick frame %d:", frame);
        for (int i = 0; i < 10; ++i) {
            uint8_t rgba[4] = {0, 0, 0, 0};
            glReadPixels(width_ * (2 * i + 1) / 20, height_ / 3, 1, 1, GL_RGBA,
                         GL_UNSIGNED_BYTE, rgba);
            std::printf(" %d", int(rgba[0]));
        }
        std::printf("\n");
        glPopAttrib();
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
    }

    // The floor's quad again, blue where the pool texture is opaque.
    void drawPool()
    {
        glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT |
                     GL_CURRENT_BIT | GL_TEXTURE_BIT);
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, poolTexture_);
        glDisable(GL_LIGHTING);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthFunc(GL_LEQUAL);
        glDepthMask(GL_FALSE);
        glColor4f(0.1f, 0.35f, 1.0f, 1.0f);
        drawFloorQuad(1.0f);
        glPopAttrib();
    }

    // 48x32 red pixels at window (4, 4), before the scene, without depth.
    void drawPanel()
    {
        std::vector<uint8_t> pixels(48 * 32 * 4, 0);
        for (size_t i = 0; i < pixels.size(); i += 4) pixels[i] = pixels[i + 3] = 255;
        glPushAttrib(GL_ENABLE_BIT);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_TEXTURE_2D);
        glDisable(GL_LIGHTING);
        glWindowPos2i(4, 4);
        glDrawPixels(48, 32, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
        glPopAttrib();
    }

    // The destination alpha at the centre (the cube), on the floor, the sphere and two
    // corners, as a program that keeps data there reads it.
    void printAlpha(int frame)
    {
        const int points[5][2] = {{width_ / 2, height_ / 2},
                                  {width_ / 2, height_ / 8},
                                  {width_ * 2 / 3, height_ / 2},
                                  {2, 2},
                                  {width_ - 3, height_ - 3}};
        std::printf("alpha frame %d:", frame);
        for (const auto& p : points) {
            GLubyte a = 0;
            glReadPixels(p[0], p[1], 1, 1, GL_ALPHA, GL_UNSIGNED_BYTE, &a);
            std::printf(" %d", int(a));
        }
        std::printf("\n");
    }

    // A pane in the scene drawn by the demo's own GLSL program, made the first time.
    void drawShaderPane()
    {
        if (!paneProgram_) {
            const char* vertex = "#version 110\nvoid main() { gl_Position = ftransform(); }\n";
            const char* fragment =
                "#version 110\nvoid main() { gl_FragColor = vec4(1.0, 0.55, 0.1, 1.0); }\n";
            const GLuint vs = glCreateShader(GL_VERTEX_SHADER);
            const GLuint fs = glCreateShader(GL_FRAGMENT_SHADER);
            glShaderSource(vs, 1, &vertex, nullptr);
            glShaderSource(fs, 1, &fragment, nullptr);
            glCompileShader(vs);
            glCompileShader(fs);
            paneProgram_ = glCreateProgram();
            glAttachShader(paneProgram_, vs);
            glAttachShader(paneProgram_, fs);
            glLinkProgram(paneProgram_);
            // Flagged: they go with the program, as careful programs leave them.
            glDeleteShader(vs);
            glDeleteShader(fs);
        }
        glUseProgram(paneProgram_);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(-2.2f, 0.9f, -8.0f);
        glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
        glBegin(GL_QUADS);
        glVertex3f(-0.5f, -0.5f, 0.0f);
        glVertex3f(0.5f, -0.5f, 0.0f);
        glVertex3f(0.5f, 0.5f, 0.0f);
        glVertex3f(-0.5f, 0.5f, 0.0f);
        glEnd();
        glUseProgram(0);
    }

    void drawHudBar()
    {
        glPushAttrib(GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT | GL_CURRENT_BIT);
        glDisable(GL_LIGHTING);
        glDisable(GL_TEXTURE_2D);
        glDepthFunc(GL_LEQUAL);
        demo::pushPixelProjection(width_, height_);
        const float x0 = 20.0f, x1 = 220.0f, y0 = float(height_) - 40.0f;
        const float y1 = float(height_) - 20.0f;
        const float dark[] = {0.19f, 0.2f, 0.46f}, light[] = {0.79f, 0.8f, 1.0f};
        auto bar = [](float a, float b, float c, float d, const float* left, const float* right) {
            glBegin(GL_QUADS);
            glColor3fv(left);
            glVertex3f(a, b, 0.5f);
            glColor3fv(right);
            glVertex3f(c, b, 0.5f);
            glVertex3f(c, d, 0.5f);
            glColor3fv(left);
            glVertex3f(a, d, 0.5f);
            glEnd();
        };
        const float white[] = {1.0f, 1.0f, 1.0f};
        bar(x0, y0, x1, y1, white, white);
        bar(x0 + 2.0f, y0 + 2.0f, x1 - 2.0f, y1 - 2.0f, dark, light);
        glPopMatrix();
        glMatrixMode(GL_PROJECTION);
        glPopMatrix();
        glMatrixMode(GL_MODELVIEW);
        glPopAttrib();
    }

    // The scene in a corner of the window, copied into envTexture_; then cleared again.
    void makeEnvMap(int frame)
    {
        glViewport(0, 0, kEnvSize, kEnvSize);
        drawScene(frame);
        if (envMapLine_) {
            glPushAttrib(GL_ENABLE_BIT | GL_CURRENT_BIT);
            glDisable(GL_LIGHTING);
            glDisable(GL_DEPTH_TEST);
            demo::pushIdentityMatrices();
            glColor3f(1.0f, 1.0f, 0.0f);
            glBegin(GL_LINES);
            glVertex2f(-0.3f, 0.0f);
            glVertex2f(0.3f, 0.0f);
            glEnd();
            demo::popMatrices();
            glPopAttrib();
        }
        glBindTexture(GL_TEXTURE_2D, envTexture_);
        glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, kEnvSize, kEnvSize);
        glViewport(0, 0, width_, height_);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }

    // envTexture_ as it is, 2D, in the window's top-left kEnvSize pixels.
    void showEnvMap()
    {
        glPushAttrib(GL_ENABLE_BIT | GL_TEXTURE_BIT);
        glDisable(GL_LIGHTING);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, envTexture_);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        demo::pushPixelProjection(width_, height_);
        const float x0 = 0.0f, y0 = float(height_ - kEnvSize), s = float(kEnvSize);
        glBegin(GL_QUADS);
        glTexCoord2f(0.0f, 0.0f);
        glVertex2f(x0, y0);
        glTexCoord2f(1.0f, 0.0f);
        glVertex2f(x0 + s, y0);
        glTexCoord2f(1.0f, 1.0f);
        glVertex2f(x0 + s, y0 + s);
        glTexCoord2f(0.0f, 1.0f);
        glVertex2f(x0, y0 + s);
        glEnd();
        demo::popMatrices();
        glPopAttrib();
    }

    void drawFarBackdrop()
    {
        glPushAttrib(GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT | GL_CURRENT_BIT);
        glDisable(GL_LIGHTING);
        glDisable(GL_TEXTURE_2D);
        glDepthFunc(GL_LEQUAL);
        demo::pushIdentityMatrices();
        glBegin(GL_QUADS);
        glColor3f(0.0f, 0.05f, 0.2f);
        glVertex3f(-1.0f, -1.0f, 1.0f);
        glVertex3f(1.0f, -1.0f, 1.0f);
        glColor3f(0.0f, 0.3f, 0.6f);
        glVertex3f(1.0f, 1.0f, 1.0f);
        glVertex3f(-1.0f, 1.0f, 1.0f);
        glEnd();
        demo::popMatrices();
        glPopAttrib();
    }

    void drawScene(int frame)
    {
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        const float lightDirection[] = {-0.5f, 0.8f, 0.7f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        glTranslatef(0.0f, -0.3f, -8.0f);
        glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(frame * 0.5f, 0.0f, 1.0f, 0.0f);

        if (lateFloor_ && frame >= 2 && !lateFloorTexture_) {
            const uint8_t green[] = {40, 170, 60}, yellow[] = {230, 210, 40};
            lateFloorTexture_ = uploadTexture(makeChecker(green, yellow, 2));
        }
        // Floor with the texture repeated four times each way.
        glBindTexture(GL_TEXTURE_2D, lateFloorTexture_ ? lateFloorTexture_ : floorTexture_);
        glNormal3f(0.0f, 1.0f, 0.0f);
        if (backdropFloor_) {
            glPushAttrib(GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT | GL_CURRENT_BIT);
            glDisable(GL_DEPTH_TEST);
            glDepthMask(GL_FALSE);
            glDisable(GL_LIGHTING);
            glDisable(GL_TEXTURE_2D);
            glColor3f(0.15f, 0.15f, 0.18f); // the clear colour
        }
        drawFloorQuad(4.0f);
        if (depthAfter_) {
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            drawFloorQuad(4.0f);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        }
        if (poolTexture_) drawPool();
        if (backdropFloor_ && backdropHaze_) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glColor4f(1.0f, 1.0f, 1.0f, 0.25f);
            glBegin(GL_QUADS);
            glVertex3f(-3.0f, -0.99f, 0.0f);
            glVertex3f(3.0f, -0.99f, 0.0f);
            glVertex3f(3.0f, -0.99f, -3.0f);
            glVertex3f(-3.0f, -0.99f, -3.0f);
            glEnd();
            glDisable(GL_BLEND);
        }
        if (backdropFloor_) glPopAttrib();
        if (decal_) {
            // In the floor's plane: only the offset keeps it in front of the floor.
            glDisable(GL_TEXTURE_2D);
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(-1.0f, -2.0f);
            const float yellow[] = {1.0f, 0.85f, 0.1f, translucentDecal_ ? 0.85f : 1.0f};
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, yellow);
            if (translucentDecal_) {
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
                glDepthMask(GL_FALSE);
            }
            glBegin(GL_QUADS);
            glVertex3f(-0.6f, -1.0f, 2.6f);
            glVertex3f(0.6f, -1.0f, 2.6f);
            glVertex3f(0.6f, -1.0f, 1.4f);
            glVertex3f(-0.6f, -1.0f, 1.4f);
            glEnd();
            const float white[] = {1.0f, 1.0f, 1.0f, 1.0f};
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
            glDisable(GL_POLYGON_OFFSET_FILL);
            glDisable(GL_BLEND);
            glDepthMask(GL_TRUE);
            glEnable(GL_TEXTURE_2D);
        }

        glBindTexture(GL_TEXTURE_2D, cutoutTexture_ ? cutoutTexture_ : cubeTexture_);
        if (cutoutTexture_) {
            glEnable(GL_ALPHA_TEST);
            glAlphaFunc(GL_GREATER, 0.5f);
            if (cutoutBlend_) {
                glEnable(GL_BLEND);
                glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            }
        }
        if (pushedBack_) {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(0.005f, 0.0f);
        }
        const float blue[] = {0.1f, 0.2f, 1.0f, 1.0f}, white[] = {1.0f, 1.0f, 1.0f, 1.0f};
        if (replace_) {
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, blue);
        }
        glPushMatrix();
        glTranslatef(-1.3f, 0.0f, 0.0f);
        glRotatef(frame * 2.0f, 0.3f, 1.0f, 0.2f);
        drawCube(0.8f, faceTextures_[0] ? faceTextures_ : nullptr);
        glPopMatrix();
        if (replace_) {
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, white);
        }
        glDisable(GL_POLYGON_OFFSET_FILL);
        glDisable(GL_ALPHA_TEST);
        glDisable(GL_BLEND);

        glBindTexture(GL_TEXTURE_2D, sphereTexture_);
        glPushMatrix();
        glTranslatef(1.3f, 0.0f, 0.0f);
        glRotatef(frame * 2.0f, 0.0f, 1.0f, 0.0f);
        glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
        if (sphereMap_) {
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
            glEnable(GL_TEXTURE_GEN_S);
            glEnable(GL_TEXTURE_GEN_T);
        }
        if (linearMap_) {
            // Two stripes' periods across the sphere, slanted against the texture's own.
            const GLfloat s[] = {0.55f, 0.2f, 0.0f, 0.5f}, t[] = {0.0f, 0.3f, 0.45f, 0.5f};
            const GLenum plane = linearMap_ == GL_OBJECT_LINEAR ? GL_OBJECT_PLANE : GL_EYE_PLANE;
            glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GLint(linearMap_));
            glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GLint(linearMap_));
            glTexGenfv(GL_S, plane, s);
            glTexGenfv(GL_T, plane, t);
            glEnable(GL_TEXTURE_GEN_S);
            glEnable(GL_TEXTURE_GEN_T);
            if (texgenMatrix_) {
                glMatrixMode(GL_TEXTURE);
                glScalef(2.0f, 1.0f, 1.0f);
                glMatrixMode(GL_MODELVIEW);
            }
        }
        if (translucent_) {
            const float glass[] = {1.0f, 1.0f, 1.0f, 0.6f};
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, glass);
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glDepthMask(GL_FALSE);
        }
        if (additive_) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE);
            glDepthMask(GL_FALSE);
            if (glowAlphaTest_) {
                glEnable(GL_ALPHA_TEST);
                glAlphaFunc(GL_GREATER, 0.01f);
            }
        }
        if (additive_ && glowListPlain_) {
            if (!glowList_) {
                glowList_ = glGenLists(1);
                glNewList(glowList_, GL_COMPILE);
                glDisable(GL_TEXTURE_2D);
                glDisable(GL_LIGHTING);
                glColor3f(0.2f, 0.3f, 1.0f);
                demo::drawSphere(0.95f, 24, 32, 2.0f);
                glColor3f(1.0f, 1.0f, 1.0f);
                glEnable(GL_LIGHTING);
                glEnable(GL_TEXTURE_2D);
                glEndList();
            }
            glCallList(glowList_);
        } else {
            demo::drawSphere(0.95f, 24, 32, 2.0f);
        }
        if (translucent_ || additive_) {
            const float opaque[] = {1.0f, 1.0f, 1.0f, 1.0f};
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, opaque);
            glDisable(GL_BLEND);
            glDisable(GL_ALPHA_TEST);
            glDepthMask(GL_TRUE);
        }
        if (texgenMatrix_) {
            glMatrixMode(GL_TEXTURE);
            glLoadIdentity();
            glMatrixMode(GL_MODELVIEW);
        }
        // Off again: the next frame's floor and cube have their own coordinates.
        glDisable(GL_TEXTURE_GEN_S);
        glDisable(GL_TEXTURE_GEN_T);
        glPopMatrix();
    }

    void shutdown() override
    {
        const GLuint textures[] = {cubeTexture_, floorTexture_, sphereTexture_};
        glDeleteTextures(3, textures);
        if (faceTextures_[0]) glDeleteTextures(6, faceTextures_);
        if (cutoutTexture_) glDeleteTextures(1, &cutoutTexture_);
        if (glowList_) glDeleteLists(glowList_, 1);
        if (lateFloorTexture_) glDeleteTextures(1, &lateFloorTexture_);
        if (envTexture_) glDeleteTextures(1, &envTexture_);
        if (paneProgram_) glDeleteProgram(paneProgram_);
    }

private:
    GLuint cubeTexture_ = 0;
    bool replace_ = false;
    bool farBackdrop_ = false;
    static constexpr int kEnvSize = 64;
    GLuint envTexture_ = 0; // --env-map
    bool envMapLine_ = false;
    GLuint floorTexture_ = 0;
    GLuint sphereTexture_ = 0;
    GLuint faceTextures_[6] = {};
    bool sphereMap_ = false;
    GLenum linearMap_ = 0; // GL_OBJECT_LINEAR, GL_EYE_LINEAR or 0
    bool texgenMatrix_ = false;
    bool translucent_ = false;
    bool additive_ = false;
    bool glowAlphaTest_ = false;
    bool glowListPlain_ = false;
    bool lateFloor_ = false;
    bool lateShader_ = false;
    bool alphaMask_ = false;
    bool cutoutBlend_ = false;
    bool pushedBack_ = false;
    GLuint paneProgram_ = 0;
    bool backdropFloor_ = false;
    bool backdropHaze_ = false;
    bool stalePanel_ = false;
    GLuint poolTexture_ = 0;
    GLuint pickFbo_ = 0;
    GLuint lateFloorTexture_ = 0;
    GLuint glowList_ = 0;
    bool depthPrepass_ = false;
    bool depthOccluder_ = false;
    bool depthAfter_ = false;
    bool decal_ = false;
    bool inset_ = false;
    bool weapon_ = false;
    bool hudBar_ = false;
    bool translucentDecal_ = false;
    int width_ = 0, height_ = 0;
    GLuint cutoutTexture_ = 0;
    static constexpr uint8_t white_[3] = {235, 235, 235};
};

} // namespace

int main(int argc, char** argv)
{
    TexturedScene scene;
    return demo::run(argc, argv, "textured", scene);
}
