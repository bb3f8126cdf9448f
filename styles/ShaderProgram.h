#pragma once

#include "styles/GlFunctions.h"

#include <string>

namespace nprgl::styles {

// A linked GLSL program. Attribute locations are fixed for every style's meshes (see
// MeshBuffers): 0 position, 1 normal, 2 colour, 3 texcoord; fragment output 0 is "fragColor".
class ShaderProgram {
public:
    ShaderProgram() = default;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    // Compiles and links; on failure returns false with the driver's log in error. Without a
    // vertex source (null) the fixed-function vertex stage feeds the fragment shader.
    // secondColour: the name of a second output blended as GL_SRC1_COLOR (dual-source
    // blending; the caller checked gl.BindFragDataLocationIndexed).
    bool build(const GlFunctions& gl, const char* vertexSource, const char* fragmentSource,
               std::string& error, const char* secondColour = nullptr);
    void destroy(const GlFunctions& gl);
    GLuint id() const { return mProgram; }
    GLint uniform(const GlFunctions& gl, const char* name) const
    {
        return gl.GetUniformLocation(mProgram, name);
    }

private:
    GLuint mProgram = 0;
};

} // namespace nprgl::styles
