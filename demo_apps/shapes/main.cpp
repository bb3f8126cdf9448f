// demo_shapes: spheres, tori and cubes at known transforms, lit, turning by a fixed step per
// frame, for measuring outline accuracy. With --truth DIR it also writes each saved frame's
// analytic silhouettes, ray cast on the CPU independently of GL.

#include "Demo.h"
#include "PngWriter.h"
#include "RayCaster.h"
#include "Shapes.h"

#include <GL/gl.h>

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <string>
#include <system_error>

namespace {

constexpr double pi = std::numbers::pi;

// Relative depth step that makes an occluding contour inside one object (torus inner rim);
// a sphere's rim steps by well under 1% between neighbouring pixels at 512x512.
constexpr double depthJump = 0.02;

void vertexOnSphere(double radius, double lat, double lon)
{
    double n[3] = {std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat)};
    glNormal3dv(n);
    glVertex3d(radius * n[0], radius * n[1], radius * n[2]);
}

// Two triangles per cell of latitude and longitude.
void drawSphere(double radius, int detail)
{
    int slices = detail;
    int stacks = std::max(2, detail / 2);
    glBegin(GL_TRIANGLES);
    for (int i = 0; i < stacks; ++i) {
        double lat0 = pi * i / stacks - pi / 2.0;
        double lat1 = pi * (i + 1) / stacks - pi / 2.0;
        for (int j = 0; j < slices; ++j) {
            double lon0 = 2.0 * pi * j / slices;
            double lon1 = 2.0 * pi * (j + 1) / slices;
            vertexOnSphere(radius, lat0, lon0);
            vertexOnSphere(radius, lat0, lon1);
            vertexOnSphere(radius, lat1, lon1);
            vertexOnSphere(radius, lat0, lon0);
            vertexOnSphere(radius, lat1, lon1);
            vertexOnSphere(radius, lat1, lon0);
        }
    }
    glEnd();
}

// Around the z axis, one GL_QUAD_STRIP per ring segment.
void drawTorus(double major, double minor, int detail)
{
    int rings = detail * 2;
    int sides = detail;
    for (int i = 0; i < rings; ++i) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= sides; ++j) {
            double v = 2.0 * pi * j / sides;
            // u_i before u_{i+1}: counter-clockwise seen from outside (the demo culls).
            for (int k = 0; k <= 1; ++k) {
                double u = 2.0 * pi * (i + k) / rings;
                double r = major + minor * std::cos(v);
                glNormal3d(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
                glVertex3d(r * std::cos(u), r * std::sin(u), minor * std::sin(v));
            }
        }
        glEnd();
    }
}

void drawCube(double half)
{
    // Per face: the normal's axis and sign; corners wound counter-clockwise from outside.
    glBegin(GL_TRIANGLES);
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {1.0, -1.0}) {
            int a = (axis + 1) % 3;
            int b = (axis + 2) % 3;
            double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            double p[4][3];
            for (int c = 0; c < 4; ++c) {
                p[c][axis] = sign * half;
                p[c][a] = corners[c][0] * half;
                p[c][b] = corners[c][1] * half * sign;
            }
            double n[3] = {0.0, 0.0, 0.0};
            n[axis] = sign;
            glNormal3dv(n);
            for (int c : {0, 1, 2, 0, 2, 3}) {
                glVertex3dv(p[c]);
            }
        }
    }
    glEnd();
}

class ShapesScene : public demo::Scene {
public:
    std::vector<demo::ExtraOption> extraOptions() const override
    {
        using Kind = demo::ExtraOption::Kind;
        return {{"step", Kind::Text, "turn per frame in degrees (default 0.5)"},
                {"detail", Kind::Int, "segments around a sphere or tube (default 96)", 8, 4096},
                {"truth", Kind::Text,
                 "DIR for shapes_<frame>_truth.png and _ids.png of each saved frame"}};
    }

