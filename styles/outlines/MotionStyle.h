#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/outlines/MotionHistory.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace nprgl::styles {

// Speed lines (the comic artist's motion lines the thesis planned, §5.1 and its ref. [39]):
// from silhouette points of a moving object, short strokes trailing opposite its screen motion
// between frames, as long as it moved fast, fading along the stroke and over a few frames.
// Motion is per vertex (MotionHistory), so objects turning in place (gears) and skinned limbs
// get lines too; still objects get none. Strokes are thin quads in window space at the depth
// of their silhouette point, depth-tested against the scene.
class MotionStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    struct Line {
        glm::vec3 head;   // window pixels and NDC depth, next to the silhouette
        glm::vec2 tail;   // window pixels
        uint64_t frame;   // the frame that made it
    };
    struct Candidate {
        uint32_t priority; // stable per vertex: who gets a line where lines would crowd
        uint32_t vertex;
        glm::vec2 trail;   // unit, opposite the vertex's screen motion
        float speed;       // pixels per frame
    };
    struct QuadVertex {
        glm::vec3 position; // window pixels, NDC depth
        glm::vec3 line;     // opacity, pixels across the line's centre, half width there
    };

    void addLines(const SceneObject& object, const std::vector<glm::vec3>& now,
                  const std::vector<glm::vec3>& before, uint64_t frame);
    void appendQuad(const Line& line, float opacity);

    ShaderProgram mProgram;
    GLuint mBuffer = 0;
    GLint mViewport = -1, mColour = -1;
    glm::vec3 mColourValue{0.0f};
    float mMinSpeed = 0.5f, mLengthScale = 8.0f, mMaxLength = 80.0f, mSpacing = 8.0f;
    float mWidth = 1.5f, mGap = 3.0f, mOpacity = 0.9f;
    int mFadeFrames = 4;
    glm::ivec4 mLinesViewport{0}; // the pixels mLines are in

    MotionHistory mHistory;
    std::vector<Line> mLines; // the last fade_frames frames' lines, oldest first
    // Scratch reused between flushes.
    std::vector<uint8_t> mFront;          // per face: faces the eye
    std::vector<float> mLeaving;          // per vertex: best cosine, outside to trail; -2: none
    std::vector<Candidate> mCandidates;
    std::vector<glm::vec3> mPlaced;       // this object's line heads (x, y) and lengths
    std::vector<QuadVertex> mUpload;
};

} // namespace nprgl::styles
