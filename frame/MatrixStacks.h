#pragma once

// MatrixStacks: the modelview, projection and texture matrix stacks (one per texture unit)
// and the matrix mode, as the program set them (glMatrixMode, glActiveTexture,
// glLoad/Mult/Push/PopMatrix and the transform calls).

#include <GL/gl.h>
#include <glm/glm.hpp>

#include <array>
#include <vector>

namespace nprgl {

class MatrixStacks {
public:
    void setMode(GLenum mode) { mMode = mode; }
    // glActiveTexture: the texture stack GL_TEXTURE mode works on.
    void setUnit(int unit) { mUnit = unit >= 0 && unit < kUnits ? unit : kUnits; }
    // The current stack's top, for the calls that load or multiply it.
    glm::mat4& top();
    // The driver refuses a push past its stack depth and a pop of the last matrix.
    void push();
    void pop();
    const glm::mat4& modelview() const { return mModelview.back(); }
    const glm::mat4& projection() const { return mProjection.back(); }
    // Unit `unit`'s texture matrix (identity for units past the first eight).
    const glm::mat4& texture(int unit) const
    {
        return mTexture[unit >= 0 && unit < kUnits ? size_t(unit) : size_t(kUnits)].back();
    }

private:
    std::vector<glm::mat4>& current();

    static constexpr size_t kMaxDepth = 64;
    static constexpr int kUnits = 8;
    GLenum mMode = GL_MODELVIEW;
    int mUnit = 0;
    std::vector<glm::mat4> mModelview{glm::mat4(1.0f)};
    std::vector<glm::mat4> mProjection{glm::mat4(1.0f)};
    // Units 0-7, and one more for units past them (followed, never read).
    std::array<std::vector<glm::mat4>, kUnits + 1> mTexture = identities();

    static std::array<std::vector<glm::mat4>, kUnits + 1> identities()
    {
        std::array<std::vector<glm::mat4>, kUnits + 1> stacks;
        for (auto& s : stacks) s.assign(1, glm::mat4(1.0f));
        return stacks;
    }
};

} // namespace nprgl
