// Texture units, bindings, texgen, texture environments and layers (texstate.c's part).
#include "frame/StateTracker.h"

#include "frame/TrackerDispatch.h"
#include "frame/TrackerGl.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <bit>

namespace nprgl {

using namespace tracker;

const char* StateTracker::multitexturing() const
{
    uint32_t layers = 0;
    if (texturedUnits(layers) == 0) {
        return "texture combiners or additions with no plain texture (GL_COMBINE, GL_ADD)";
    }
    return "a 1D, 3D or cube-map texture on the surface (the styles draw 2D textures)";
}

uint32_t StateTracker::texturedUnits(uint32_t& layers) const
{
    const AttribState& a = mAttrib;
    const uint32_t textured = (a.textureUnits | (a.texture2D ? 1u : 0u)) & 0xFFu;
    // The surface's texture is on the lowest unit that applies a texture of its own, on
    // coordinates of its own, the plain way (GL_MODULATE, GL_REPLACE, GL_DECAL). The other
    // units layer light or effects over it: lightmaps and shadows through combiners or
    // additions, environment maps on generated coordinates.
    uint32_t plain = 0;
    const uint32_t depth = depthUnits();
    for (int u = 0; u < 8; ++u) {
        const GLenum mode = a.envMode[size_t(u)];
        const bool ownCoordinates = ((a.texGen >> (4 * u)) & 0x3u) != 0x3u;
        const bool applies = (mode == GL_MODULATE || mode == GL_REPLACE || mode == GL_DECAL) &&
                             !(depth & (1u << u));
        if ((textured & (1u << u)) && ownCoordinates && applies) plain |= 1u << u;
    }
    // Only the first textured unit may be a generated or combined one on its own (a sphere
    // map alone is styled without it; a combiner alone is not the surface's texture).
    const uint32_t base = plain ? plain & (~plain + 1u) : 0u;
    layers = textured & ~base;
    return base;
}

uint32_t StateTracker::depthUnits() const
{
    const AttribState& a = mAttrib;
    uint32_t units = 0;
    for (int u = 0; u < 8; ++u) {
        // The unit's 2D texture is the one it applies (a cube map or another target wins).
        const bool twoD = u == 0 ? a.texture2D && !(a.textureUnits & 1u)
                                 : ((a.texture2DUnits & ~a.cubeUnits) >> u) & 1u;
        if (twoD && mTextures.depth(mUnitTextures[size_t(u)])) units |= 1u << u;
    }
    return units;
}

int StateTracker::surfaceUnit() const
{
    const AttribState& a = mAttrib;
    uint32_t layers = 0;
    const uint32_t base = texturedUnits(layers);
    if (base == 0) {
        // No plain texture: untextured, or a reflective surface: a unit on generated
        // coordinates (an environment map, styled without its texture) under combined or
        // added layers (shadows, fades; not drawn). Combiners alone are the surface's colour
        // computed in ways the styles cannot follow.
        // A shadow map alone leaves the surface untextured.
        const uint32_t textured =
            (a.textureUnits | (a.texture2D ? 1u : 0u)) & 0xFFu & ~depthUnits();
        if (textured == 0) return 0;
        uint32_t generated = 0;
        for (int u = 0; u < 8; ++u) {
            if ((textured & (1u << u)) && ((a.texGen >> (4 * u)) & 0x3u) == 0x3u) {
                generated |= 1u << u;
            }
        }
        if (generated == 0) return -1;
        for (int u = 0; u < 8; ++u) {
            const GLenum mode = a.envMode[size_t(u)];
            const bool layer = mode == GL_COMBINE || mode == GL_ADD;
            if ((textured & ~generated & (1u << u)) && !layer) return -1;
        }
        return std::countr_zero(generated);
    }
    const int u = std::countr_zero(base);
    // The surface's texture must be a 2D one (the styles draw 2D textures).
    if (u == 0) return (a.textureUnits & 1u) == 0 ? 0 : -1;
    return u < 8 && (a.texture2DUnits & base) != 0 ? u : -1;
}

uint32_t StateTracker::droppedLayers() const
{
    uint32_t layers = 0;
    texturedUnits(layers);
    const int surface = surfaceUnit();
    if (surface < 0) return 0;
    // A surface on generated coordinates comes from among the layers (texturedUnits finds no
    // plain one): it is drawn, not dropped.
    layers &= ~(1u << surface);
    const int light = mAttrib.lighting ? -1 : lightUnit();
    return light < 0 ? layers : layers & ~(1u << light);
}

int StateTracker::lightUnit() const
{
    const AttribState& a = mAttrib;
    uint32_t layers = 0;
    if (texturedUnits(layers) == 0) return -1;
    layers &= ~depthUnits();
    for (int u = 0; u < 8; ++u) {
        if (!(layers & (1u << u)) || a.envMode[size_t(u)] != GL_MODULATE) continue;
        if (((a.texGen >> (4 * u)) & 0x3u) == 0x3u) continue;
        const bool twoD = u == 0 ? a.texture2D : (a.texture2DUnits & (1u << u)) != 0;
        return twoD ? u : -1;
    }
    return -1;
}

void StateTracker::followSurfaceUnit()
{
    const int u = std::max(surfaceUnit(), 0);
    if (u != mSurfaceUnit) {
        mUnitTexcoords[size_t(mSurfaceUnit)] = mCurrent.texcoord;
        mSurfaceUnit = u;
        mCurrent.texcoord = mUnitTexcoords[size_t(u)];
    }
    // The lightmap's coordinates are a copy: every unit's own are in mUnitTexcoords (or, for
    // the surface's unit, mCurrent.texcoord).
    mLightUnit = lightUnit();
    if (mLightUnit >= 0) mCurrent.lightcoord = mUnitTexcoords[size_t(mLightUnit)];
}

void StateTracker::texGen(GLenum coord, GLenum pname, const double* values, size_t count)
{
    if (coord < GL_S || coord > GL_Q || mActiveUnit >= 8) return;
    const uint32_t c = coord - GL_S;
    AttribState& a = mAttrib;
    if (pname == GL_TEXTURE_GEN_MODE && count == 1) {
        const GLenum mode = enumOf(values[0]);
        if (mode != GL_SPHERE_MAP && mode != GL_OBJECT_LINEAR && mode != GL_EYE_LINEAR &&
            mode != GL_NORMAL_MAP && mode != GL_REFLECTION_MAP) {
            return; // the driver refuses it (GL_INVALID_ENUM)
        }
        a.texGenMode[4 * mActiveUnit + c] = mode;
        return;
    }
    if (c > 1 || count != 4) return; // R and Q planes: only S and T map a 2D texture
    const glm::vec4 plane{float(values[0]), float(values[1]), float(values[2]), float(values[3])};
    if (pname == GL_OBJECT_PLANE) {
        a.objectPlane[2 * mActiveUnit + c] = plane;
    } else if (pname == GL_EYE_PLANE) {
        // GL keeps p M^-1 (M: the modelview at the call), so that p · eye position holds.
        a.eyePlane[2 * mActiveUnit + c] = plane * glm::inverse(mMatrices.modelview());
    }
}

styles::GeneratedTexture StateTracker::generatedTexture() const
{
    // The surface unit's 2D texture on S and T generated by a mode the styles can follow: a
    // reflection or a projection they may show as detail (their parameter).
    const AttribState& a = mAttrib;
    const int u = surfaceUnit();
    styles::GeneratedTexture g;
    if (u < 0 || u >= 8 || ((a.texGen >> (4 * u)) & 0x3u) != 0x3u) return g;
    for (int c = 0; c < 2; ++c) {
        const GLenum mode = a.texGenMode[size_t(4 * u + c)];
        if (mode != GL_SPHERE_MAP && mode != GL_OBJECT_LINEAR && mode != GL_EYE_LINEAR) {
            return {}; // cube-map coordinates (normal, reflection map): a 2D map cannot take them
        }
        g.mode[c] = mode;
        g.plane[c] = mode == GL_OBJECT_LINEAR ? a.objectPlane[size_t(2 * u + c)]
                                              : a.eyePlane[size_t(2 * u + c)];
    }
    g.texture = unitTexture(u);
    if (g.texture == 0) return {};
    g.matrix = mMatrices.texture(u);
    if (const glm::vec3* mean = mTextures.mean(mUnitTextures[size_t(u)])) g.mean = *mean;
    return g;
}

GLuint StateTracker::detailTexture() const
{
    // A texture on generated coordinates (an environment or reflection map) is not the
    // surface's own: the styles draw the surface without it.
    const AttribState& a = mAttrib;
    const int u = surfaceUnit();
    if (u < 0 || ((a.texGen >> (4 * u)) & 0xFu) != 0) return 0;
    if (depthUnits() & (1u << u)) return 0; // a shadow map alone on unit 0
    return unitTexture(u);
}

GLuint StateTracker::unitTexture(int unit) const
{
    if (unit == 0) return mAttrib.texture2D ? sceneTexture(mBoundTexture) : 0;
    return sceneTexture(mUnitTextures[size_t(unit)]);
}

void StateTracker::bakeObjectLinear(TrackedBatch& batch) const
{
    // Coordinates on object planes are fixed to the vertices like the program's own: made
    // here, per batch, they stay right when batches with planes of their own (a terrain's
    // tiles, each its texture and its planes) are welded into one object.
    styles::GeneratedTexture& g = batch.generated;
    if (g.texture == 0 || g.mode[0] != GL_OBJECT_LINEAR || g.mode[1] != GL_OBJECT_LINEAR) return;
    for (TrackedVertex& v : batch.vertices) {
        const glm::vec4 p(v.position, 1.0f);
        v.texcoord = {glm::dot(g.plane[0], p), glm::dot(g.plane[1], p)};
    }
    batch.texture = g.texture; // the texture matrix follows (applyTextureMatrices)
    g = {};
}

void StateTracker::applyTextureMatrices(TrackedBatch& batch) const
{
    // The texture and lightmap coordinates as the units' texture matrices move them (a
    // scrolled or scaled texture); one pass, and none where both are the identity.
    static const glm::mat4 kIdentity(1.0f);
    const int u = surfaceUnit();
    const glm::mat4& surface = u >= 0 ? mMatrices.texture(u) : kIdentity;
    const glm::mat4& light = mLightUnit >= 0 ? mMatrices.texture(mLightUnit) : kIdentity;
    const bool moveSurface = surface != kIdentity, moveLight = light != kIdentity;
    if (!moveSurface && !moveLight) return;
    auto apply = [](const glm::mat4& m, glm::vec2& st) {
        const glm::vec4 t = m * glm::vec4(st, 0.0f, 1.0f);
        st = t.w != 0.0f ? glm::vec2(t) / t.w : glm::vec2(t);
    };
    for (TrackedVertex& v : batch.vertices) {
        if (moveSurface) apply(surface, v.texcoord);
        if (moveLight) apply(light, v.lightcoord);
    }
}

GLuint StateTracker::sceneTexture(GLuint name) const
{
    // The default texture, once it has an image (enabled without one, GL draws untextured:
    // so do the styles). GL has one default 2D texture, whichever unit binds it.
    return name == 0 && mTextures.defaultImage() ? styles::kDefaultTexture : name;
}

void StateTracker::activeTexture(GLenum unit)
{
    if (unit >= GL_TEXTURE0 && unit < GL_TEXTURE0 + 32) mActiveUnit = int(unit - GL_TEXTURE0);
    mMatrices.setUnit(mActiveUnit);
}

void StateTracker::bindTexture(GLenum target, GLuint texture)
{
    if (target == GL_TEXTURE_CUBE_MAP && size_t(mActiveUnit) < mUnitCubeTextures.size()) {
        mUnitCubeTextures[size_t(mActiveUnit)] = texture;
    }
    if (target == GL_TEXTURE_2D && mActiveUnit == 0) mBoundTexture = texture;
    if (target == GL_TEXTURE_2D && size_t(mActiveUnit) < mUnitTextures.size()) {
        mUnitTextures[size_t(mActiveUnit)] = texture;
    }
}

void StateTracker::replacedByTexture(TrackedBatch& batch) const
{
    const int u = surfaceUnit();
    if (batch.texture == 0 || u < 0) return;
    const GLenum mode = mAttrib.envMode[size_t(u)];
    const GLuint name = styles::textureName(batch.texture);
    const bool opaque = mTextures.opaque(name);
    // GL_REPLACE takes the texture's alpha too where it has one (kept opaque: opaqueAlpha);
    // an alpha-only texture replaces the alpha alone. GL_DECAL keeps the fragment's alpha and
    // mixes the colours by the texture's, so only an opaque texture replaces them.
    if ((mode == GL_REPLACE && !mTextures.alphaOnly(name)) || (mode == GL_DECAL && opaque)) {
        for (TrackedVertex& v : batch.vertices) v.color = glm::vec4(glm::vec3(1.0f), v.color.a);
    }
}

void StateTracker::texEnv(GLenum target, GLenum pname, GLenum mode)
{
    if (target != GL_TEXTURE_ENV || mActiveUnit >= 8) return;
    const size_t u = size_t(mActiveUnit);
    AttribState& a = mAttrib;
    // Another value is refused by the driver (GL_INVALID_ENUM), which keeps the one it had.
    switch (pname) {
    case GL_TEXTURE_ENV_MODE:
        if (mode == GL_MODULATE || mode == GL_REPLACE || mode == GL_DECAL || mode == GL_BLEND ||
            mode == GL_ADD || mode == GL_COMBINE) {
            a.envMode[u] = mode;
        }
        break;
    case GL_COMBINE_RGB:
        if (mode == GL_REPLACE || mode == GL_MODULATE || mode == GL_ADD ||
            mode == GL_ADD_SIGNED || mode == GL_INTERPOLATE || mode == GL_SUBTRACT ||
            mode == GL_DOT3_RGB || mode == GL_DOT3_RGBA) {
            a.combineRgb[u] = mode;
        }
        break;
    case GL_RGB_SCALE:
        if (mode == 1 || mode == 2 || mode == 4) a.rgbScale[u] = float(mode);
        break;
    case GL_SOURCE0_RGB:
    case GL_SOURCE1_RGB:
        a.combineArgs[4 * u + (pname - GL_SOURCE0_RGB)] = mode;
        break;
    case GL_OPERAND0_RGB:
    case GL_OPERAND1_RGB:
        a.combineArgs[4 * u + 2 + (pname - GL_OPERAND0_RGB)] = mode;
        break;
    default:
        break;
    }
}

bool StateTracker::layerEffect(int unit, glm::vec3& scale, glm::vec3& offset) const
{
    const AttribState& a = mAttrib;
    const size_t u = size_t(unit);
    // The unit's texture: a cube map where one is enabled (GL takes it over a 2D one).
    glm::vec3 m;
    if (a.cubeUnits & (1u << u)) {
        if (!mTextures.cubeMean(mUnitCubeTextures[u], m)) return false;
    } else {
        const glm::vec3* mean = mTextures.mean(mUnitTextures[u]);
        if (!mean) return false;
        m = *mean;
    }
    GLenum function = a.envMode[u];
    float k = 1.0f;
    if (function == GL_COMBINE) {
        // The texture with the colour so far, either way round, each as its colour.
        const GLenum* args = &a.combineArgs[4 * u];
        const bool plain = ((args[0] == GL_TEXTURE && args[1] == GL_PREVIOUS) ||
                            (args[0] == GL_PREVIOUS && args[1] == GL_TEXTURE)) &&
                           args[2] == GL_SRC_COLOR && args[3] == GL_SRC_COLOR;
        if (!plain) return false;
        function = a.combineRgb[u];
        k = a.rgbScale[u];
    }
    // As an affine map of the colour so far: c' = scale c + offset, with the texel's mean.
    switch (function) {
    case GL_MODULATE: scale = k * m; offset = glm::vec3(0.0f); return true;
    case GL_ADD: scale = glm::vec3(k); offset = k * m; return true;
    case GL_ADD_SIGNED: scale = glm::vec3(k); offset = k * (m - 0.5f); return true;
    default: return false; // replacing, interpolating, subtracting, dot products: not followed
    }
}

void StateTracker::layerEffects(TrackedBatch& batch) const
{
    uint32_t layers = droppedLayers();
    // A surface textured by a cube map alone (an environment on reflection coordinates, the
    // styles draw none) is dropped as a layer is: its mean tint stays.
    const int surface = surfaceUnit();
    if (surface >= 0 && batch.texture == 0 && batch.generated.texture == 0 &&
        (mAttrib.cubeUnits & (1u << surface))) {
        layers |= 1u << surface;
    }
    for (int u = 0; u < 8; ++u) {
        glm::vec3 scale, offset;
        if (!(layers & (1u << u)) || !layerEffect(u, scale, offset)) continue;
        // GL applies the units in order: this one to what the ones before it made.
        batch.layerScale *= scale;
        batch.layerOffset = scale * batch.layerOffset + offset;
    }
}

uint64_t StateTracker::textureHash(GLuint texture) const
{
    return mTextures.hash(texture);
}

} // namespace nprgl
