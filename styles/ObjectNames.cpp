#include "styles/ObjectNames.h"

#include <atomic>

namespace nprgl::styles {

void ObjectNames::reserve(const GlFunctions& gl, Kind kind, GLsizei n, GLuint* names)
{
    // One counter for the process: contexts that share objects never get the same name.
    static std::atomic<GLuint> next{kFirst};
    auto inUse = [&](GLuint name) {
        switch (kind) {
        case Kind::Texture: return gl.IsTexture(name) != GL_FALSE;
        case Kind::Buffer: return gl.IsBuffer(name) != GL_FALSE;
        case Kind::Framebuffer: return gl.IsFramebuffer(name) != GL_FALSE;
        case Kind::Renderbuffer: return gl.IsRenderbuffer(name) != GL_FALSE;
        case Kind::Query: return gl.IsQuery(name) != GL_FALSE;
        }
        return true;
    };
    for (GLsizei i = 0; i < n; ++i) {
        GLuint name = next.fetch_add(1);
        // A program that took a name this high keeps it; past the top the range starts over.
        while (name == 0 || name < kFirst || inUse(name)) name = next.fetch_add(1);
        names[i] = name;
    }
}

} // namespace nprgl::styles
