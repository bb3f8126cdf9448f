// demo_immediate: lit shapes re-sent with glBegin/glEnd every frame, in many primitive modes.

#include "Demo.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace {

constexpr float pi = std::numbers::pi_v<float>;

// One glBegin/glEnd block. Vertices are computed once so frames measure GL calls, not trig.
struct Batch {
    explicit Batch(GLenum batchMode, bool withColour = false)
        : mode(batchMode), coloured(withColour)
    {
    }

    GLenum mode;
    bool coloured;
    std::vector<float> data; // per vertex: [r g b] nx ny nz x y z

    void add(const float* normal, float x, float y, float z)
    {
        data.insert(data.end(), {normal[0], normal[1], normal[2], x, y, z});
    }
    void add(float nx, float ny, float nz, float x, float y, float z)
    {
        data.insert(data.end(), {nx, ny, nz, x, y, z});
    }
    size_t vertexCount() const { return data.size() / (coloured ? 9 : 6); }
};

struct Shape {
    float diffuse[4];
    float position[3];
    float spinAxis[3];
    std::vector<Batch> batches;
};

class ImmediateScene : public demo::Scene {
public:
    std::vector<demo::ExtraOption> extraOptions() const override
    {
        return {{"detail", demo::ExtraOption::Kind::Int,
                 "tessellation factor; vertices per frame grow linearly (default 1)", 1, 2000},
                {"shine", demo::ExtraOption::Kind::Flag,
                 "draw the first shape a second time, adding light (GL_ONE, GL_ONE) over the "
                 "same vertices, as multi-pass programs draw a surface's layers"},
                {"frame", demo::ExtraOption::Kind::Flag,
                 "a flat 2D band around the window's edge, drawn after the clear, and a "
                 "scissored clear of a corner in another colour: the border shows no clear "
                 "colour, and not every clear is the background"},
                {"light1", demo::ExtraOption::Kind::Text,
                 "a second white light as bright as the first, from the lower right: "
                 "'directional', 'spot' (positional, aimed at the shapes) or 'spot-away' (the "
                 "same, aimed away from them)"}};
    }

    bool init(const demo::Options& options, std::string& error) override
    {
        width_ = options.width;
        height_ = options.height;
        report_ = options.report;
        scale_ = std::sqrt(static_cast<float>(options.intValue("detail", 1)));
        shine_ = options.has("shine");
        frame_ = options.has("frame");
        light1_ = options.textValue("light1", "");
        if (!light1_.empty() && light1_ != "directional" && light1_ != "spot" &&
            light1_ != "spot-away") {
            error = "--light1: directional, spot or spot-away";
            return false;
        }
        buildShapes();

        glViewport(0, 0, width_, height_);
        demo::setPerspective(45.0, static_cast<double>(width_) / height_, 1.0, 100.0);
        glClearColor(0.10f, 0.12f, 0.16f, 1.0f);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_NORMALIZE);
        glShadeModel(GL_SMOOTH);
        const float ambient[] = {0.18f, 0.18f, 0.2f, 1.0f};
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
        const float white[] = {1.0f, 1.0f, 1.0f, 1.0f};
        glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
        glLightfv(GL_LIGHT0, GL_SPECULAR, white);
        glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
        return true;
    }

    void draw(int frame) override
    {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        if (frame_) drawFrame();
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        // Light fixed in eye space, above-left of the viewer.
        const float lightDirection[] = {-0.4f, 0.6f, 1.0f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        if (!light1_.empty()) placeLight1();

        glTranslatef(0.0f, 0.0f, -10.0f);
        glRotatef(15.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(frame * 0.5f, 0.0f, 1.0f, 0.0f);

        size_t vertices = 0;
        const float specular[] = {0.6f, 0.6f, 0.6f, 1.0f};
        for (const Shape& shape : shapes_) {
            glPushMatrix();
            glTranslatef(shape.position[0], shape.position[1], shape.position[2]);
            glRotatef(frame * 2.0f, shape.spinAxis[0], shape.spinAxis[1], shape.spinAxis[2]);
            glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, shape.diffuse);
            glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
            glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40.0f);
            for (const Batch& batch : shape.batches) {
                vertices += drawBatch(batch);
            }
            if (shine_ && &shape == &shapes_.front()) drawShine(shape);
            glPopMatrix();
        }
        if (report_ && frame == 1) {
            std::fprintf(stderr, "demo_immediate: vertices_per_frame=%zu\n", vertices);
        }
    }

