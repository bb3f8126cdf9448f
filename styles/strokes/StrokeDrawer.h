#pragma once

#include "common/PngImage.h"
#include "styles/GlFunctions.h"
#include "styles/ShaderProgram.h"
#include "styles/strokes/StrokeGeometry.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace nprgl::styles::strokes {

// Draws a frame's stroke quads (StrokeGeometry) with blending: either as soft lines with
// round ends (the sketchy renderer) or with the stroke texture (the textured renderer),
// whose start cap, tiling middle and end cap follow the screen arc length. All GL lives
// here; the quads arrive already in normalised device coordinates.
class StrokeDrawer {
public:
    struct Options {
        bool textured = false;
        bool depthTest = false; // z-buffer visibility: test against the scene's depth
        glm::vec4 color{0.1f, 0.1f, 0.1f, 1.0f};
        float capLength = 16.0f;  // pixels of the texture's caps
        float tileLength = 96.0f; // pixels of one middle tile
        float u1 = 0.25f, u2 = 0.75f;
    };

    bool init(const GlFunctions& gl, std::string& error);
    void destroy(const GlFunctions& gl);
    // Uploads the stroke texture (RGBA8, u along the stroke); kept until the next call.
    void setTexture(const GlFunctions& gl, const PngImage& image);
    void draw(const GlFunctions& gl, const std::vector<StrokeVertex>& vertices,
              const Options& options);

private:
    ShaderProgram mSketchy, mTextured;
    GLuint mBuffer = 0;
    GLsizeiptr mBufferBytes = 0;
    GLuint mTexture = 0;
};

} // namespace nprgl::styles::strokes
