// demo_arrays: a rippling lit surface and a twisting column recomputed on the CPU every frame,
// drawn from client vertex arrays, or from buffer objects with --vbo.

// Declares the GL 1.5 buffer functions; must precede every include that may pull in GL/gl.h.
#define GL_GLEXT_PROTOTYPES

#include "Demo.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <vector>

namespace {

constexpr float pi = std::numbers::pi_v<float>;
constexpr int gridSize = 64; // quads per side of the surface
constexpr int gridVertices = (gridSize + 1) * (gridSize + 1);
constexpr int columnSegments = 24;
constexpr int columnVertices = (4 * columnSegments + 1) * 6; // walls and a top cap
constexpr float surfaceHalf = 2.0f;

struct Vertex {
    float position[3];
    float normal[3];
    uint8_t colour[4];
};

class ArraysScene : public demo::Scene {
public:
    std::vector<demo::ExtraOption> extraOptions() const override
    {
        return {{"vbo", demo::ExtraOption::Kind::Flag, "draw from buffer objects"},
                {"list", demo::ExtraOption::Kind::Flag,
                 "compile the first frame's array draws (and their client state) into a "
                 "display list and call it"},
                {"shine", demo::ExtraOption::Kind::Flag,
                 "draw the column a second time, adding light (GL_ONE, GL_ONE) over the same "
                 "vertices, as multi-pass engines draw a surface's layers"}};
    }

    bool init(const demo::Options& options, std::string&) override
    {
        useVbo_ = options.has("vbo");
        useList_ = options.has("list");
        shine_ = options.has("shine");
        vertices_.resize(gridVertices + columnVertices);
        buildIndices();

        glViewport(0, 0, options.width, options.height);
        demo::setPerspective(40.0, static_cast<double>(options.width) / options.height, 1.0,
                             50.0);
        glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
        const float specular[] = {0.5f, 0.5f, 0.5f, 1.0f};
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);
        glShadeModel(GL_SMOOTH);

        if (useVbo_) {
            glGenBuffers(2, buffers_);
            glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
            glBufferData(GL_ARRAY_BUFFER, vertices_.size() * sizeof(Vertex), nullptr,
                         GL_STREAM_DRAW);
            // Both index lists share one element buffer: 32-bit triangles, then 16-bit strips.
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
            size_t triangleBytes = triangleIndices_.size() * sizeof(uint32_t);
            size_t stripBytes = stripIndices_.size() * sizeof(uint16_t);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, triangleBytes + stripBytes, nullptr,
                         GL_STATIC_DRAW);
            glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, triangleBytes, triangleIndices_.data());
            glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, triangleBytes, stripBytes,
                            stripIndices_.data());
        }
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        return true;
    }

    void draw(int frame) override
    {
        updateSurface(frame);
        updateColumn(frame);

        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        const float lightDirection[] = {0.3f, 1.0f, 0.6f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        glTranslatef(0.0f, -0.5f, -7.5f);
        glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(frame * 0.5f, 0.0f, 1.0f, 0.0f);

        // In VBO mode the pointers are offsets into the bound buffers.
        const char* base = reinterpret_cast<const char*>(vertices_.data());
        const char* indexBase = reinterpret_cast<const char*>(triangleIndices_.data());
        const char* stripBase = reinterpret_cast<const char*>(stripIndices_.data());
        if (useVbo_) {
            glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
            glBufferSubData(GL_ARRAY_BUFFER, 0, vertices_.size() * sizeof(Vertex),
                            vertices_.data());
            base = nullptr;
            indexBase = nullptr;
            stripBase = reinterpret_cast<const char*>(triangleIndices_.size() * sizeof(uint32_t));
        }
        glVertexPointer(3, GL_FLOAT, sizeof(Vertex), base + offsetof(Vertex, position));
        glNormalPointer(GL_FLOAT, sizeof(Vertex), base + offsetof(Vertex, normal));
        glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), base + offsetof(Vertex, colour));

        // With --list the draws are compiled once (the arrays' contents are copied into the
        // list) and the list is called every frame.
        if (useList_ && list_ != 0) {
            glCallList(list_);
            return;
        }
        if (useList_) {
            list_ = glGenLists(1);
            glDisableClientState(GL_VERTEX_ARRAY);
            glDisableClientState(GL_NORMAL_ARRAY);
            glDisableClientState(GL_COLOR_ARRAY);
            glNewList(list_, GL_COMPILE);
            // Client state inside the list, as programs do: GL runs it at once (it is never
            // compiled), so the draws below read these arrays while the list compiles.
            glEnableClientState(GL_VERTEX_ARRAY);
            glEnableClientState(GL_NORMAL_ARRAY);
            glEnableClientState(GL_COLOR_ARRAY);
            glVertexPointer(3, GL_FLOAT, sizeof(Vertex), base + offsetof(Vertex, position));
            glNormalPointer(GL_FLOAT, sizeof(Vertex), base + offsetof(Vertex, normal));
            glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), base + offsetof(Vertex, colour));
        }
        // Back half of the surface as indexed triangles, front half as one strip per row.
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(triangleIndices_.size()),
                       GL_UNSIGNED_INT, indexBase);
        const int stripLength = 2 * (gridSize + 1);
        for (int row = 0; row < gridSize / 2; ++row) {
            glDrawElements(GL_TRIANGLE_STRIP, stripLength, GL_UNSIGNED_SHORT,
                           stripBase + row * stripLength * sizeof(uint16_t));
        }
        glDrawArrays(GL_TRIANGLES, gridVertices, columnVertices);
        if (shine_ && !useList_) drawShine();
        if (useList_) {
            glEndList();
            glCallList(list_);
        }
    }

    void shutdown() override
    {
        if (list_ != 0) glDeleteLists(list_, 1);
        if (useVbo_) {
            glBindBuffer(GL_ARRAY_BUFFER, 0);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
            glDeleteBuffers(2, buffers_);
        }
    }

