#include "frame/MatrixStacks.h"

namespace nprgl {

std::vector<glm::mat4>& MatrixStacks::current()
{
    switch (mMode) {
    case GL_PROJECTION: return mProjection;
    case GL_TEXTURE: return mTexture[size_t(mUnit)];
    default: return mModelview;
    }
}

glm::mat4& MatrixStacks::top() { return current().back(); }

void MatrixStacks::push()
{
    std::vector<glm::mat4>& stack = current();
    if (stack.size() < kMaxDepth) stack.push_back(stack.back());
}

void MatrixStacks::pop()
{
    std::vector<glm::mat4>& stack = current();
    if (stack.size() > 1) stack.pop_back();
}

} // namespace nprgl
