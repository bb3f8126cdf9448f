#pragma once

// FixedLighting: GL's fixed-function lighting and flat shading, per vertex, on the CPU.

#include "frame/AttribStack.h"
#include "frame/StateTracker.h"

#include <glm/glm.hpp>

#include <vector>

namespace nprgl {

// The colours the fixed pipeline gives a batch's vertices (OpenGL 2.1, section 2.14.1): the
// material's emission, the scene's ambient, and per enabled light its ambient, diffuse
// (N·L) and specular (Blinn's N·H, at the infinite or the local viewer), attenuated and cut
// by its spot; clamped per channel. For the `replica` style, which must draw what the
// program's picture shows; the other styles shade from the material's colour instead.
class FixedLighting {
public:
    using Material = AttribState::Material;
    // The light on the lit side of a surface (litSideLight): what GL's ambient reflectance
    // takes (the scene's ambient and the lights' own) and what its diffuse takes.
    struct SideLight {
        glm::vec3 ambient{0.0f};
        glm::vec3 diffuse{1.0f};
    };

    // Lights every vertex of `batch` (batch.modelview set, colours still the current colour
    // per vertex) with the material state `a`, its colour-material mode and the diffuse
    // changes between glBegin and glEnd (batch.materials). With GL_LIGHT_MODEL_TWO_SIDE,
    // primitives whose window winding shows their back (batch.projection set) are lit from
    // the other side with the back material, as GL lights them (pickSides).
    static void lightBatch(const AttribState& a, TrackedBatch& batch);
    // The light on the lit side of a surface at `at` (eye space), `key` the brightest light:
    // the scene's ambient, every enabled light's ambient, and its diffuse at N·L 0.75 (some
    // 40 degrees off the light), as GL sums them; at full strength (scaled so that its
    // brightest channel is 1: the styles' bands shade, a white light changes nothing). But
    // where the ambient and the key light alone pass 1 (lights that reach everywhere: not
    // spots, not attenuated), that sum as it is: GL brightens the material so, and clamps per
    // channel. A bluish ambient under a pinkish sun lights snow white where both together
    // pass 1 in every channel (extremetuxracer's) and its yellow yellower; a pinkish sun alone
    // lights it pink. Other lights come from elsewhere: at most a part of them adds to the
    // key's on one surface, so they only tint. A positional light whose attenuation brightens
    // it at `at` (a constant factor below 1, antmaze's 0.1) counts so brightened, as one that
    // reaches everywhere: GL lights the surface that much brighter and clamps.
    static SideLight litSideLight(const AttribState& a, const glm::vec3& at, size_t key);
    // Colours a lit batch for the shading styles: each vertex its material's (or its colour
    // material's) diffuse colour on the lit side in all of `light`, plus its emission,
    // clamped per channel (GL's ambient reflectance is the shadow band's: shadowTint); with
    // GL_LIGHT_MODEL_TWO_SIDE and a back unlike the front, the faces the window shows wound
    // the other way in the back's (pickSides). Returns the first vertex's front colour.
    static glm::vec4 colourLitSides(const AttribState& a, TrackedBatch& batch,
                                    const SideLight& light);
    // Gives each primitive the colours of the side it shows in the window: the vertices'
    // back colours (`backs`, one per vertex) where its winding is clockwise (counter-clockwise
    // when `clockwiseFront`, glFrontFace(GL_CW)). Strips and fans become separate primitives.
    static void pickSides(TrackedBatch& batch, const std::vector<glm::vec4>& backs,
                          bool clockwiseFront);
    // Under glShadeModel(GL_FLAT): each primitive in its provoking vertex's colour, as GL's
    // flat shading draws it (OpenGL 2.1, table 2.2). Strips and fans are unrolled into
    // separate triangles or quads (their vertices differ in colour from face to face).
    static void flattenBatch(TrackedBatch& batch);
    // Towards light i from the eye-space point `eye` (unit, into l), and how much of the
    // light reaches it (attenuation and spot; 1 for a far light). False where the point is
    // at the light, or not finite.
    static bool towardsLight(const AttribState& a, size_t i, const glm::vec3& eye, glm::vec3& l,
                             float& reach);
    // GL's colour where no light reaches a surface of colour `colour` (the current colour,
    // for colour material), emission and ambient terms, as a share (0..1, by luma) of
    // `litSide`, the colour the styles give its lit side.
    static float ambientShare(const AttribState& a, const glm::vec4& colour,
                              const glm::vec4& litSide);
    // The same unlit colour's hue against `litSide`'s: per channel unlit / litSide, scaled so
    // that litSide times it keeps litSide's luma (SceneLights::shadowTint). 1 where unknown.
    static glm::vec3 shadowTint(const AttribState& a, const glm::vec4& colour,
                                const glm::vec4& litSide);
    // GL's colour where no light reaches: emission plus the ambient light reflected, clamped.
    static glm::vec3 unlitColour(const AttribState& a, const glm::vec4& colour);
    // What light `key` adds to that colour facing the surface head-on (the material's or the
    // colour's diffuse reflection of it), as a share of `litSide` by luma: with ambientShare,
    // how GL's own light at a point compares with the lit side. Below 0: not known.
    static float diffuseShare(const AttribState& a, const glm::vec4& colour,
                              const glm::vec4& litSide, size_t key);
    // One vertex: eye-space position and normal (as GL transformed them, not normalised).
    static glm::vec4 shade(const AttribState& a, const Material& m, const glm::vec3& eye,
                           glm::vec3 normal);
};

} // namespace nprgl
