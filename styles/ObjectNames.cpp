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
        GLuint name = next.fetch_sub(1);
        while (name < kLast || name > kFirst || inUse(name)) {
            if (name < kLast || name > kFirst) {
                GLuint seen = name - 1;
                next.compare_exchange_strong(seen, kFirst); // past the bottom: from the top
            }
            name = next.fetch_sub(1);
        }
        names[i] = name;
    }
}

} // namespace nprgl::styles
