// Lights, materials and the colours lit batches take (light.c's part of the tracker).
#include "frame/StateTracker.h"

#include "frame/FixedLighting.h"
#include "frame/TrackerGl.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>

namespace nprgl {

using namespace tracker;

void StateTracker::light(GLenum light, GLenum pname, const float* v)
{
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + 8 || !v) return;
    const size_t i = light - GL_LIGHT0;
    if (pname == GL_POSITION) {
        // GL stores the position in eye space, transformed by the modelview of the call.
        mAttrib.lightPosition[i] = mMatrices.modelview() * glm::vec4(v[0], v[1], v[2], v[3]);
    } else if (pname == GL_DIFFUSE) {
        mAttrib.lightDiffuse[i] = glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_SPECULAR) {
        mAttrib.lightSpecular[i] = glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_AMBIENT) {
        mAttrib.lightAmbient[i] = glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_SPOT_DIRECTION) {
        // Eye space too, by the modelview's upper 3x3.
        mAttrib.spotDirection[i] = glm::mat3(mMatrices.modelview()) * glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_SPOT_CUTOFF) {
        mAttrib.spotCutoff[i] = v[0];
    } else if (pname == GL_SPOT_EXPONENT) {
        mAttrib.spotExponent[i] = v[0];
    } else if (pname == GL_CONSTANT_ATTENUATION) {
        mAttrib.attenuation[i].x = v[0];
    } else if (pname == GL_LINEAR_ATTENUATION) {
        mAttrib.attenuation[i].y = v[0];
    } else if (pname == GL_QUADRATIC_ATTENUATION) {
        mAttrib.attenuation[i].z = v[0];
    }
}

void StateTracker::litBy(styles::SceneLights& out) const
{
    // The enabled lights, the brightest (keyLight) first, each weighted by its diffuse
    // brightness against the brightest's: a surface facing the brightest light is fully lit,
    // as in GL, and a dimmer fill light adds its part.
    const AttribState& a = mAttrib;
    out.count = 0;
    const size_t key = keyLight();
    float top = 0.0f;
    for (size_t k = 0; k < 8; ++k) {
        const size_t i = k == 0 ? key : (k <= key ? k - 1 : k);
        if (!(a.lightsOn & (1u << i))) continue;
        styles::SceneLights::Light& l = out.lights[out.count++];
        // As the shader takes them, without branches: a far light is not attenuated, and a
        // light that is no spot keeps SceneLights' cutoff of -2 and an exponent of 0.
        l.position = a.lightPosition[i];
        const bool positional = l.position.w != 0.0f;
        const bool spot = positional && a.spotCutoff[i] < 180.0f;
        const float length = glm::length(a.spotDirection[i]);
        l.spotDirection = spot && length > 1e-12f ? a.spotDirection[i] / length
                                                  : glm::vec3(0.0f, 0.0f, -1.0f);
        l.spotCosCutoff = spot ? std::cos(glm::radians(std::max(a.spotCutoff[i], 0.0f))) : -2.0f;
        l.falloff = positional ? glm::vec4(a.attenuation[i], spot ? a.spotExponent[i] : 0.0f)
                               : glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
        l.weight = glm::dot(glm::max(a.lightDiffuse[i], glm::vec3(0.0f)),
                            glm::vec3(0.299f, 0.587f, 0.114f));
        top = std::max(top, l.weight);
    }
    for (uint32_t k = 0; k < out.count; ++k) {
        styles::SceneLights::Light& l = out.lights[k];
        l.weight = top > 1e-6f ? l.weight / top : 1.0f;
    }
    // The highlight GL draws: the brightest light's. Under GL_COLOR_MATERIAL's specular mode
    // the colour is per vertex, which the styles' one highlight colour cannot follow: none.
    const bool colourSpecular = a.frontColorMaterial() && a.colorMaterialMode == GL_SPECULAR;
    out.shine = out.count > 0 && !colourSpecular
                    ? glm::clamp(glm::max(a.lightSpecular[key], 0.0f) * a.material.specular,
                                 0.0f, 1.0f)
                    : glm::vec3(0.0f);
    out.shininess = std::clamp(a.material.shininess, 0.0f, 128.0f);
    out.twoSide = a.twoSide;
}

void StateTracker::lightModel(GLenum pname, const float* v)
{
    if (!v) return;
    if (pname == GL_LIGHT_MODEL_AMBIENT) mAttrib.modelAmbient = glm::vec3(v[0], v[1], v[2]);
    if (pname == GL_LIGHT_MODEL_LOCAL_VIEWER) mAttrib.localViewer = v[0] != 0.0f;
    if (pname == GL_LIGHT_MODEL_TWO_SIDE) mAttrib.twoSide = v[0] != 0.0f;
}

size_t StateTracker::keyLight() const
{
    // The brightest enabled light gives the styles their L: the others only brighten.
    const AttribState& a = mAttrib;
    size_t key = 0;
    float best = -1.0f;
    for (size_t i = 0; i < 8; ++i) {
        if (!(a.lightsOn & (1u << i))) continue;
        const float y = glm::dot(a.lightDiffuse[i], glm::vec3(0.299f, 0.587f, 0.114f));
        if (y > best) {
            best = y;
            key = i;
        }
    }
    return key;
}

