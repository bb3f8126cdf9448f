#pragma once

// MatrixStacks: the modelview, projection and texture matrix stacks and the matrix mode, as
// the program set them (glMatrixMode, glLoad/Mult/Push/PopMatrix and the transform calls).

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <vector>

namespace nprgl {

class MatrixStacks {
public:
    void setMode(GLenum mode) { mMode = mode; }
    // The current stack's top, for the calls that load or multiply it.
    glm::mat4& top();
    // The driver refuses a push past its stack depth and a pop of the last matrix.
    void push();
    void pop();
    const glm::mat4& modelview() const { return mModelview.back(); }
    const glm::mat4& projection() const { return mProjection.back(); }

private:
    std::vector<glm::mat4>& current();

    static constexpr size_t kMaxDepth = 64;
    GLenum mMode = GL_MODELVIEW;
    std::vector<glm::mat4> mModelview{glm::mat4(1.0f)};
    std::vector<glm::mat4> mProjection{glm::mat4(1.0f)};
    std::vector<glm::mat4> mTexture{glm::mat4(1.0f)};
};

} // namespace nprgl