private:
    // The column's second pass: unlit added light, no depth writes, the same vertices.
    void drawShine()
    {
        demo::beginShinePass();
        glDisableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_TRIANGLES, gridVertices, columnVertices);
        glEnableClientState(GL_COLOR_ARRAY);
        demo::endShinePass();
    }

    static int gridIndex(int i, int j) { return j * (gridSize + 1) + i; }

    void buildIndices()
    {
        for (int j = 0; j < gridSize / 2; ++j) {
            for (int i = 0; i < gridSize; ++i) {
                uint32_t a = gridIndex(i, j);
                uint32_t b = gridIndex(i + 1, j);
                uint32_t c = gridIndex(i + 1, j + 1);
                uint32_t d = gridIndex(i, j + 1);
                triangleIndices_.insert(triangleIndices_.end(), {a, d, b, b, d, c});
            }
        }
        for (int j = gridSize / 2; j < gridSize; ++j) {
            for (int i = 0; i <= gridSize; ++i) {
                stripIndices_.push_back(static_cast<uint16_t>(gridIndex(i, j)));
                stripIndices_.push_back(static_cast<uint16_t>(gridIndex(i, j + 1)));
            }
        }
    }

    // Height field y = f(x, z): a radial ripple plus a slower travelling wave.
    void updateSurface(int frame)
    {
        float phase = frame * 0.2f;
        for (int j = 0; j <= gridSize; ++j) {
            for (int i = 0; i <= gridSize; ++i) {
                float x = surfaceHalf * (2.0f * i / gridSize - 1.0f);
                float z = surfaceHalf * (2.0f * j / gridSize - 1.0f);
                float r = std::sqrt(x * x + z * z) + 1e-4f;
                float y = 0.12f * std::sin(4.0f * r - phase)
                          + 0.08f * std::sin(1.5f * x + phase * 0.5f);
                float dydr = 0.48f * std::cos(4.0f * r - phase);
                float dydx = dydr * x / r + 0.12f * std::cos(1.5f * x + phase * 0.5f);
                float dydz = dydr * z / r;
                Vertex& v = vertices_[gridIndex(i, j)];
                v = {{x, y, z}, {-dydx, 1.0f, -dydz}, {0, 0, 0, 255}};
                normalize(v.normal);
                // A checker of two blues so the ripple reads clearly.
                bool odd = ((i / 8) + (j / 8)) % 2 != 0;
                v.colour[0] = odd ? 40 : 70;
                v.colour[1] = odd ? 110 : 160;
                v.colour[2] = odd ? 200 : 230;
            }
        }
    }

    // A square column whose twist swings back and forth, as flat-shaded triangles.
    void updateColumn(int frame)
    {
        const float half = 0.28f;
        const float height = 1.6f;
        float twist = 1.6f * std::sin(frame * 0.06f);
        auto corner = [&](int side, int segment, float* p) {
            float t = static_cast<float>(segment) / columnSegments;
            float angle = side * pi / 2.0f + pi / 4.0f + twist * t;
            p[0] = half * std::sqrt(2.0f) * std::cos(angle);
            p[1] = 0.1f + height * t;
            p[2] = half * std::sqrt(2.0f) * std::sin(angle);
        };
        Vertex* out = &vertices_[gridVertices];
        for (int side = 0; side < 4; ++side) {
            uint8_t shade = static_cast<uint8_t>(side % 2 == 0 ? 255 : 225);
            for (int segment = 0; segment < columnSegments; ++segment) {
                float p[4][3];
                corner(side, segment, p[0]);
                corner(side + 1, segment, p[1]);
                corner(side + 1, segment + 1, p[2]);
                corner(side, segment + 1, p[3]);
                const int order[6] = {0, 2, 1, 0, 3, 2};
                float n[3];
                faceNormal(p[0], p[2], p[1], n);
                for (int k : order) {
                    *out++ = {{p[k][0], p[k][1], p[k][2]}, {n[0], n[1], n[2]},
                              {shade, static_cast<uint8_t>(shade * 0.55f), 40, 255}};
                }
            }
        }
        float top[4][3];
        for (int side = 0; side < 4; ++side) {
            corner(side, columnSegments, top[side]);
        }
        for (int k : {0, 2, 1, 0, 3, 2}) {
            *out++ = {{top[k][0], top[k][1], top[k][2]}, {0.0f, 1.0f, 0.0f}, {240, 200, 60, 255}};
        }
    }

    static void normalize(float* v)
    {
        float length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        for (int k = 0; k < 3; ++k) {
            v[k] /= length;
        }
    }

    static void faceNormal(const float* a, const float* b, const float* c, float* n)
    {
        float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        float v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        n[0] = u[1] * v[2] - u[2] * v[1];
        n[1] = u[2] * v[0] - u[0] * v[2];
        n[2] = u[0] * v[1] - u[1] * v[0];
        normalize(n);
    }

    bool useList_ = false;
    bool shine_ = false;
    GLuint list_ = 0;
    bool useVbo_ = false;
    GLuint buffers_[2] = {0, 0};
    std::vector<Vertex> vertices_;
    std::vector<uint32_t> triangleIndices_;
    std::vector<uint16_t> stripIndices_;
};

} // namespace

int main(int argc, char** argv)
{
    ArraysScene scene;
    return demo::run(argc, argv, "arrays", scene);
}