uint32_t StateTracker::currentMaterialId()
{
    const AttribState& a = mAttrib;
    // Unlit or colour-material keys leave the diffuse zero; their first two entries tell
    // them apart from lit ones.
    std::array<float, 7> key = {float(a.lighting), float(a.frontColorMaterial()),
                                float(detailTexture()), 0.0f, 0.0f, 0.0f, 0.0f};
    if (a.lighting && !a.frontColorMaterial()) {
        const glm::vec4& d = a.material.diffuse;
        key[3] = d.r;
        key[4] = d.g;
        key[5] = d.b;
        key[6] = d.a;
    }
    auto it = mMaterialIds.find(key);
    if (it != mMaterialIds.end()) return it->second;
    uint32_t id = uint32_t(mMaterialIds.size()) + 1;
    mMaterialIds.emplace(key, id);
    return id;
}

void StateTracker::batchMaterial(GLenum face, GLenum pname, const float* v)
{
    if (!mInBegin || face == GL_BACK || !v) return;
    if (pname != GL_DIFFUSE && pname != GL_AMBIENT_AND_DIFFUSE && pname != GL_AMBIENT) return;
    TrackedBatch::MaterialChange change;
    change.first = uint32_t(mBatch.vertices.size());
    change.setsDiffuse = pname != GL_AMBIENT;
    change.setsAmbient = pname != GL_DIFFUSE;
    if (change.setsDiffuse) change.diffuse = {v[0], v[1], v[2], v[3]};
    if (change.setsAmbient) change.ambient = {v[0], v[1], v[2]};
    mBatch.materials.push_back(change);
}

void StateTracker::material(GLenum face, GLenum pname, const float* v)
{
    batchMaterial(face, pname, v);
    if (!v) return;
    if (face != GL_BACK) mAttrib.material.set(pname, v);
    // Only GL's two-sided lighting shows it (FixedLighting, for the replica).
    if (face == GL_BACK || face == GL_FRONT_AND_BACK) mAttrib.backMaterial.set(pname, v);
}

void StateTracker::addEvenSpecular(TrackedBatch& batch) const
{
    // GL's specular term at each vertex (Blinn's half-vector, an infinite viewer), per light;
    // the least of it over the batch lights all of the batch. A flat face under a light near
    // its mirror angle (sproingies' stairs: a dark material made pale by its shine) is that
    // bright all over; on a curved surface the least is about nothing, and its highlight is
    // the styles' highlight band.
    const AttribState& a = mAttrib;
    if (!(glm::dot(a.material.specular, a.material.specular) > 0.0f)) return;
    struct Shine {
        glm::vec3 colour;
        size_t light;
        float lowest = INFINITY;
    };
    std::array<Shine, 8> shines;
    size_t count = 0;
    for (size_t i = 0; i < 8; ++i) {
        const glm::vec3 colour = glm::max(a.lightSpecular[i], 0.0f) * a.material.specular;
        if ((a.lightsOn & (1u << i)) && glm::dot(colour, colour) > 0.0f) {
            shines[count++] = {colour, i};
        }
    }
    constexpr float kNone = 1e-3f;
    const glm::mat4& modelview = batch.modelview;
    const glm::mat3 normals = glm::inverseTranspose(glm::mat3(modelview));
    size_t shining = count; // lights every vertex so far has some of
    for (const TrackedVertex& v : batch.vertices) {
        if (shining == 0) return; // a vertex without any: nothing even
        const glm::vec3 eye = glm::vec3(modelview * glm::vec4(v.position, 1.0f));
        const glm::vec3 n = glm::normalize(normals * v.normal);
        for (size_t k = 0; k < count; ++k) {
            Shine& shine = shines[k];
            if (!(shine.lowest > kNone)) continue;
            const size_t i = shine.light;
            glm::vec3 l;
            float reach = 0.0f;
            float s = 0.0f;
            if (FixedLighting::towardsLight(a, i, eye, l, reach)) {
                const float nh = glm::dot(n, glm::normalize(l + glm::vec3(0.0f, 0.0f, 1.0f)));
                if (glm::dot(n, l) > 0.0f && nh > 0.0f) {
                    s = std::pow(nh, a.material.shininess) * reach;
                }
            }
            shine.lowest = std::min(shine.lowest, std::isfinite(s) ? s : 0.0f);
            if (!(shine.lowest > kNone)) --shining;
        }
    }
    glm::vec3 even(0.0f);
    for (size_t k = 0; k < count; ++k) {
        const float lowest = shines[k].lowest;
        if (lowest > kNone && std::isfinite(lowest)) {
            even += shines[k].colour * std::min(lowest, 1.0f);
        }
    }
    if (even == glm::vec3(0.0f)) return;
    for (TrackedVertex& v : batch.vertices) {
        v.color = glm::min(v.color + glm::vec4(even, 0.0f), glm::vec4(1.0f));
    }
}

} // namespace nprgl
