#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"

#include <glm/glm.hpp>

#include <vector>

namespace nprgl::styles {

// HijackGL's blueprint renderer: white silhouettes, creases and borders drawn a few pixels
// past their ends (construction lines), a faint grid over the page, and dimension lines with
// arrowheads and the length in object units on the longest visible straight edges, and,
// optionally, the hidden lines dashed. The
// `blueprint` preset puts it over blue paper and flat blue surfaces.
class BlueprintStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    struct Vertex {
        glm::vec3 ndc;
        float alpha;
        float along; // pixels from the line's first end: where the dashes fall
    };
    // An edge chosen for a dimension: its ends in NDC and its object-space length.
    struct Dimension {
        glm::vec3 a, b;
        float length = 0.0f;
        float rank = 0.0f; // object-space length: stable from frame to frame
    };

    void addLine(glm::vec3 a, glm::vec3 b, float alpha, float extendPixels);
    void addDimension(const Dimension& d);
    void addText(const std::string& text, glm::vec2 centre, glm::vec2 along, float alpha);
    glm::vec2 toPixels(glm::vec3 ndc) const;
    glm::vec3 fromPixels(glm::vec2 p, float z) const;

    ShaderProgram mProgram;
    GLuint mBuffer = 0;
    GLint mInk = -1;
    GLint mDash = -1;
    glm::vec3 mInkColour{1.0f};
    float mWidth = 1.5f, mExtend = 6.0f, mGrid = 24.0f, mGridAlpha = 0.18f;
    int mDimensions = 3;
    float mHidden = 0.0f, mDashLength = 5.0f;
    glm::vec2 mLineRange{1.0f};
    glm::ivec4 mViewport{0};
    std::vector<Vertex> mLines, mGridLines;
    std::vector<Dimension> mCandidates;
};

} // namespace nprgl::styles
