// A program that draws from ARB vertex and element buffers fetched through
// OSMesaGetProcAddress (as SDL games do), in a lit 3D scene: a cube from
// glInterleavedArrays(GL_T2F_V3F, 0, NULL) and a ring from glDrawElements with an ARB element
// buffer, textured from an ARB pixel-unpack buffer (glTexImage2D, glCompressedTexImage2DARB
// at offsets into it). Prints a checksum of its last frame and how many pixels the objects cover.
//   --vao        the ring comes from a vertex array object (GL 3.0, which nprgl does not
//                follow) while the default one points at client memory since unmapped
//   --restart    the ring comes from client arrays, its triangles separated by a primitive
//                restart index (GL 3.1), which is no vertex: nothing may read it as one
//   --map        the ring's vertices are written through glMapBufferRange with explicit
//                flushes, its indices through a mapped range flushed by the unmap (GL 3.0)
//   --program    the ring is coloured by an ARB fragment program (ARB_fragment_program: its
//                text, a local and an env parameter)
//   --empty      draws nothing (the background alone)
//   --save FILE  writes the last frame's RGBA bytes
#include "tests/probes/CubeFaces.h"

#include <GL/osmesa.h>
#include <GL/glext.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <sys/mman.h>
#include <vector>

namespace {

PFNGLGENBUFFERSARBPROC genBuffers;
PFNGLBINDBUFFERARBPROC bindBuffer;
PFNGLBUFFERDATAARBPROC bufferData;
using InterleavedArrays = void(APIENTRY*)(GLenum, GLsizei, const void*);
InterleavedArrays interleavedArrays;
PFNGLCOMPRESSEDTEXIMAGE2DARBPROC compressedTexImage2D;
PFNGLGENVERTEXARRAYSPROC genVertexArrays;
PFNGLBINDVERTEXARRAYPROC bindVertexArray;
PFNGLPRIMITIVERESTARTINDEXPROC primitiveRestartIndex;
PFNGLMAPBUFFERRANGEPROC mapBufferRange;
PFNGLFLUSHMAPPEDBUFFERRANGEPROC flushMappedBufferRange;
PFNGLUNMAPBUFFERARBPROC unmapBuffer;
PFNGLGENPROGRAMSARBPROC genPrograms;
PFNGLBINDPROGRAMARBPROC bindProgram;
PFNGLPROGRAMSTRINGARBPROC programString;
PFNGLPROGRAMLOCALPARAMETER4FARBPROC programLocal4f;
PFNGLPROGRAMENVPARAMETER4FVARBPROC programEnv4fv;

template <typename T> bool fetch(T& fn, const char* name)
{
    fn = reinterpret_cast<T>(OSMesaGetProcAddress(name));
    if (!fn) std::fprintf(stderr, "probe_arb_vbo: no %s\n", name);
    return fn != nullptr;
}

// A cube as triangles, each vertex (s, t, x, y, z) for GL_T2F_V3F.
std::vector<float> cube()
{
    const auto& kFaces = nprgl::probes::kCubeFaces;
    static const int kCorners[6] = {0, 1, 2, 0, 2, 3};
    std::vector<float> out;
    for (const auto& face : kFaces) {
        for (int c : kCorners) {
            out.insert(out.end(), {float(c == 1 || c == 2), float(c >= 2)});
            for (int k = 0; k < 3; ++k)
                out.push_back(0.5f * float(face[c][k]));
        }
    }
    return out;
}

// A torus: interleaved normal and position per vertex, and triangle indices.
void torus(std::vector<float>& vertices, std::vector<GLushort>& indices)
{
    const int rings = 24, sides = 12;
    const float big = 0.6f, small = 0.2f;
    for (int i = 0; i <= rings; ++i) {
        const float u = 6.2831853f * float(i) / rings;
        for (int j = 0; j <= sides; ++j) {
            const float v = 6.2831853f * float(j) / sides;
            const float nx = std::cos(u) * std::cos(v), ny = std::sin(u) * std::cos(v),
                        nz = std::sin(v);
            vertices.insert(vertices.end(),
                            {nx, ny, nz, std::cos(u) * (big + small * std::cos(v)),
                             std::sin(u) * (big + small * std::cos(v)), small * nz});
        }
    }
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            const GLushort a = GLushort(i * (sides + 1) + j), b = GLushort(a + sides + 1);
            indices.insert(indices.end(),
                           {a, b, GLushort(a + 1), GLushort(a + 1), b, GLushort(b + 1)});
        }
    }
}

} // namespace