private:
    // GL_LIGHT1, fixed in eye space at the lower right (as bright as GL_LIGHT0): a far light,
    // or a spot with a 30-degree cone, aimed at the shapes or away from them.
    void placeLight1() const
    {
        const float white[] = {1.0f, 1.0f, 1.0f, 1.0f};
        glLightfv(GL_LIGHT1, GL_DIFFUSE, white);
        if (light1_ == "directional") {
            const float direction[] = {0.9f, -0.5f, 0.3f, 0.0f};
            glLightfv(GL_LIGHT1, GL_POSITION, direction);
            glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f);
        } else {
            const float position[] = {9.0f, -5.0f, -7.0f, 1.0f};
            glLightfv(GL_LIGHT1, GL_POSITION, position);
            const float towards[] = {-9.0f, 5.0f, -3.0f};
            const float away[] = {9.0f, -5.0f, 3.0f};
            glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, light1_ == "spot" ? towards : away);
            glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 30.0f);
            glLightf(GL_LIGHT1, GL_SPOT_EXPONENT, 2.0f);
        }
        glEnable(GL_LIGHT1);
    }

    // A band a tenth of the window wide around its edge, unlit, in window coordinates, and a
    // corner inside it cleared through a scissor.
    void drawFrame() const
    {
        glClearColor(0.85f, 0.85f, 0.2f, 1.0f);
        glScissor(width_ / 5, height_ / 5, width_ / 8, height_ / 8);
        glEnable(GL_SCISSOR_TEST);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.10f, 0.12f, 0.16f, 1.0f);
        glPushAttrib(GL_ENABLE_BIT);
        glDisable(GL_LIGHTING);
        glDisable(GL_DEPTH_TEST);
        demo::pushPixelProjection(width_, height_);
        const float w = float(width_), h = float(height_), b = 0.1f * std::min(w, h);
        glColor3f(0.55f, 0.35f, 0.2f);
        glBegin(GL_QUADS);
        const float bands[4][4] = {{0, 0, w, b}, {0, h - b, w, h}, {0, b, b, h - b},
                                   {w - b, b, w, h - b}};
        for (const auto& r : bands) {
            glVertex2f(r[0], r[1]);
            glVertex2f(r[2], r[1]);
            glVertex2f(r[2], r[3]);
            glVertex2f(r[0], r[3]);
        }
        glEnd();
        demo::popMatrices();
        glPopAttrib();
    }

    // The shape's second pass: unlit added light, no depth writes, the same vertices.
    static void drawShine(const Shape& shape)
    {
        demo::beginShinePass();
        for (const Batch& batch : shape.batches) drawBatch(batch);
        demo::endShinePass();
    }

    static size_t drawBatch(const Batch& batch)
    {
        if (batch.coloured) {
            glEnable(GL_COLOR_MATERIAL);
        }
        glBegin(batch.mode);
        const float* v = batch.data.data();
        const float* end = v + batch.data.size();
        while (v < end) {
            if (batch.coloured) {
                glColor3f(v[0], v[1], v[2]);
                v += 3;
            }
            glNormal3f(v[0], v[1], v[2]);
            glVertex3f(v[3], v[4], v[5]);
            v += 6;
        }
        glEnd();
        if (batch.coloured) {
            glDisable(GL_COLOR_MATERIAL);
        }
        return batch.vertexCount();
    }

    int tess(int base) const
    {
        return std::max(base, static_cast<int>(std::lround(base * scale_)));
    }

    void buildShapes()
    {
        shapes_.clear();
        shapes_.push_back({{0.95f, 0.65f, 0.15f, 1.0f}, {-2.6f, 1.3f, 0.0f}, {1, 1, 0}, torus()});
        shapes_.push_back({{0.2f, 0.45f, 0.95f, 1.0f}, {0.0f, 1.3f, 0.0f}, {0, 1, 0}, sphere()});
        shapes_.push_back({{0.3f, 0.85f, 0.3f, 1.0f}, {2.6f, 1.3f, 0.0f}, {1, 0, 1}, cone()});
        shapes_.push_back({{0.9f, 0.25f, 0.35f, 1.0f}, {-2.6f, -1.3f, 0.0f}, {0, 1, 1}, prism()});
        shapes_.push_back({{0.2f, 0.8f, 0.8f, 1.0f}, {0.0f, -1.3f, 0.0f}, {1, 1, 1}, cube()});
        shapes_.push_back({{1.0f, 1.0f, 1.0f, 1.0f}, {2.6f, -1.3f, 0.0f}, {1, 0, 0},
                           octahedron()});
    }

    std::vector<Batch> torus() const
    {
        const float major = 0.7f;
        const float minor = 0.3f;
        int rings = tess(32);
        int sides = tess(16);
        std::vector<Batch> batches;
        for (int i = 0; i < rings; ++i) {
            Batch strip{GL_QUAD_STRIP};
            for (int j = 0; j <= sides; ++j) {
                float v = 2.0f * pi * j / sides;
                for (int k = 1; k >= 0; --k) {
                    float u = 2.0f * pi * (i + k) / rings;
                    float n[3] = {std::cos(u) * std::cos(v), std::sin(u) * std::cos(v),
                                  std::sin(v)};
                    float r = major + minor * std::cos(v);
                    strip.add(n, r * std::cos(u), r * std::sin(u), minor * std::sin(v));
                }
            }
            batches.push_back(std::move(strip));
        }
        return batches;
    }

    std::vector<Batch> sphere() const
    {
        const float radius = 0.9f;
        int stacks = tess(20);
        int slices = tess(32);
        std::vector<Batch> batches;
        for (int i = 0; i < stacks; ++i) {
            Batch strip{GL_TRIANGLE_STRIP};
            for (int j = 0; j <= slices; ++j) {
                float lon = 2.0f * pi * j / slices;
                for (int k = 0; k <= 1; ++k) {
                    float lat = pi * (i + k) / stacks - pi / 2.0f;
                    float n[3] = {std::cos(lat) * std::cos(lon), std::sin(lat),
                                  -std::cos(lat) * std::sin(lon)};
                    strip.add(n, radius * n[0], radius * n[1], radius * n[2]);
                }
            }
            batches.push_back(std::move(strip));
        }
        return batches;
    }

    // Side made of strips with a GL_TRIANGLE_FAN at the tip; the base is another fan.
    std::vector<Batch> cone() const
    {
        const float radius = 0.75f;
        const float height = 1.5f;
        int slices = tess(32);
        int stacks = tess(6);
        float slopeLength = std::hypot(radius, height);
        auto sideNormal = [&](float angle, float* n) {
            n[0] = height / slopeLength * std::cos(angle);
            n[1] = radius / slopeLength;
            n[2] = -height / slopeLength * std::sin(angle);
        };
        auto sidePoint = [&](Batch& batch, float angle, float t) {
            float n[3];
            sideNormal(angle, n);
            float r = radius * (1.0f - t);
            batch.add(n, r * std::cos(angle), -height / 2 + height * t, -r * std::sin(angle));
        };
        std::vector<Batch> batches;
        for (int i = 0; i + 1 < stacks; ++i) {
            Batch strip{GL_TRIANGLE_STRIP};
            // Upper ring first: the strip's triangles then wind outwards, like the fans.
            for (int j = 0; j <= slices; ++j) {
                float angle = 2.0f * pi * j / slices;
                sidePoint(strip, angle, static_cast<float>(i + 1) / stacks);
                sidePoint(strip, angle, static_cast<float>(i) / stacks);
            }
            batches.push_back(std::move(strip));
        }
        Batch tip{GL_TRIANGLE_FAN};
        tip.add(0.0f, 1.0f, 0.0f, 0.0f, height / 2, 0.0f);
        for (int j = 0; j <= slices; ++j) {
            sidePoint(tip, 2.0f * pi * j / slices, static_cast<float>(stacks - 1) / stacks);
        }
        batches.push_back(std::move(tip));
        Batch base{GL_TRIANGLE_FAN};
        base.add(0.0f, -1.0f, 0.0f, 0.0f, -height / 2, 0.0f);
        for (int j = slices; j >= 0; --j) {
            float angle = 2.0f * pi * j / slices;
            base.add(0.0f, -1.0f, 0.0f, radius * std::cos(angle), -height / 2,
                     -radius * std::sin(angle));
        }
        batches.push_back(std::move(base));
        return batches;
    }

    // Hexagonal prism: GL_QUADS walls, GL_POLYGON caps.
    std::vector<Batch> prism() const
    {
        const int sides = 6;
        const float radius = 0.75f;
        const float height = 1.3f;
        int rows = tess(4);
        // Walls are split across their height only: the caps meet them at the corners alone,
        // so the prism is watertight (no T-junction).
        const int columns = 1;
        auto corner = [&](int i, float* p) {
            float angle = 2.0f * pi * i / sides;
            p[0] = radius * std::cos(angle);
            p[1] = -radius * std::sin(angle);
        };
        Batch walls{GL_QUADS};
        for (int i = 0; i < sides; ++i) {
            float a[2];
            float b[2];
            corner(i, a);
            corner(i + 1, b);
            float mid = 2.0f * pi * (i + 0.5f) / sides;
            float n[3] = {std::cos(mid), 0.0f, -std::sin(mid)};
            auto at = [&](int column, int row) {
                float s = static_cast<float>(column) / columns;
                float y = -height / 2 + height * row / rows;
                walls.add(n, a[0] + (b[0] - a[0]) * s, y, a[1] + (b[1] - a[1]) * s);
            };
            for (int row = 0; row < rows; ++row) {
                for (int column = 0; column < columns; ++column) {
                    at(column, row);
                    at(column + 1, row);
                    at(column + 1, row + 1);
                    at(column, row + 1);
                }
            }
        }
        Batch top{GL_POLYGON};
        Batch bottom{GL_POLYGON};
        for (int i = 0; i < sides; ++i) {
            float p[2];
            corner(i, p);
            top.add(0.0f, 1.0f, 0.0f, p[0], height / 2, p[1]);
            corner(sides - i, p);
            bottom.add(0.0f, -1.0f, 0.0f, p[0], -height / 2, p[1]);
        }
        std::vector<Batch> batches;
        batches.push_back(std::move(walls));
        batches.push_back(std::move(top));
        batches.push_back(std::move(bottom));
        return batches;
    }

    std::vector<Batch> cube() const
    {
        const float half = 0.65f;
        int n = tess(4);
        // Each face: normal, then the two in-face axes (their cross product is the normal).
        const float faces[6][3][3] = {
            {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
            {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
            {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
        };
        Batch quads{GL_QUADS};
        for (const auto& face : faces) {
            auto at = [&](int i, int j) {
                float s = (2.0f * i / n - 1.0f) * half;
                float t = (2.0f * j / n - 1.0f) * half;
                quads.add(face[0], face[0][0] * half + face[1][0] * s + face[2][0] * t,
                          face[0][1] * half + face[1][1] * s + face[2][1] * t,
                          face[0][2] * half + face[1][2] * s + face[2][2] * t);
            };
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) {
                    at(i, j);
                    at(i + 1, j);
                    at(i + 1, j + 1);
                    at(i, j + 1);
                }
            }
        }
        return {std::move(quads)};
    }

    // Flat-shaded octahedron of GL_TRIANGLES, coloured per vertex through GL_COLOR_MATERIAL.
    std::vector<Batch> octahedron() const
    {
        const float radius = 0.95f;
        int n = tess(4);
        Batch triangles{GL_TRIANGLES, true};
        for (int face = 0; face < 8; ++face) {
            float sx = (face & 1) ? -1.0f : 1.0f;
            float sy = (face & 2) ? -1.0f : 1.0f;
            float sz = (face & 4) ? -1.0f : 1.0f;
            float corners[3][3] = {{sx * radius, 0, 0}, {0, sy * radius, 0}, {0, 0, sz * radius}};
            // Keep the winding counter-clockwise seen from outside.
            if (sx * sy * sz < 0) {
                std::swap(corners[1], corners[2]);
            }
            float normal[3] = {sx, sy, sz};
            // Barycentric grid point (i, j) of the face, coloured by its weights.
            auto at = [&](int i, int j) {
                float w[3] = {static_cast<float>(i) / n, static_cast<float>(j) / n, 0.0f};
                w[2] = 1.0f - w[0] - w[1];
                float p[3];
                for (int c = 0; c < 3; ++c) {
                    p[c] = corners[0][c] * w[0] + corners[1][c] * w[1] + corners[2][c] * w[2];
                }
                triangles.data.insert(triangles.data.end(),
                                      {0.25f + 0.75f * w[0], 0.25f + 0.75f * w[1],
                                       0.25f + 0.75f * w[2], normal[0], normal[1], normal[2],
                                       p[0], p[1], p[2]});
            };
            for (int i = 0; i < n; ++i) {
                for (int j = 0; i + j < n; ++j) {
                    at(i, j);
                    at(i + 1, j);
                    at(i, j + 1);
                    if (i + j + 2 <= n) {
                        at(i + 1, j);
                        at(i + 1, j + 1);
                        at(i, j + 1);
                    }
                }
            }
        }
        return {std::move(triangles)};
    }

    int width_ = 0;
    int height_ = 0;
    bool report_ = false;
    float scale_ = 1.0f;
    bool shine_ = false;
    bool frame_ = false;
    std::string light1_;
    std::vector<Shape> shapes_;
};

} // namespace

int main(int argc, char** argv)
{
    ImmediateScene scene;
    return demo::run(argc, argv, "immediate", scene);
}
