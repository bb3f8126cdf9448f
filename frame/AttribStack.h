#pragma once

// AttribStack: the server state that decides holding and shading (enables, lighting, colour
// mask, polygon mode, viewport, scissor) and glPushAttrib/glPopAttrib over it, group by group.

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace nprgl {

struct AttribState {
    bool lighting = false, colorMaterial = false, depthTest = false, texture2D = false;
    uint32_t textureUnits = 0; // bit u: a texture target is enabled on unit u (not unit 0's 2D)
    uint32_t texture2DUnits = 0; // bit u: GL_TEXTURE_2D is enabled on unit u >= 1
    uint32_t cubeUnits = 0;      // bit u: GL_TEXTURE_CUBE_MAP is enabled on unit u
    // GL_TEXTURE_ENV_MODE per unit < 8 (GL_MODULATE, GL_COMBINE...): which unit's texture is
    // the surface's and which layer light or effects over it.
    std::array<GLenum, 8> envMode{GL_MODULATE, GL_MODULATE, GL_MODULATE, GL_MODULATE,
                                  GL_MODULATE, GL_MODULATE, GL_MODULATE, GL_MODULATE};
    // GL_COMBINE's colour function, GL_RGB_SCALE, and its first two colour sources and
    // operands (at 4u: GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_OPERAND0_RGB, GL_OPERAND1_RGB) per
    // unit: what a layer the styles do not draw does to the colour on average.
    std::array<GLenum, 8> combineRgb = filled<GLenum>(GL_MODULATE);
    std::array<float, 8> rgbScale = filled(1.0f);
    std::array<GLenum, 32> combineArgs = defaultCombineArgs();
    uint32_t texGen = 0;       // bit 4u + c: coordinate c (S, T, R, Q) generated on unit u < 8
    // glTexGen's mode (GL's default GL_EYE_LINEAR) of coordinate c on unit u at 4u + c, and
    // the object and eye planes of S and T at 2u + c (GL's defaults; the eye planes in eye
    // space, as the driver keeps them).
    std::array<GLenum, 32> texGenMode = filled<GLenum, 32>(GL_EYE_LINEAR);
    std::array<glm::vec4, 16> objectPlane = defaultPlanes();
    std::array<glm::vec4, 16> eyePlane = defaultPlanes();
    bool blend = false, alphaTest = false, stencilTest = false;
    bool vertexProgram = false, fragmentProgram = false; // ARB assembly programs enabled
    bool fillFront = true, fillBack = true, depthMask = true;
    uint8_t colorMask = 0xF; // glColorMask: bits red, green, blue, alpha
    // No colour channel written (alpha aside): a depth-only pass.
    bool colorMaskNone() const { return (colorMask & 0x7u) == 0; }
    // Red, green and blue written: the picture is the draw's (alpha may be masked).
    bool colorMaskRgb() const { return (colorMask & 0x7u) == 0x7u; }
    bool colorMaskAlpha() const { return (colorMask & 0x8u) != 0; }
    GLenum blendSrc = GL_ONE, blendDst = GL_ZERO; // the colour part of glBlendFunc(Separate)
    GLenum alphaFunc = GL_ALWAYS;
    float alphaRef = 0.0f;
    GLenum depthFunc = GL_LESS;
    bool polygonOffsetFill = false;
    // Face culling: which faces of a draw reach the picture (two passes over one mesh that
    // cull opposite faces draw different triangles).
    bool cullFace = false;
    GLenum cullMode = GL_BACK, frontFace = GL_CCW;
    float offsetFactor = 0.0f, offsetUnits = 0.0f;
    bool fog = false;
    GLenum fogMode = GL_EXP;
    float fogStart = 0.0f, fogEnd = 1.0f, fogDensity = 1.0f;
    glm::vec3 fogColour{0.0f};
    // A face's glMaterial state (GL's defaults).
    struct Material {
        glm::vec3 ambient{0.2f};                   // what the ambient light reflects
        glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
        glm::vec3 specular{0.0f};                  // with shininess, Blinn's exponent
        glm::vec3 emission{0.0f};                  // the light the surface gives itself
        float shininess = 0.0f;
        // glMaterial's pname and values.
        void set(GLenum pname, const float* v);
    };
    // The front's, and the back's that GL's two-sided lighting shows.
    Material material, backMaterial;
    GLenum colorMaterialMode = GL_AMBIENT_AND_DIFFUSE; // what glColor sets under GL_COLOR_MATERIAL
    // The faces glColorMaterial names: a program that names GL_BACK alone leaves the front
    // (what the picture mostly shows) its material, whatever glColor says.
    GLenum colorMaterialFace = GL_FRONT_AND_BACK;
    bool frontColorMaterial() const { return colorMaterial && colorMaterialFace != GL_BACK; }
    uint8_t lightsOn = 0; // bit i: GL_LIGHTi enabled
    // GL_POSITION in eye space (transformed by the modelview of the call), and GL_DIFFUSE:
    // GL's defaults, white for light 0 and black for the others.
    std::array<glm::vec4, 8> lightPosition = defaultPositions();
    std::array<glm::vec3, 8> lightDiffuse = defaultDiffuse();
    std::array<glm::vec3, 8> lightSpecular = defaultDiffuse(); // GL's default is the same
    // GL_AMBIENT of each light (black by default) and GL_LIGHT_MODEL_AMBIENT.
    std::array<glm::vec3, 8> lightAmbient{};
    glm::vec3 modelAmbient{0.2f};
    // GL_LIGHT_MODEL_LOCAL_VIEWER and GL_LIGHT_MODEL_TWO_SIDE; glShadeModel(GL_FLAT).
    bool localViewer = false, twoSide = false, flatShade = false;
    // GL_NORMALIZE and GL_RESCALE_NORMAL: without them GL lights with the normal as the
    // modelview scaled it.
    bool normalize = false, rescaleNormal = false;
    // GL_SPOT_DIRECTION (eye space, as GL_POSITION), GL_SPOT_CUTOFF (180: no spot),
    // GL_SPOT_EXPONENT, and the constant, linear and quadratic attenuation of each light.
    std::array<glm::vec3, 8> spotDirection = filled(glm::vec3(0.0f, 0.0f, -1.0f));
    std::array<float, 8> spotCutoff = filled(180.0f);
    std::array<float, 8> spotExponent{};
    std::array<glm::vec3, 8> attenuation = filled(glm::vec3(1.0f, 0.0f, 0.0f));

    template <typename T, size_t N = 8>
    static std::array<T, N> filled(const T& value)
    {
        std::array<T, N> a;
        a.fill(value);
        return a;
    }
    static std::array<GLenum, 32> defaultCombineArgs()
    {
        std::array<GLenum, 32> a;
        for (size_t u = 0; u < 8; ++u) {
            a[4 * u] = GL_TEXTURE;
            a[4 * u + 1] = GL_PREVIOUS;
            a[4 * u + 2] = a[4 * u + 3] = GL_SRC_COLOR;
        }
        return a;
    }
    static std::array<glm::vec4, 16> defaultPlanes()
    {
        std::array<glm::vec4, 16> p;
        for (size_t i = 0; i < p.size(); ++i) {
            p[i] = i % 2 == 0 ? glm::vec4(1.0f, 0.0f, 0.0f, 0.0f)
                              : glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
        }
        return p;
    }

    static std::array<glm::vec4, 8> defaultPositions()
    {
        std::array<glm::vec4, 8> p;
        p.fill(glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
        return p;
    }
    static std::array<glm::vec3, 8> defaultDiffuse()
    {
        std::array<glm::vec3, 8> d;
        d.fill(glm::vec3(0.0f));
        d[0] = glm::vec3(1.0f);
        return d;
    }
    glm::ivec4 viewport{0, 0, 0, 0};
    // glDepthRange (near, far): engines draw their first-person weapon in a range of its own
    // so that walls never cut into it.
    glm::vec2 depthRange{0.0f, 1.0f};
    // The scissor box (window pixels) and whether the test confines the drawing to it.
    bool scissorTest = false;
    glm::ivec4 scissor{0, 0, 0, 0};
};

class AttribStack {
public:
    AttribState& current() { return mCurrent; }
    const AttribState& current() const { return mCurrent; }
    void push(GLbitfield mask);
    // Restores the groups the matching push saved; an empty stack is the driver's underflow.
    void pop();
    size_t depth() const { return mStack.size(); }

private:
    static constexpr size_t kMaxDepth = 64;
    AttribState mCurrent;
    std::vector<std::pair<GLbitfield, AttribState>> mStack;
};

} // namespace nprgl
