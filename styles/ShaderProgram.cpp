#include "styles/ShaderProgram.h"

#include <vector>

namespace nprgl::styles {

namespace {

GLuint compile(const GlFunctions& gl, GLenum type, const char* source, std::string& error)
{
    GLuint shader = gl.CreateShader(type);
    gl.ShaderSource(shader, 1, &source, nullptr);
    gl.CompileShader(shader);
    GLint ok = GL_FALSE;
    gl.GetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return shader;
    GLint length = 0;
    gl.GetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(size_t(std::max(length, 1)), '\0');
    gl.GetShaderInfoLog(shader, GLsizei(log.size()), nullptr, log.data());
    error = std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
            " shader: " + log.data();
    gl.DeleteShader(shader);
    return 0;
}

} // namespace

bool ShaderProgram::build(const GlFunctions& gl, const char* vertexSource,
                          const char* fragmentSource, std::string& error,
                          const char* secondColour)
{
    destroy(gl);
    GLuint vs = 0;
    if (vertexSource) {
        vs = compile(gl, GL_VERTEX_SHADER, vertexSource, error);
        if (!vs) return false;
    }
    GLuint fs = compile(gl, GL_FRAGMENT_SHADER, fragmentSource, error);
    if (!fs) {
        if (vs) gl.DeleteShader(vs);
        return false;
    }
    GLuint program = gl.CreateProgram();
    if (vs) gl.AttachShader(program, vs);
    gl.AttachShader(program, fs);
    gl.BindAttribLocation(program, 0, "position");
    gl.BindAttribLocation(program, 1, "normal");
    gl.BindAttribLocation(program, 2, "color");
    gl.BindAttribLocation(program, 3, "texcoord");
    gl.BindAttribLocation(program, 4, "lightcoord");
    gl.BindFragDataLocation(program, 0, "fragColor");
    if (secondColour && gl.BindFragDataLocationIndexed) {
        gl.BindFragDataLocationIndexed(program, 0, 1, secondColour);
    }
    gl.LinkProgram(program);
    if (vs) gl.DeleteShader(vs);
    gl.DeleteShader(fs);
    GLint ok = GL_FALSE;
    gl.GetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        gl.GetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(size_t(std::max(length, 1)), '\0');
        gl.GetProgramInfoLog(program, GLsizei(log.size()), nullptr, log.data());
        error = std::string("link: ") + log.data();
        gl.DeleteProgram(program);
        return false;
    }
    mProgram = program;
    return true;
}

void ShaderProgram::destroy(const GlFunctions& gl)
{
    if (mProgram) gl.DeleteProgram(mProgram);
    mProgram = 0;
}

} // namespace nprgl::styles
