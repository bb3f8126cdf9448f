// demo_dlopen: links neither libGL nor libOSMesa; loads them at run time like SDL does and
// draws a lit, spinning cube and an orbiting ball through the resolved pointers.

#include "FrameLoop.h"
#include "GlLoader.h"
#include "Options.h"
#include "Scene.h"

#include <cmath>
#include <cstdio>
#include <numbers>

namespace {

constexpr float pi = std::numbers::pi_v<float>;

class DlopenScene : public demo::Scene {
public:
    std::vector<demo::ExtraOption> extraOptions() const override
    {
        return {{"lib", demo::ExtraOption::Kind::Text,
                 "library to dlopen (default libGL.so.1, or libOSMesa.so.8 with --offscreen)"},
                {"print-resolved", demo::ExtraOption::Kind::Flag,
                 "print to stderr which shared object glClear and glVertex3f come from"}};
    }

    void setFunctions(const demo::DrawFunctions& gl) { gl_ = gl; }

    bool init(const demo::Options& options, std::string&) override
    {
        gl_.viewport(0, 0, options.width, options.height);
        gl_.matrixMode(GL_PROJECTION);
        gl_.loadIdentity();
        // 45 degree vertical field of view, near plane at 1.
        double top = std::tan(pi / 8.0);
        double right = top * options.width / options.height;
        gl_.frustum(-right, right, -top, top, 1.0, 50.0);
        gl_.matrixMode(GL_MODELVIEW);
        gl_.clearColor(0.1f, 0.14f, 0.12f, 1.0f);
        gl_.enable(GL_DEPTH_TEST);
        gl_.enable(GL_LIGHTING);
        gl_.enable(GL_LIGHT0);
        gl_.enable(GL_NORMALIZE);
        return true;
    }

    void draw(int frame) override
    {
        gl_.clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        gl_.loadIdentity();
        const float lightDirection[] = {-0.3f, 0.7f, 1.0f, 0.0f};
        gl_.lightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        gl_.translatef(0.0f, 0.0f, -6.0f);
        gl_.rotatef(20.0f, 1.0f, 0.0f, 0.0f);

        gl_.pushMatrix();
        gl_.rotatef(frame * 2.0f, 0.2f, 1.0f, 0.1f);
        drawCube(0.8f);
        gl_.popMatrix();

        gl_.pushMatrix();
        gl_.rotatef(frame * -1.5f, 0.0f, 1.0f, 0.0f);
        gl_.translatef(1.8f, 0.0f, 0.0f);
        setColour(0.95f, 0.85f, 0.2f);
        drawSphere(0.4f, 16, 24);
        gl_.popMatrix();
    }

private:
    void setColour(float r, float g, float b)
    {
        const float colour[] = {r, g, b, 1.0f};
        gl_.materialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colour);
    }

    void drawCube(float half)
    {
        // Each face: normal, then two in-face axes; one colour per face.
        const float faces[6][3][3] = {
            {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
            {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
            {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
        };
        const float colours[6][3] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.25f, 0.4f, 0.95f},
                                     {0.9f, 0.6f, 0.1f}, {0.8f, 0.3f, 0.8f}, {0.2f, 0.8f, 0.8f}};
        const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (int f = 0; f < 6; ++f) {
            const auto& face = faces[f];
            setColour(colours[f][0], colours[f][1], colours[f][2]);
            gl_.begin(GL_QUADS);
            gl_.normal3f(face[0][0], face[0][1], face[0][2]);
            for (const auto& st : corners) {
                float s = st[0] * half;
                float t = st[1] * half;
                gl_.vertex3f(face[0][0] * half + face[1][0] * s + face[2][0] * t,
                             face[0][1] * half + face[1][1] * s + face[2][1] * t,
                             face[0][2] * half + face[1][2] * s + face[2][2] * t);
            }
            gl_.end();
        }
    }

    void drawSphere(float radius, int stacks, int slices)
    {
        for (int i = 0; i < stacks; ++i) {
            gl_.begin(GL_TRIANGLE_STRIP);
            for (int j = 0; j <= slices; ++j) {
                float lon = 2.0f * pi * j / slices;
                for (int k = 0; k <= 1; ++k) {
                    float lat = pi * (i + k) / stacks - pi / 2.0f;
                    float n[3] = {std::cos(lat) * std::cos(lon), std::sin(lat),
                                  -std::cos(lat) * std::sin(lon)};
                    gl_.normal3f(n[0], n[1], n[2]);
                    gl_.vertex3f(radius * n[0], radius * n[1], radius * n[2]);
                }
            }
            gl_.end();
        }
    }

    demo::DrawFunctions gl_;
};

} // namespace

int main(int argc, char** argv)
{
    DlopenScene scene;
    demo::Options options;
    int status = demo::parseOptions(argc, argv, "dlopen", scene.extraOptions(), options);
    if (status >= 0) {
        return status;
    }
    demo::GlLoader loader;
    std::string error;
    if (!loader.load(options.textValue("lib", ""), options.offscreen, error)) {
        std::fprintf(stderr, "%s: %s\n", options.appName.c_str(), error.c_str());
        return 1;
    }
    if (options.has("print-resolved")) {
        loader.printResolved();
    }
    scene.setFunctions(loader.draw());
    return demo::runFrames(options, loader.api(), scene);
}