    bool init(const demo::Options& options, std::string& error) override
    {
        options_ = options;
        std::string step = options.textValue("step", "0.5");
        auto [end, ec] = std::from_chars(step.data(), step.data() + step.size(), step_);
        if (ec != std::errc() || end != step.data() + step.size() || !std::isfinite(step_)) {
            error = "--step needs a number of degrees, got '" + step + "'";
            return false;
        }
        detail_ = options.intValue("detail", 96);
        truthDir_ = options.textValue("truth", "");
        if (!truthDir_.empty()) {
            std::error_code dirError;
            std::filesystem::create_directories(truthDir_, dirError);
            if (dirError) {
                error = "cannot create " + truthDir_ + ": " + dirError.message();
                return false;
            }
        }

        shapes::Camera camera = shapes::cameraFor(options.width, options.height);
        glViewport(0, 0, options.width, options.height);
        demo::setPerspective(camera.fovYDegrees, camera.aspect, camera.zNear, camera.zFar);
        glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_CULL_FACE);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_COLOR_MATERIAL);
        glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
        const float ambient[] = {0.25f, 0.25f, 0.25f, 1.0f};
        glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
        const float specular[] = {0.4f, 0.4f, 0.4f, 1.0f};
        glMaterialfv(GL_FRONT, GL_SPECULAR, specular);
        glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);
        glShadeModel(GL_SMOOTH);
        return true;
    }

    void draw(int frame) override
    {
        double angle = (frame - 1) * step_;
        std::vector<shapes::Shape> scene = shapes::sceneAt(angle);
        shapes::Camera camera = shapes::cameraFor(options_.width, options_.height);

        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_MODELVIEW);
        // The light is fixed to the camera, upper left in front.
        glLoadIdentity();
        const float lightDirection[] = {-0.4f, 0.6f, 0.7f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        glLoadMatrixd(camera.view.m.data());
        for (const shapes::Shape& shape : scene) {
            glPushMatrix();
            glMultMatrixd(shape.model.m.data());
            glColor3fv(shape.colour.data());
            switch (shape.kind) {
            case shapes::Kind::Sphere: drawSphere(shape.a, detail_); break;
            case shapes::Kind::Torus: drawTorus(shape.a, shape.b, detail_); break;
            case shapes::Kind::Cube: drawCube(shape.a); break;
            }
            glPopMatrix();
        }

        bool wanted = options_.saveDir.empty() || options_.shouldSave(frame);
        if (!truthDir_.empty() && wanted) {
            writeTruth(frame, scene, camera);
        }
    }

private:
    void writeTruth(int frame, const std::vector<shapes::Shape>& scene,
                    const shapes::Camera& camera)
    {
        int w = options_.width;
        int h = options_.height;
        shapes::TruthFrame truth = shapes::castRays(scene, camera, w, h);
        std::vector<uint8_t> mask = shapes::silhouettes(truth, depthJump);
        demo::Image silhouette{w, h, std::vector<uint8_t>(static_cast<size_t>(w) * h * 3)};
        demo::Image ids = silhouette;
        for (size_t i = 0; i < mask.size(); ++i) {
            for (int c = 0; c < 3; ++c) {
                silhouette.rgb[i * 3 + c] = mask[i] ? 255 : 0;
                int id = truth.ids[i];
                ids.rgb[i * 3 + c] =
                    id == 0 ? 0 : static_cast<uint8_t>(scene[id - 1].colour[c] * 255.0f);
            }
        }
        std::string base = truthDir_ + "/" + options_.shortName + "_" + std::to_string(frame);
        std::string error;
        if (!demo::writePng(base + "_truth.png", silhouette, error)
            || !demo::writePng(base + "_ids.png", ids, error)) {
            std::fprintf(stderr, "%s: %s\n", options_.appName.c_str(), error.c_str());
            std::exit(1);
        }
    }

    demo::Options options_;
    double step_ = 0.5;
    int detail_ = 96;
    std::string truthDir_;
};

} // namespace

int main(int argc, char** argv)
{
    ShapesScene scene;
    return demo::run(argc, argv, "shapes", scene);
}