int main(int argc, char** argv)
{
    bool vao = false, empty = false, restart = false, map = false, program = false;
    const char* save = nullptr;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--vao") == 0) vao = true;
        if (std::strcmp(argv[i], "--empty") == 0) empty = true;
        if (std::strcmp(argv[i], "--restart") == 0) restart = true;
        if (std::strcmp(argv[i], "--map") == 0) map = true;
        if (std::strcmp(argv[i], "--program") == 0) program = true;
        if (std::strcmp(argv[i], "--save") == 0 && i + 1 < argc) save = argv[++i];
    }
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    const int w = 128, h = 128;
    std::vector<uint8_t> pixels(w * h * 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, w, h)) {
        std::fprintf(stderr, "probe_arb_vbo: no context\n");
        return 2;
    }
    if (!fetch(genBuffers, "glGenBuffersARB") || !fetch(bindBuffer, "glBindBufferARB") ||
        !fetch(bufferData, "glBufferDataARB") || !fetch(interleavedArrays, "glInterleavedArrays") ||
        !fetch(compressedTexImage2D, "glCompressedTexImage2DARB")) {
        return 2;
    }
    if (vao && (!fetch(genVertexArrays, "glGenVertexArrays") ||
                !fetch(bindVertexArray, "glBindVertexArray"))) {
        return 2;
    }
    if (restart && !fetch(primitiveRestartIndex, "glPrimitiveRestartIndex")) return 2;
    if (map && (!fetch(mapBufferRange, "glMapBufferRange") ||
                !fetch(flushMappedBufferRange, "glFlushMappedBufferRange") ||
                !fetch(unmapBuffer, "glUnmapBufferARB"))) {
        return 2;
    }
    if (program && (!fetch(genPrograms, "glGenProgramsARB") ||
                    !fetch(bindProgram, "glBindProgramARB") ||
                    !fetch(programString, "glProgramStringARB") ||
                    !fetch(programLocal4f, "glProgramLocalParameter4fARB") ||
                    !fetch(programEnv4fv, "glProgramEnvParameter4fvARB"))) {
        return 2;
    }
    GLuint fragmentProgram = 0;
    if (program) {
        // The lit colour times a local parameter, plus an env parameter.
        static const char kText[] = "!!ARBfp1.0\n"
                                    "TEMP c;\n"
                                    "MUL c, fragment.color, program.local[0];\n"
                                    "ADD result.color, c, program.env[1];\n"
                                    "END\n";
        genPrograms(1, &fragmentProgram);
        bindProgram(GL_FRAGMENT_PROGRAM_ARB, fragmentProgram);
        programString(GL_FRAGMENT_PROGRAM_ARB, GL_PROGRAM_FORMAT_ASCII_ARB,
                      GLsizei(sizeof kText - 1), kText);
        programLocal4f(GL_FRAGMENT_PROGRAM_ARB, 0, 1.0f, 0.3f, 0.2f, 1.0f);
        const GLfloat env[4] = {0.1f, 0.1f, 0.4f, 0.0f};
        programEnv4fv(GL_FRAGMENT_PROGRAM_ARB, 1, env);
        bindProgram(GL_FRAGMENT_PROGRAM_ARB, 0);
    }
    const std::vector<float> box = cube();
    std::vector<float> ring;
    std::vector<GLushort> ringIndices;
    torus(ring, ringIndices);
    const GLushort kRestart = 0xFFFF;
    std::vector<GLushort> restartIndices;
    for (size_t i = 0; i < ringIndices.size(); ++i) {
        if (i > 0 && i % 3 == 0) restartIndices.push_back(kRestart);
        restartIndices.push_back(ringIndices[i]);
    }
    GLuint buffers[4] = {};
    genBuffers(4, buffers);
    bindBuffer(GL_ARRAY_BUFFER_ARB, buffers[0]);
    bufferData(GL_ARRAY_BUFFER_ARB, GLsizeiptr(box.size() * sizeof(float)), box.data(),
               GL_STATIC_DRAW_ARB);
    const GLsizeiptr ringBytes = GLsizeiptr(ring.size() * sizeof(float));
    const GLsizeiptr indexBytes = GLsizeiptr(ringIndices.size() * sizeof(GLushort));
    bindBuffer(GL_ARRAY_BUFFER_ARB, buffers[1]);
    bufferData(GL_ARRAY_BUFFER_ARB, ringBytes, map ? nullptr : ring.data(), GL_STATIC_DRAW_ARB);
    bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, buffers[2]);
    bufferData(GL_ELEMENT_ARRAY_BUFFER_ARB, indexBytes, map ? nullptr : ringIndices.data(),
               GL_STATIC_DRAW_ARB);
    if (map) {
        // Vertices: a range from byte 16 on, written whole, flushed in two pieces; the first
        // 16 bytes through a second mapping that the unmap flushes.
        const GLsizeiptr rest = ringBytes - 16, half = rest / 2;
        auto* v = static_cast<uint8_t*>(mapBufferRange(
            GL_ARRAY_BUFFER, 16, rest, GL_MAP_WRITE_BIT | GL_MAP_FLUSH_EXPLICIT_BIT));
        std::memcpy(v, reinterpret_cast<const uint8_t*>(ring.data()) + 16, size_t(rest));
        flushMappedBufferRange(GL_ARRAY_BUFFER, 0, half);
        flushMappedBufferRange(GL_ARRAY_BUFFER, half, rest - half);
        unmapBuffer(GL_ARRAY_BUFFER);
        void* head = mapBufferRange(GL_ARRAY_BUFFER, 0, 16, GL_MAP_WRITE_BIT);
        std::memcpy(head, ring.data(), 16);
        unmapBuffer(GL_ARRAY_BUFFER);
        void* ix = mapBufferRange(GL_ELEMENT_ARRAY_BUFFER, 0, indexBytes,
                                  GL_MAP_WRITE_BIT | GL_MAP_INVALIDATE_BUFFER_BIT);
        std::memcpy(ix, ringIndices.data(), size_t(indexBytes));
        unmapBuffer(GL_ELEMENT_ARRAY_BUFFER);
    }
    bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, 0);
    bindBuffer(GL_ARRAY_BUFFER_ARB, 0);
    // Textures from a pixel-unpack buffer: an 8x8 checker at offset 64, one DXT1 block at 512.
    std::vector<uint8_t> texels(520, 0);
    for (int i = 0; i < 64; ++i) {
        const uint8_t v = ((i % 8) / 2 + (i / 16)) % 2 ? 255 : 120;
        for (int c = 0; c < 4; ++c)
            texels[64 + i * 4 + c] = c == 3 ? 255 : v;
    }
    texels[512] = 0xFF; // colour 0 white, colour 1 black, every texel colour 0
    texels[513] = 0xFF;
    bindBuffer(GL_PIXEL_UNPACK_BUFFER_ARB, buffers[3]);
    bufferData(GL_PIXEL_UNPACK_BUFFER_ARB, GLsizeiptr(texels.size()), texels.data(),
               GL_STATIC_DRAW_ARB);
    GLuint textures[2] = {};
    glGenTextures(2, textures);
    glBindTexture(GL_TEXTURE_2D, textures[1]);
    compressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, 4, 4, 0, 8,
                         reinterpret_cast<const void*>(512));
    glBindTexture(GL_TEXTURE_2D, textures[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 reinterpret_cast<const void*>(64));
    bindBuffer(GL_PIXEL_UNPACK_BUFFER_ARB, 0);

    GLuint ringArrays = 0;
    if (vao) {
        // The ring's arrays and indices live in a vertex array object...
        genVertexArrays(1, &ringArrays);
        bindVertexArray(ringArrays);
        bindBuffer(GL_ARRAY_BUFFER_ARB, buffers[1]);
        glNormalPointer(GL_FLOAT, 6 * sizeof(float), reinterpret_cast<const void*>(0));
        glVertexPointer(3, GL_FLOAT, 6 * sizeof(float),
                        reinterpret_cast<const void*>(3 * sizeof(float)));
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnableClientState(GL_VERTEX_ARRAY);
        bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, buffers[2]);
        bindVertexArray(0);
        bindBuffer(GL_ARRAY_BUFFER_ARB, 0);
        // ...while the default one is left pointing at client memory that is then unmapped
        // (legal: it is never drawn from again).
        const size_t page = 4096;
        void* gone =
            mmap(nullptr, page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        glVertexPointer(3, GL_FLOAT, 0, gone);
        glNormalPointer(GL_FLOAT, 0, gone);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        munmap(gone, page);
    }

    const GLfloat light[] = {0.4f, 0.6f, 1.0f, 0.0f};
    const uint8_t clear[4] = {26, 51, 77, 255};
    uint64_t sum = 0;
    int covered = 0;
    for (int frame = 0; frame < 3; ++frame) {
        glViewport(0, 0, w, h);
        glClearColor(clear[0] / 255.0f, clear[1] / 255.0f, clear[2] / 255.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_NORMALIZE);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 10.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glLightfv(GL_LIGHT0, GL_POSITION, light);
        glTranslatef(0.0f, 0.0f, -3.5f);
        glRotatef(25.0f + 10.0f * float(frame), 1.0f, 1.0f, 0.0f);

        if (empty) {
            glFinish();
            continue;
        }
        // The torus: normals and positions from an ARB buffer, indices from another.
        glPushMatrix();
        glTranslatef(0.55f, 0.0f, 0.0f);
        if (restart) {
            glNormalPointer(GL_FLOAT, 6 * sizeof(float), ring.data());
            glVertexPointer(3, GL_FLOAT, 6 * sizeof(float), ring.data() + 3);
            glEnableClientState(GL_NORMAL_ARRAY);
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnable(GL_PRIMITIVE_RESTART);
            primitiveRestartIndex(kRestart);
            glDrawElements(GL_TRIANGLES, GLsizei(restartIndices.size()), GL_UNSIGNED_SHORT,
                           restartIndices.data());
            glDisable(GL_PRIMITIVE_RESTART);
            glDisableClientState(GL_NORMAL_ARRAY);
            glDisableClientState(GL_VERTEX_ARRAY);
        } else if (vao) {
            bindVertexArray(ringArrays);
            glDrawElements(GL_TRIANGLES, GLsizei(ringIndices.size()), GL_UNSIGNED_SHORT, nullptr);
            bindVertexArray(0);
        } else {
            if (program) {
                bindProgram(GL_FRAGMENT_PROGRAM_ARB, fragmentProgram);
                glEnable(GL_FRAGMENT_PROGRAM_ARB);
            }
            bindBuffer(GL_ARRAY_BUFFER_ARB, buffers[1]);
            glNormalPointer(GL_FLOAT, 6 * sizeof(float), reinterpret_cast<const void*>(0));
            glVertexPointer(3, GL_FLOAT, 6 * sizeof(float),
                            reinterpret_cast<const void*>(3 * sizeof(float)));
            glEnableClientState(GL_NORMAL_ARRAY);
            glEnableClientState(GL_VERTEX_ARRAY);
            bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, buffers[2]);
            glDrawElements(GL_TRIANGLES, GLsizei(ringIndices.size()), GL_UNSIGNED_SHORT, nullptr);
            glDisableClientState(GL_NORMAL_ARRAY);
            glDisableClientState(GL_VERTEX_ARRAY);
            bindBuffer(GL_ELEMENT_ARRAY_BUFFER_ARB, 0);
            bindBuffer(GL_ARRAY_BUFFER_ARB, 0);
            if (program) glDisable(GL_FRAGMENT_PROGRAM_ARB);
        }
        glPopMatrix();
        // The cube: vertex and texcoord arrays at offsets 8 and 0 of an ARB buffer.
        glPushMatrix();
        glTranslatef(-0.55f, 0.0f, 0.0f);
        glNormal3f(0.3f, 0.5f, 0.8f);
        bindBuffer(GL_ARRAY_BUFFER_ARB, buffers[0]);
        interleavedArrays(GL_T2F_V3F, 0, nullptr);
        glEnable(GL_TEXTURE_2D);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(box.size() / 5));
        glDisable(GL_TEXTURE_2D);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glPopMatrix();
        glFinish();
    }
    for (size_t i = 0; i < pixels.size(); i += 4) {
        for (int c = 0; c < 4; ++c)
            sum = sum * 31 + pixels[i + c];
        covered += pixels[i] != clear[0] || pixels[i + 1] != clear[1] || pixels[i + 2] != clear[2];
    }
    if (save) {
        if (FILE* f = std::fopen(save, "wb")) {
            std::fwrite(pixels.data(), 1, pixels.size(), f);
            std::fclose(f);
        }
    }
    std::printf("arb_vbo checksum %016llx covered %d error 0x%x\n",
                static_cast<unsigned long long>(sum), covered, glGetError());
    OSMesaDestroyContext(ctx);
    return 0;
}
