#include "frame/FixedLighting.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>

namespace nprgl {

namespace {

// Luma of encoded colour values: GL lights them as they are.
float luma(const glm::vec3& c) { return 0.299f * c.r + 0.587f * c.g + 0.114f * c.b; }

// The material `m` with glColor's `colour` in the place GL_COLOR_MATERIAL's `mode` names
// (0: none).
AttribState::Material withColour(AttribState::Material m, GLenum mode, const glm::vec4& colour)
{
    switch (mode) {
    case GL_AMBIENT: m.ambient = glm::vec3(colour); break;
    case GL_DIFFUSE: m.diffuse = colour; break;
    case GL_AMBIENT_AND_DIFFUSE:
        m.ambient = glm::vec3(colour);
        m.diffuse = colour;
        break;
    case GL_SPECULAR: m.specular = glm::vec3(colour); break;
    case GL_EMISSION: m.emission = glm::vec3(colour); break;
    default: break;
    }
    return m;
}

// The front material at a batch's first vertex: the one at glBegin (the state now is the one
// after glEnd) where materials change between glBegin and glEnd.
AttribState::Material beginMaterial(AttribState::Material now, const TrackedBatch& batch)
{
    if (!batch.materials.empty()) {
        now.diffuse = batch.beginMaterial;
        now.ambient = batch.beginAmbient;
    }
    return now;
}

// Steps `m` to vertex `vertex` (vertex by vertex, in order; `next` starts at 0): each change
// between glBegin and glEnd from its vertex on.
void advanceMaterial(const TrackedBatch& batch, size_t vertex, size_t& next,
                     AttribState::Material& m)
{
    while (next < batch.materials.size() && batch.materials[next].first <= vertex) {
        const TrackedBatch::MaterialChange& change = batch.materials[next++];
        if (change.setsDiffuse) m.diffuse = change.diffuse;
        if (change.setsAmbient) m.ambient = change.ambient;
    }
}

} // namespace

bool FixedLighting::towardsLight(const AttribState& a, size_t i, const glm::vec3& eye,
                                 glm::vec3& l, float& reach)
{
    const glm::vec4 p = a.lightPosition[i];
    l = p.w != 0.0f ? glm::vec3(p) / p.w - eye : glm::vec3(p);
    const float distance = glm::length(l);
    if (!(distance > 1e-12f) || !std::isfinite(distance)) return false;
    l /= distance;
    reach = 1.0f;
    if (p.w != 0.0f) {
        const glm::vec3 k = a.attenuation[i];
        reach = 1.0f / std::max(k.x + (k.y + k.z * distance) * distance, 1e-6f);
        if (a.spotCutoff[i] != 180.0f) {
            const float cosine = glm::dot(-l, glm::normalize(a.spotDirection[i]));
            reach *= cosine < std::cos(glm::radians(a.spotCutoff[i]))
                         ? 0.0f
                         : std::pow(std::max(cosine, 0.0f), a.spotExponent[i]);
        }
    }
    return true;
}

glm::vec4 FixedLighting::shade(const AttribState& a, const Material& m, const glm::vec3& eye,
                               glm::vec3 normal)
{
    glm::vec3 c = m.emission + m.ambient * a.modelAmbient;
    const glm::vec3 towardsEye =
        a.localViewer ? glm::normalize(-eye) : glm::vec3(0.0f, 0.0f, 1.0f);
    for (size_t i = 0; i < 8; ++i) {
        glm::vec3 l;
        float reach = 0.0f;
        if (!(a.lightsOn & (1u << i)) || !towardsLight(a, i, eye, l, reach)) continue;
        glm::vec3 term = m.ambient * a.lightAmbient[i];
        const float nl = glm::dot(normal, l);
        if (nl > 0.0f) {
            term += nl * glm::vec3(m.diffuse) * a.lightDiffuse[i];
            const glm::vec3 h = l + towardsEye;
            const float hl = glm::length(h);
            const float nh = hl > 1e-12f ? glm::dot(normal, h / hl) : 0.0f;
            if (nh > 0.0f) {
                // GL's 0^0 is 1: a shininess of 0 gives the full specular colour.
                const float s = m.shininess > 0.0f ? std::pow(nh, m.shininess) : 1.0f;
                term += s * m.specular * a.lightSpecular[i];
            }
        }
        c += reach * term;
    }
    c = glm::clamp(c, 0.0f, 1.0f);
    if (!std::isfinite(c.r + c.g + c.b)) c = glm::vec3(0.0f);
    return {c, std::clamp(m.diffuse.a, 0.0f, 1.0f)};
}

void FixedLighting::lightBatch(const AttribState& a, TrackedBatch& batch)
{
    const glm::mat4& modelview = batch.modelview;
    const glm::mat3 normals = glm::inverseTranspose(glm::mat3(modelview));
    // GL_RESCALE_NORMAL divides by the modelview's scale (its third row's length, as the
    // spec has it for a uniform scale); GL_NORMALIZE makes every normal unit.
    const float rescale = a.rescaleNormal ? glm::length(glm::vec3(normals[0][2], normals[1][2],
                                                                  normals[2][2]))
                                          : 1.0f;
    // Which faces glColor's colour applies to (GL_COLOR_MATERIAL's face): the front's
    // vertices, or those lit from the back (two-sided), may each keep the material.
    const GLenum colourMode = a.colorMaterial ? a.colorMaterialMode : 0;
    const GLenum frontMode = a.colorMaterialFace != GL_BACK ? colourMode : 0;
    const GLenum backMode = a.colorMaterialFace != GL_FRONT ? colourMode : 0;
    Material m = beginMaterial(a.material, batch);
    size_t next = 0;
    std::vector<glm::vec4> backs(a.twoSide ? batch.vertices.size() : 0);
    for (size_t i = 0; i < batch.vertices.size(); ++i) {
        TrackedVertex& v = batch.vertices[i];
        advanceMaterial(batch, i, next, m);
        const glm::vec3 eye = glm::vec3(modelview * glm::vec4(v.position, 1.0f));
        glm::vec3 n = normals * v.normal;
        if (a.normalize) {
            const float length = glm::length(n);
            n = length > 1e-12f ? n / length : n;
        } else if (a.rescaleNormal && rescale > 1e-12f) {
            n /= rescale;
        }
        // Two-sided: GL lights every vertex for both sides and each primitive shows the side
        // its window winding faces (pickSides), whatever way the normals point.
        if (a.twoSide) backs[i] = shade(a, withColour(a.backMaterial, backMode, v.color), eye, -n);
        v.color = shade(a, withColour(m, frontMode, v.color), eye, n);
    }
    if (a.twoSide) pickSides(batch, backs, a.frontFace == GL_CW);
}

namespace {

// Whether the triangle faces the window counter-clockwise: the sign of the determinant of its
// clip-space x, y, w (homogeneous, so right for the part in front of the eye even when a
// corner is behind it). 0: seen edge-on, or degenerate.
int windingSign(const glm::mat4& clip, const glm::vec3& p0, const glm::vec3& p1,
                const glm::vec3& p2)
{
    auto xyw = [&](const glm::vec3& p) {
        const glm::vec4 c = clip * glm::vec4(p, 1.0f);
        return glm::dvec3(c.x, c.y, c.w);
    };
    const double d = glm::dot(xyw(p0), glm::cross(xyw(p1), xyw(p2)));
    return d > 0.0 ? 1 : d < 0.0 ? -1 : 0;
}

} // namespace

void FixedLighting::pickSides(TrackedBatch& batch, const std::vector<glm::vec4>& backs,
                              bool clockwiseFront)
{
    std::vector<TrackedVertex>& v = batch.vertices;
    const size_t n = v.size();
    const glm::mat4 clip = batch.projection * batch.modelview;
    // A primitive's side from its first corners that are not in a line (a quad or polygon
    // is planar as GL assumes it): corner k is vertex c[k].
    auto showsBack = [&](const size_t* c, size_t count) {
        int sign = 0;
        for (size_t k = 2; k < count && sign == 0; ++k) {
            sign = windingSign(clip, v[c[0]].position, v[c[k - 1]].position, v[c[k]].position);
        }
        return (sign < 0) != clockwiseFront && sign != 0;
    };
    auto back = [&](std::initializer_list<size_t> corners) {
        return showsBack(corners.begin(), corners.size());
    };
    // Independent primitives keep their vertices, each in its side's colours.
    auto colourSide = [&](size_t first, size_t count, bool isBack) {
        if (!isBack) return;
        for (size_t k = first; k < first + count; ++k) v[k].color = backs[k];
    };
    if (batch.mode == GL_TRIANGLES || batch.mode == GL_QUADS) {
        const size_t stride = batch.mode == GL_TRIANGLES ? 3 : 4;
        for (size_t first = 0; first + stride <= n; first += stride) {
            colourSide(first, stride,
                       stride == 3 ? back({first, first + 1, first + 2})
                                   : back({first, first + 1, first + 2, first + 3}));
        }
        return;
    }
    if (batch.mode == GL_POLYGON) {
        std::vector<size_t> corners(n);
        for (size_t k = 0; k < n; ++k) corners[k] = k;
        colourSide(0, n, showsBack(corners.data(), n));
        return;
    }
    // Strips and fans share a vertex between faces that may show different sides: they
    // become their separate primitives, in the winding GL gives each.
    std::vector<TrackedVertex> out;
    auto put = [&](std::initializer_list<size_t> corners) {
        const bool isBack = back(corners);
        for (size_t k : corners) {
            out.push_back(v[k]);
            if (isBack) out.back().color = backs[k];
        }
    };
    switch (batch.mode) {
    case GL_TRIANGLE_STRIP:
        out.reserve(3 * n);
        for (size_t i = 0; i + 2 < n; ++i) {
            if (i % 2 == 0) put({i, i + 1, i + 2});
            else put({i + 1, i, i + 2});
        }
        batch.mode = GL_TRIANGLES;
        break;
    case GL_TRIANGLE_FAN:
        out.reserve(3 * n);
        for (size_t i = 1; i + 1 < n; ++i) put({0, i, i + 1});
        batch.mode = GL_TRIANGLES;
        break;
    case GL_QUAD_STRIP:
        out.reserve(2 * n);
        for (size_t i = 0; 2 * i + 3 < n; ++i) {
            // The provoking vertex (2i+3) last, as flattenBatch takes a quad's.
            put({2 * i + 2, 2 * i, 2 * i + 1, 2 * i + 3});
        }
        batch.mode = GL_QUADS;
        break;
    default: return;
    }
    v.swap(out);
}

void FixedLighting::flattenBatch(TrackedBatch& batch)
{
    std::vector<TrackedVertex>& v = batch.vertices;
    if (v.empty()) return;
    const size_t n = v.size();
    // Independent primitives: each takes its provoking (last; a polygon's first) vertex's.
    if (batch.mode == GL_TRIANGLES || batch.mode == GL_QUADS) {
        const size_t stride = batch.mode == GL_TRIANGLES ? 3 : 4;
        for (size_t first = 0; first + stride <= n; first += stride) {
            const glm::vec4 c = v[first + stride - 1].color;
            for (size_t k = 0; k + 1 < stride; ++k) v[first + k].color = c;
        }
        return;
    }
    if (batch.mode == GL_POLYGON) {
        for (TrackedVertex& x : v) x.color = v.front().color;
        return;
    }
    // Strips and fans share vertices between primitives of different colours: they become
    // their separate primitives (the same faces, welded again by position downstream), each
    // in its provoking vertex's colour, in the winding GL gives each.
    std::vector<TrackedVertex> out;
    auto put = [&](std::initializer_list<size_t> corners, size_t provoking) {
        for (size_t k : corners) {
            out.push_back(v[k]);
            out.back().color = v[provoking].color;
        }
    };
    switch (batch.mode) {
    case GL_TRIANGLE_STRIP:
        out.reserve(3 * n);
        for (size_t i = 0; i + 2 < n; ++i) {
            if (i % 2 == 0) put({i, i + 1, i + 2}, i + 2);
            else put({i + 1, i, i + 2}, i + 2);
        }
        batch.mode = GL_TRIANGLES;
        break;
    case GL_TRIANGLE_FAN:
        out.reserve(3 * n);
        for (size_t i = 1; i + 1 < n; ++i) put({0, i, i + 1}, i + 1);
        batch.mode = GL_TRIANGLES;
        break;
    case GL_QUAD_STRIP:
        out.reserve(2 * n);
        for (size_t i = 0; 2 * i + 3 < n; ++i) {
            put({2 * i, 2 * i + 1, 2 * i + 3, 2 * i + 2}, 2 * i + 3);
        }
        batch.mode = GL_QUADS;
        break;
    default: return;
    }
    v.swap(out);
}

FixedLighting::SideLight FixedLighting::litSideLight(const AttribState& a, const glm::vec3& at,
                                                     size_t key)
{
    constexpr float kLitSide = 0.75f;
    const glm::vec3 scene = glm::max(a.modelAmbient, glm::vec3(0.0f));
    SideLight all{scene, glm::vec3(0.0f)}, main{scene, glm::vec3(0.0f)};
    for (size_t i = 0; i < 8; ++i) {
        if (!(a.lightsOn & (1u << i))) continue;
        const bool spot = a.spotCutoff[i] != 180.0f;
        const bool attenuated =
            a.lightPosition[i].w != 0.0f && a.attenuation[i] != glm::vec3(1.0f, 0.0f, 0.0f);
        glm::vec3 l;
        float reach = 1.0f;
        const bool towards = towardsLight(a, i, at, l, reach);
        // A spot aimed away from the object adds none of its light there, its ambient
        // included (GL's spot factor scales all of a light's terms).
        if (towards && !(reach > 0.0f)) continue;
        const bool brightened = !spot && attenuated && towards && reach > 1.0f;
        const glm::vec3 diffuse = kLitSide * (brightened ? std::min(reach, 1e3f) : 1.0f) *
                                  glm::max(a.lightDiffuse[i], glm::vec3(0.0f));
        const glm::vec3 own = glm::max(a.lightAmbient[i], glm::vec3(0.0f));
        all.ambient += own;
        all.diffuse += diffuse;
        const bool local = spot || (attenuated && !brightened);
        if (local) continue;
        main.ambient += own;
        if (i == key) main.diffuse += diffuse;
    }
    const glm::vec3 mainSum = main.ambient + main.diffuse;
    if (std::max({mainSum.r, mainSum.g, mainSum.b}) >= 1.0f) return main;
    const glm::vec3 allSum = all.ambient + all.diffuse;
    const float top = std::max({allSum.r, allSum.g, allSum.b});
    if (!(top > 1e-6f)) return SideLight{};
    return SideLight{all.ambient / top, all.diffuse / top};
}

glm::vec4 FixedLighting::colourLitSides(const AttribState& a, TrackedBatch& batch,
                                        const SideLight& light)
{
    // glColor takes the place of what GL_COLOR_MATERIAL's mode names, on the faces it names.
    const GLenum mode = a.colorMaterial ? a.colorMaterialMode : 0;
    const bool colourFront = a.colorMaterial && a.colorMaterialFace != GL_BACK;
    const bool colourBack = a.colorMaterial && a.colorMaterialFace != GL_FRONT;
    auto litColour = [&](const Material& material, bool follows, const glm::vec4& colour) {
        const Material m = withColour(material, follows ? mode : 0, colour);
        // The diffuse colour, the one the eye mostly sees, in all of the light: the styles
        // shade from it. GL's ambient reflectance shows where the light does not reach: the
        // shadow band's hue (shadowTint).
        const glm::vec3 c = glm::max(m.emission, glm::vec3(0.0f)) +
                            glm::vec3(m.diffuse) * (light.ambient + light.diffuse);
        return glm::vec4(glm::min(c, glm::vec3(1.0f)), m.diffuse.a);
    };
    // Two-sided, with a back unlike the front: the back's lit colours too.
    const bool backDiffers =
        a.twoSide && (colourFront != colourBack || a.backMaterial.diffuse != a.material.diffuse ||
                      a.backMaterial.ambient != a.material.ambient ||
                      a.backMaterial.emission != a.material.emission);
    std::vector<glm::vec4> backs(backDiffers ? batch.vertices.size() : 0);
    Material m = beginMaterial(a.material, batch);
    size_t next = 0;
    for (size_t i = 0; i < batch.vertices.size(); ++i) {
        advanceMaterial(batch, i, next, m);
        glm::vec4& colour = batch.vertices[i].color;
        if (backDiffers) backs[i] = litColour(a.backMaterial, colourBack, colour);
        colour = litColour(m, colourFront, colour);
    }
    const glm::vec4 first = batch.vertices.empty() ? glm::vec4(0.0f) : batch.vertices[0].color;
    if (backDiffers) pickSides(batch, backs, a.frontFace == GL_CW);
    return first;
}

glm::vec3 FixedLighting::unlitColour(const AttribState& a, const glm::vec4& colour)
{
    glm::vec3 ambientLight = glm::max(a.modelAmbient, glm::vec3(0.0f));
    for (size_t i = 0; i < 8; ++i) {
        if (a.lightsOn & (1u << i)) ambientLight += glm::max(a.lightAmbient[i], glm::vec3(0.0f));
    }
    const GLenum mode = a.frontColorMaterial() ? a.colorMaterialMode : 0;
    const bool colourAmbient = mode == GL_AMBIENT || mode == GL_AMBIENT_AND_DIFFUSE;
    const glm::vec3 reflects = colourAmbient ? glm::vec3(colour) : a.material.ambient;
    const glm::vec3 emits = mode == GL_EMISSION ? glm::vec3(colour) : a.material.emission;
    return glm::clamp(glm::max(emits, glm::vec3(0.0f)) + reflects * ambientLight, 0.0f, 1.0f);
}

float FixedLighting::ambientShare(const AttribState& a, const glm::vec4& colour,
                                  const glm::vec4& litSide)
{
    const glm::vec3 unlit = unlitColour(a, colour);
    const float lit = luma(glm::vec3(litSide));
    // A black lit side (a black material): no light makes it lighter, GL shows it the same
    // everywhere.
    if (!(lit > 1e-4f)) return 1.0f;
    const float share = luma(unlit) / lit;
    return std::isfinite(share) ? std::clamp(share, 0.0f, 1.0f) : -1.0f;
}

glm::vec3 FixedLighting::shadowTint(const AttribState& a, const glm::vec4& colour,
                                    const glm::vec4& litSide)
{
    const glm::vec3 unlit = unlitColour(a, colour);
    const float unlitLuma = luma(unlit), litLuma = luma(glm::vec3(litSide));
    // Too dark to have a hue that shows, or no lit colour to compare with.
    if (!(unlitLuma > 1e-3f) || !(litLuma > 1e-3f)) return glm::vec3(1.0f);
    // A channel the lit side (nearly) lacks cannot say its hue: it darkens as the whole does.
    glm::vec3 tint(unlitLuma / litLuma);
    for (int c = 0; c < 3; ++c) {
        if (litSide[c] > 1.0f / 64.0f) tint[c] = unlit[c] / litSide[c];
    }
    const float scale = luma(glm::vec3(litSide) * tint);
    if (!(scale > 1e-6f) || !std::isfinite(scale)) return glm::vec3(1.0f);
    tint *= litLuma / scale;
    // Times the lit colour and its ambient share this is GL's unlit colour; the bound only
    // keeps a channel the lit side nearly lacks from growing without limit.
    return glm::clamp(tint, 0.0f, 16.0f);
}

float FixedLighting::diffuseShare(const AttribState& a, const glm::vec4& colour,
                                  const glm::vec4& litSide, size_t key)
{
    const GLenum mode = a.frontColorMaterial() ? a.colorMaterialMode : 0;
    const bool colourDiffuse = mode == GL_DIFFUSE || mode == GL_AMBIENT_AND_DIFFUSE;
    const glm::vec3 reflects = colourDiffuse ? glm::vec3(colour) : glm::vec3(a.material.diffuse);
    const glm::vec3 added =
        glm::clamp(reflects * glm::max(a.lightDiffuse[key], glm::vec3(0.0f)), 0.0f, 1.0f);
    const float lit = luma(glm::vec3(litSide));
    if (!(lit > 1e-4f)) return -1.0f;
    const float share = luma(added) / lit;
    return std::isfinite(share) ? std::max(share, 0.0f) : -1.0f;
}

} // namespace nprgl
