// A core-profile program (OSMesa, OpenGL 3.3 core): draws a shaded triangle with a VAO and
// prints a checksum of its pixels. nprgl must pass it through untouched under any style.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/osmesa.h>
#include <GL/glext.h>

#include <cstdint>
#include <cstdio>
#include <vector>

namespace {

GLuint shader(GLenum type, const char* source)
{
    GLuint s = glCreateShader(type);
    glShaderSource(s, 1, &source, nullptr);
    glCompileShader(s);
    return s;
}

} // namespace

int main()
{
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    const int w = 64, h = 64;
    std::vector<uint8_t> pixels(w * h * 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) {
        std::fprintf(stderr, "probe_core: no core context\n");
        return 2;
    }
    GLuint program = glCreateProgram();
    glAttachShader(program, shader(GL_VERTEX_SHADER, R"(#version 330 core
layout(location = 0) in vec2 p;
out vec2 q;
void main() { q = p; gl_Position = vec4(p, 0.5, 1.0); })"));
    glAttachShader(program, shader(GL_FRAGMENT_SHADER, R"(#version 330 core
in vec2 q;
out vec4 c;
void main() { c = vec4(q * 0.5 + 0.5, 0.25, 1.0); })"));
    glLinkProgram(program);
    const float triangle[] = {-0.9f, -0.9f, 0.9f, -0.8f, 0.0f, 0.9f};
    GLuint vao = 0, vbo = 0;
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof triangle, triangle, GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    uint64_t sum = 0;
    for (int frame = 0; frame < 3; ++frame) {
        glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
        glEnable(GL_DEPTH_TEST);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glUseProgram(program);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glFinish();
        for (size_t i = 0; i < pixels.size(); ++i) sum = sum * 31 + pixels[i];
    }
    std::printf("core %s checksum %016llx error 0x%x\n",
                reinterpret_cast<const char*>(glGetString(GL_VERSION)),
                static_cast<unsigned long long>(sum), glGetError());
    OSMesaDestroyContext(ctx);
    return 0;
}
