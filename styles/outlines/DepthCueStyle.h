#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"

#include <glm/glm.hpp>

#include <vector>

namespace nprgl::styles {

// HijackGL's depth-cued wireframe: the edges of the scene's meshes (every edge, or only the
// silhouettes, creases and borders) drawn as lines whose intensity and width fall off with
// depth between the nearest and the farthest point of the scene, so near parts read first.
// Lines are depth-tested against the scene: hidden edges stay hidden.
class DepthCueStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    struct LineVertex {
        glm::vec3 eye;   // eye-space position
        float intensity; // 1 near ... far_intensity far
    };
    static constexpr int kMaxLevels = 8;

    ShaderProgram mProgram;
    GLuint mBuffer = 0;
    GLint mProjection = -1, mInk = -1;
    bool mAllEdges = true;
    float mNearWidth = 2.5f, mFarWidth = 0.5f, mNearIntensity = 1.0f, mFarIntensity = 0.15f;
    int mLevels = 4;
    glm::vec3 mInkColour{0.0f};
    glm::vec2 mLineRange{1.0f};
    // Scratch reused between frames: eye-space points per object, lines per width level.
    std::vector<std::vector<glm::vec3>> mEye;
    std::vector<LineVertex> mLines[kMaxLevels];
    std::vector<LineVertex> mUpload;
};

} // namespace nprgl::styles
