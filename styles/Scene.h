#pragma once

#include "reconstruct/ObjectMesh.h"

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace nprgl::styles {

// The program's enabled GL lights at a lit draw, the brightest first: what the shading styles'
// light term sums, as GL's diffuse sum does (ShadingCommon's litDot).
struct SceneLights {
    struct Light {
        glm::vec4 position{0.0f, 0.0f, 1.0f, 0.0f}; // eye space; w 0: towards a far light
        glm::vec3 spotDirection{0.0f, 0.0f, -1.0f}; // eye space, unit, where a spot points
        float spotCosCutoff = -2.0f;                 // below -1: not a spot
        // Constant, linear, quadratic attenuation and spot exponent: 1, 0, 0 for a far light,
        // exponent 0 for one that is no spot (the shader's factors are then 1).
        glm::vec4 falloff{1.0f, 0.0f, 0.0f, 0.0f};
        float weight = 1.0f; // its diffuse brightness against the brightest light's (1)
    };
    uint32_t count = 0; // 0: the object was not lit by the program
    Light lights[8];
    // What GL shows where none of the lights reaches (the material's emission and what it
    // reflects of the ambient light), as a share of the object's colour on its lit side:
    // how dark the program's own shadowed side is. Below 0: not known.
    float ambientShare = -1.0f;
    // The hue of that shadowed side against the lit side's, per channel (luma 1): GL's unlit
    // colour over its lit colour, normalised. Not grey where the lights are coloured and the
    // ambient light is not (extrusion's yellow and cyan lights make its cream tubes green
    // where lit, olive where not). 1: the same hue, or not known.
    glm::vec3 shadowTint{1.0f};
    // What the brightest light adds facing a surface head-on, as a share of the same colour
    // (FixedLighting::diffuseShare): GL's light at a point is about ambientShare plus this
    // times the lights' L·n. Below 0: not known.
    float diffuseShare = -1.0f;
    // GL's highlight from the brightest light: its specular colour times the material's, and
    // the material's Blinn exponent. Black: the material does not shine.
    glm::vec3 shine{0.0f};
    float shininess = 0.0f;
    // GL_LIGHT_MODEL_TWO_SIDE: GL lights the side facing the eye; else both sides by the
    // program's normal as it is.
    bool twoSide = false;
};

// Texture object 0 (GL's default 2D texture, one for all units), where a program that never
// names its textures (glTexImage2D with none bound) keeps its image: in the scene by this
// name, since 0 there means no texture. textureName() gives the name to bind.
constexpr GLuint kDefaultTexture = ~0u;
inline GLuint textureName(GLuint texture) { return texture == kDefaultTexture ? 0 : texture; }

// Whether a projection divides by depth: its last row is not (0, 0, 0, w). Not the element w
// alone: a program that puts its camera into the projection matrix (glFrustum, then the view
// on GL_PROJECTION, the modelview left the identity) has the camera's translation there.
inline bool perspective(const glm::mat4& projection)
{
    return projection[0][3] != 0.0f || projection[1][3] != 0.0f || projection[2][3] != 0.0f;
}

// A texture the program maps by coordinates GL generates (glTexGen on S and T): a reflection
// (GL_SPHERE_MAP) or a projection (GL_OBJECT_LINEAR, GL_EYE_LINEAR planes). A projection is
// the surface's texture; a reflection is dropped unless a style's parameter shows it
// (`reflections`). Drawn on the coordinates GL would generate (ShadingCommon's vertex shader).
struct GeneratedTexture {
    GLuint texture = 0;
    GLenum mode[2] = {0, 0}; // of S and T: GL_SPHERE_MAP, GL_OBJECT_LINEAR or GL_EYE_LINEAR
    // Each coordinate's plane: in object space for GL_OBJECT_LINEAR, in eye space (as
    // glTexGen transformed it by the modelview of its call) for GL_EYE_LINEAR.
    glm::vec4 plane[2]{glm::vec4(1.0f, 0.0f, 0.0f, 0.0f), glm::vec4(0.0f, 1.0f, 0.0f, 0.0f)};
    glm::mat4 matrix{1.0f}; // the unit's texture matrix, which GL applies after generating
    // The texture's mean colour (1 where unknown): where the styles drop the texture (a
    // reflection, see ShadingCommon::reflectionsParam) the surface keeps its average tint, as
    // a chrome or crystal object whose only colour is its reflection keeps its hue.
    glm::vec3 mean{1.0f};
};

// How a draw looks, as the program's state at it says: what the tracker records per batch
// (frame/StateTracker's TrackedBatch) and the styles draw each object with (SceneObject), one
// record for both, so nothing is copied field by field between them.
struct Appearance {
    glm::mat4 projection{1.0f};
    // Every light the program lit it with, the brightest first (none: unlit, or no light on).
    SceneLights lights;
    // The normal GL lights by and reflects a sphere map about: the program's as the modelview
    // moved it, unit only under GL_NORMALIZE (GL_RESCALE_NORMAL takes out the modelview's
    // scale). 0, GL_NORMALIZE or GL_RESCALE_NORMAL. blocktube's normals are 0.7 long, and
    // boxed scales its balls by 3 without either: GL shows them a third as lit.
    GLenum normals = GL_NORMALIZE;
    // The winding the program culled (GL_CW, GL_CCW) in the winding batches are assembled in,
    // all (GL_FRONT_AND_BACK) or none (0): the styles cull the same faces (FaceCulling). Two
    // passes over one mesh that cull opposite faces draw different triangles.
    GLenum culled = 0;
    // A texture on generated coordinates (texture is then 0): ShadingCommon::withGenerated.
    GeneratedTexture generated;
    GLuint texture = 0; // the program's GL_TEXTURE_2D when enabled, else 0
    // A lightmap layered over the texture (its own coordinates: Vertex::lightcoord): with no
    // GL lighting, the shading styles take their light from it instead of L·n. 0: none.
    GLuint lightmap = 0;
    // What the program's layers over the texture that the styles do not draw do to its colour
    // on average: c scale + offset, before fog, from each layer's texture mean (a detail
    // texture added signed over a terrain keeps the terrain's brightness). Identity where a
    // layer is not followed.
    glm::vec3 layerScale{1.0f};
    glm::vec3 layerOffset{0.0f};
    // Blended over what is behind it by its alpha (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA):
    // drawn by the shading style after the opaque scene, with its depth writes as the program
    // had them (StyleChain::render).
    bool translucent = false;
    bool depthWrite = true;
    // Drawn by the program without the depth test (or, opaque, without depth writes): a sky
    // or scenery behind the scene (before its other objects) or a mark over it (after them).
    // The shading style draws it so, in that place; outline styles leave it out.
    bool depthTest = true;
    // Without the test, the program's depth test on at GL_ALWAYS: its depth is written (with
    // depthWrite) where it draws, whatever was there.
    bool depthAlways = false;
    // The program's depth function. Translucent objects are tested with GL_LEQUAL where the
    // program's is: text a program draws each frame at one depth without clearing depth
    // fails GL_LESS against the depth it left the frame before.
    GLenum depthFunc = GL_LESS;
    // The program's alpha test (GL_ALWAYS: none): the shading style's alpha is tested as the
    // program's would be, so cut-outs keep their shape; only outline styles that follow the
    // cut draw their lines (Style::outlinesCutOuts).
    GLenum alphaFunc = GL_ALWAYS;
    float alphaRef = 0.0f;
    // Under the alpha test, how fine its texture's cut is (TextureImage::cutFeature), in
    // texture coordinate units (an object's: the finest of its batches'); 0 when not known,
    // kKeptWhole when the test cuts nothing of the texture (a mostly opaque blended surface,
    // shaped by its polygons).
    float cutFeature = 0.0f;
    // Drawn by the program with no colour channel (a depth pre-pass, an occluder): the chain
    // writes its depth after the opaque scene and draws no colour for it.
    bool depthOnly = false;
    // The program's polygon offset (GL_POLYGON_OFFSET_FILL's, 0 when off; decals on a
    // surface): applied in the shading pass; outline styles leave such objects out (their
    // edges would fight the surface's).
    float offsetFactor = 0.0f, offsetUnits = 0.0f;
    bool special() const
    {
        return alphaFunc != GL_ALWAYS || offsetFactor != 0.0f || offsetUnits != 0.0f;
    }
    // A decal: pulled towards the eye over a surface by its offset (its lines would fight
    // the surface's). An offset that pushes away keeps an object behind marks drawn over it.
    bool lifted() const { return offsetFactor < 0.0f || offsetUnits < 0.0f; }
    // The program's fog at its draw (mode 0: none), applied to the styled colours by the
    // eye distance as GL's fixed pipeline does.
    struct Fog {
        GLenum mode = 0; // GL_LINEAR, GL_EXP, GL_EXP2, or 0 when fog is off
        float start = 0.0f, end = 1.0f, density = 1.0f;
        glm::vec3 colour{0.0f};
    } fog;
};

// One object the compositor held back: a welded mesh and the state it was drawn with.
// Colours per corner (mesh->corner(f, k).color) are what the program's picture shows: the
// current colour, or the material's diffuse when it lit the object without colour-material.
struct SceneObject : Appearance {
    std::shared_ptr<const reconstruct::ObjectMesh> mesh;
    glm::mat4 modelview{1.0f};
    // Towards the light in eye space, unit: the brightest enabled light's position (or
    // direction) when the program lit the object, else a head-light from the upper left.
    glm::vec3 lightDir{0.0f, 0.0f, 1.0f};
    // Shaded in one even light (the shading styles' middle band): a sky or backdrop the
    // program did not light, which a head-light would shade by its faces' arbitrary normals.
    bool flatLight = false;
    // Faces drawn with another texture than `texture` (a cube with a texture per face is one
    // object): runs of consecutive faces, in the mesh's face order, covering all of them.
    // Empty when every face has `texture`.
    struct TextureRun {
        uint32_t firstFace = 0;
        uint32_t faceCount = 0;
        GLuint texture = 0;
        GLuint lightmap = 0;
    };
    std::vector<TextureRun> textureRuns;
    uint32_t id = 0;               // 1, 2, ... in drawing order: for ID buffers

    // Whether any face is drawn with a texture of the program's.
    bool textured() const
    {
        if (texture != 0) return true;
        for (const TextureRun& run : textureRuns) {
            if (run.texture != 0) return true;
        }
        return false;
    }

    // Whether any face has a lightmap.
    bool lightmapped() const
    {
        if (lightmap != 0) return true;
        for (const TextureRun& run : textureRuns) {
            if (run.lightmap != 0) return true;
        }
        return false;
    }
    // A projection without a perspective row looks along -z everywhere.
    bool orthographic() const { return !perspective(projection); }
    // Whether the window-space winding of its faces is the mirror of their eye-facing one: a
    // mirroring modelview, or a projection that mirrors x against y (glOrtho(0, w, h, 0, ...),
    // the top-down 2D view many programs draw in; a z flip alone turns no winding).
    bool mirrored() const
    {
        const glm::mat4& p = projection;
        const bool projects = p[0][0] * p[1][1] - p[1][0] * p[0][1] < 0.0f;
        return (glm::determinant(glm::mat3(modelview)) < 0.0f) != projects;
    }
};

// What one flush of the compositor hands to the styles.
struct Scene {
    std::vector<SceneObject> objects;
    glm::ivec4 viewport{0, 0, 0, 0}; // the program's viewport at the draws
    glm::vec4 clearColor{0.0f, 0.0f, 0.0f, 1.0f};
    uint64_t frame = 0;              // frames since the context started (0-based)
    uint32_t framebuffer = 0;        // the draw framebuffer the scene was drawn into
    uint64_t colourClears = 0;       // the program's colour clears so far (a running count)
    // Nothing was drawn into the viewport's colour since the program cleared it (or, in a
    // window's back buffer, since the last frame was shown): every pixel at the far depth is
    // background, whatever its colour.
    bool colourFresh = false;
    // The program drew the scene confined to the scissor box (x, y, width, height, window
    // pixels); the styles draw it so too.
    bool scissored = false;
    glm::ivec4 scissor{0, 0, 0, 0};
    // The program's glDepthRange for the scene (one per scene: a change flushes).
    glm::vec2 depthRange{0.0f, 1.0f};
    // The program's draws write alpha (one per scene: a change flushes); when they do not,
    // neither do the styles in its framebuffer (a program may keep data there).
    bool alphaWrites = true;
    // The flush comes before the program copies the framebuffer into a texture (glCopyTex*):
    // these pixels are that texture's content (a reflection, an environment map), not the
    // window's picture, so no page is laid in them (PaperStyle).
    bool copiedToTexture = false;

    // Everything but the objects, from `whole` (for a part of it drawn on its own).
    void takeFrameOf(const Scene& whole)
    {
        viewport = whole.viewport;
        clearColor = whole.clearColor;
        frame = whole.frame;
        framebuffer = whole.framebuffer;
        colourClears = whole.colourClears;
        colourFresh = whole.colourFresh;
        scissored = whole.scissored;
        scissor = whole.scissor;
        depthRange = whole.depthRange;
        alphaWrites = whole.alphaWrites;
        copiedToTexture = whole.copiedToTexture;
    }
    // `rect` (x, y, width, height, window pixels) within the scissor box, when scissored.
    glm::ivec4 confined(glm::ivec4 rect) const
    {
        if (!scissored) return rect;
        const glm::ivec2 lo = glm::max(glm::ivec2(rect), glm::ivec2(scissor));
        const glm::ivec2 hi = glm::min(glm::ivec2(rect) + glm::ivec2(rect.z, rect.w),
                                       glm::ivec2(scissor) + glm::ivec2(scissor.z, scissor.w));
        return glm::ivec4(lo, glm::max(hi - lo, glm::ivec2(0)));
    }
};

} // namespace nprgl::styles
