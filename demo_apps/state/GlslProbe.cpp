#include "GlslProbe.h"

#include <cstdio>

namespace {

const char* kVertex = R"(#version 110
uniform float scale;
attribute float weight;
varying vec4 colour;
void main()
{
    vec3 n = normalize(gl_NormalMatrix * gl_Normal);
    colour = gl_Color * (0.5 + 0.5 * max(n.z, 0.0)) * weight;
    gl_Position = ftransform() * vec4(scale, scale, 1.0, 1.0);
}
)";

const char* kFragment = R"(#version 110
uniform vec4 tint;
varying vec4 colour;
void main() { gl_FragColor = colour * tint; }
)";

// An undeclared name: GL must refuse it and say why, under nprgl as natively.
const char* kBroken = R"(#version 110
void main() { gl_FragColor = undeclared; }
)";

GLuint compile(GLenum kind, const char* source)
{
    const GLuint shader = glCreateShader(kind);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    return shader;
}

double shaderInt(GLuint shader, GLenum name)
{
    GLint value = -1;
    glGetShaderiv(shader, name, &value);
    return value;
}

double programInt(GLuint program, GLenum name)
{
    GLint value = -1;
    glGetProgramiv(program, name, &value);
    return value;
}

// A log's length and a checksum of its text: the same log gives the same two.
std::vector<double> logOf(GLuint object, bool program)
{
    char text[2048] = {};
    GLsizei length = 0;
    if (program) {
        glGetProgramInfoLog(object, sizeof text, &length, text);
    } else {
        glGetShaderInfoLog(object, sizeof text, &length, text);
    }
    unsigned sum = 0;
    for (GLsizei i = 0; i < length; ++i) sum = sum * 31u + static_cast<unsigned char>(text[i]);
    return {double(length), double(sum % 1000003u)};
}

} // namespace

bool GlslProbe::init(std::string& error)
{
    mVertex = compile(GL_VERTEX_SHADER, kVertex);
    mFragment = compile(GL_FRAGMENT_SHADER, kFragment);
    mBroken = compile(GL_FRAGMENT_SHADER, kBroken);
    mProgram = glCreateProgram();
    glAttachShader(mProgram, mVertex);
    glAttachShader(mProgram, mFragment);
    glLinkProgram(mProgram);
    if (programInt(mProgram, GL_LINK_STATUS) != GL_TRUE) {
        error = "the GLSL program did not link";
        return false;
    }
    if (shaderInt(mBroken, GL_COMPILE_STATUS) != GL_FALSE) {
        error = "a shader with an undeclared name compiled";
        return false;
    }
    mTint = glGetUniformLocation(mProgram, "tint");
    mScale = glGetUniformLocation(mProgram, "scale");
    mWeight = glGetAttribLocation(mProgram, "weight");
    if (mTint < 0 || mScale < 0 || mWeight < 0) {
        error = "the GLSL program lacks its uniforms or attribute";
        return false;
    }
    mAtInit = ask();
    return true;
}

void GlslProbe::draw(int frame)
{
    mFrame = frame;
    glUseProgram(mProgram);
    // Exact in binary, so a query gives back the very numbers.
    glUniform4f(mTint, 1.0f, 0.5f + 0.0625f * float(frame % 4), 0.25f, 1.0f);
    glUniform1f(mScale, 0.25f);
    glVertexAttrib1f(GLuint(mWeight), 0.75f);
    glColor3f(0.9f, 0.8f, 0.2f);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glBegin(GL_QUADS);
    glVertex3f(-1.0f, -1.0f, 0.0f);
    glVertex3f(1.0f, -1.0f, 0.0f);
    glVertex3f(1.0f, 1.0f, 0.0f);
    glVertex3f(-1.0f, 1.0f, 0.0f);
    glEnd();
    glUseProgram(0);
}

std::vector<GlslProbe::Answer> GlslProbe::ask() const
{
    std::vector<Answer> out;
    out.push_back({"vertex shader GL_COMPILE_STATUS", {shaderInt(mVertex, GL_COMPILE_STATUS)}});
    out.push_back({"broken shader GL_COMPILE_STATUS", {shaderInt(mBroken, GL_COMPILE_STATUS)}});
    out.push_back({"broken shader info log", logOf(mBroken, false)});
    out.push_back({"program GL_LINK_STATUS", {programInt(mProgram, GL_LINK_STATUS)}});
    out.push_back({"program info log", logOf(mProgram, true)});
    out.push_back({"program GL_ATTACHED_SHADERS", {programInt(mProgram, GL_ATTACHED_SHADERS)}});
    out.push_back({"program GL_ACTIVE_UNIFORMS", {programInt(mProgram, GL_ACTIVE_UNIFORMS)}});
    out.push_back({"program GL_ACTIVE_ATTRIBUTES", {programInt(mProgram, GL_ACTIVE_ATTRIBUTES)}});
    out.push_back({"uniform locations tint, scale",
                   {double(glGetUniformLocation(mProgram, "tint")),
                    double(glGetUniformLocation(mProgram, "scale"))}});
    out.push_back({"attribute location weight",
                   {double(glGetAttribLocation(mProgram, "weight"))}});
    GLfloat tint[4] = {-1, -1, -1, -1};
    GLfloat scale = -1;
    glGetUniformfv(mProgram, mTint, tint);
    glGetUniformfv(mProgram, mScale, &scale);
    out.push_back({"uniform values tint, scale",
                   {tint[0], tint[1], tint[2], tint[3], scale}});
    return out;
}

std::vector<GlslProbe::Answer> GlslProbe::expected() const
{
    std::vector<Answer> out = mAtInit;
    out.back().values = {1.0, 0.5 + 0.0625 * (mFrame % 4), 0.25, 1.0, 0.25};
    return out;
}

std::string GlslProbe::summary() const
{
    std::string text = "glsl:";
    for (const Answer& answer : mAtInit) {
        text += " " + answer.name + " =";
        for (double v : answer.values) {
            char number[32];
            std::snprintf(number, sizeof number, " %.9g", v);
            text += number;
        }
        text += ";";
    }
    return text;
}

void GlslProbe::shutdown()
{
    glDeleteProgram(mProgram);
    glDeleteShader(mVertex);
    glDeleteShader(mFragment);
    glDeleteShader(mBroken);
}
