#include "frame/AttribStack.h"

#include <algorithm>

namespace nprgl {

void AttribState::Material::set(GLenum pname, const float* v)
{
    if (pname == GL_DIFFUSE || pname == GL_AMBIENT_AND_DIFFUSE) {
        diffuse = {v[0], v[1], v[2], v[3]};
    }
    if (pname == GL_AMBIENT || pname == GL_AMBIENT_AND_DIFFUSE) ambient = {v[0], v[1], v[2]};
    if (pname == GL_EMISSION) emission = {v[0], v[1], v[2]};
    if (pname == GL_SPECULAR) specular = {v[0], v[1], v[2]};
    if (pname == GL_SHININESS) shininess = std::clamp(v[0], 0.0f, 128.0f);
}

void AttribStack::push(GLbitfield mask)
{
    if (mStack.size() < kMaxDepth) mStack.emplace_back(mask, mCurrent);
}

void AttribStack::pop()
{
    if (mStack.empty()) return;
    const auto [mask, saved] = mStack.back();
    mStack.pop_back();
    AttribState& a = mCurrent;
    // Each piece comes back only if its group was saved.
    if (mask & GL_ENABLE_BIT) {
        a.lighting = saved.lighting;
        a.colorMaterial = saved.colorMaterial;
        a.depthTest = saved.depthTest;
        a.texture2D = saved.texture2D;
        a.blend = saved.blend;
        a.blendSrc = saved.blendSrc;
        a.blendDst = saved.blendDst;
        a.alphaTest = saved.alphaTest;
        a.alphaFunc = saved.alphaFunc;
        a.alphaRef = saved.alphaRef;
        a.stencilTest = saved.stencilTest;
        a.lightsOn = saved.lightsOn;
        a.fog = saved.fog;
        a.vertexProgram = saved.vertexProgram;
        a.fragmentProgram = saved.fragmentProgram;
        a.scissorTest = saved.scissorTest;
        a.normalize = saved.normalize;
        a.rescaleNormal = saved.rescaleNormal;
    }
    if (mask & GL_TRANSFORM_BIT) {
        a.normalize = saved.normalize;
        a.rescaleNormal = saved.rescaleNormal;
    }
    if (mask & GL_LIGHTING_BIT) {
        a.lighting = saved.lighting;
        a.colorMaterial = saved.colorMaterial;
        a.lightsOn = saved.lightsOn;
        a.material = saved.material;
        a.backMaterial = saved.backMaterial;
        a.localViewer = saved.localViewer;
        a.twoSide = saved.twoSide;
        a.flatShade = saved.flatShade;
        a.colorMaterialMode = saved.colorMaterialMode;
        a.colorMaterialFace = saved.colorMaterialFace;
        a.lightPosition = saved.lightPosition;
        a.lightDiffuse = saved.lightDiffuse;
        a.lightSpecular = saved.lightSpecular;
        a.lightAmbient = saved.lightAmbient;
        a.modelAmbient = saved.modelAmbient;
        a.spotDirection = saved.spotDirection;
        a.spotCutoff = saved.spotCutoff;
        a.spotExponent = saved.spotExponent;
        a.attenuation = saved.attenuation;
    }
    if (mask & GL_DEPTH_BUFFER_BIT) {
        a.depthTest = saved.depthTest;
        a.depthMask = saved.depthMask;
        a.depthFunc = saved.depthFunc;
    }
    if (mask & GL_COLOR_BUFFER_BIT) {
        a.blend = saved.blend;
        a.alphaTest = saved.alphaTest;
        a.colorMask = saved.colorMask;
    }
    if (mask & GL_STENCIL_BUFFER_BIT) a.stencilTest = saved.stencilTest;
    if (mask & (GL_POLYGON_BIT | GL_ENABLE_BIT)) {
        a.polygonOffsetFill = saved.polygonOffsetFill;
        a.cullFace = saved.cullFace;
    }
    if (mask & GL_POLYGON_BIT) {
        a.offsetFactor = saved.offsetFactor;
        a.offsetUnits = saved.offsetUnits;
        a.fillFront = saved.fillFront;
        a.fillBack = saved.fillBack;
        a.cullMode = saved.cullMode;
        a.frontFace = saved.frontFace;
    }
    if (mask & (GL_TEXTURE_BIT | GL_ENABLE_BIT)) {
        a.texture2D = saved.texture2D;
        a.textureUnits = saved.textureUnits;
        a.texture2DUnits = saved.texture2DUnits;
        a.cubeUnits = saved.cubeUnits;
        a.texGen = saved.texGen;
    }
    if (mask & GL_TEXTURE_BIT) {
        a.envMode = saved.envMode;
        a.combineRgb = saved.combineRgb;
        a.rgbScale = saved.rgbScale;
        a.combineArgs = saved.combineArgs;
        a.texGenMode = saved.texGenMode;
        a.objectPlane = saved.objectPlane;
        a.eyePlane = saved.eyePlane;
    }
    if (mask & GL_VIEWPORT_BIT) {
        a.viewport = saved.viewport;
        a.depthRange = saved.depthRange;
    }
    if (mask & GL_SCISSOR_BIT) {
        a.scissorTest = saved.scissorTest;
        a.scissor = saved.scissor;
    }
    if (mask & GL_FOG_BIT) {
        a.fog = saved.fog;
        a.fogMode = saved.fogMode;
        a.fogStart = saved.fogStart;
        a.fogEnd = saved.fogEnd;
        a.fogDensity = saved.fogDensity;
        a.fogColour = saved.fogColour;
    }
}

} // namespace nprgl
