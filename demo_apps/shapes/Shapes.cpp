#include "Shapes.h"

#include <cmath>
#include <numbers>

namespace shapes {

Mat4 Mat4::identity()
{
    Mat4 r;
    r.m[0] = r.m[5] = r.m[10] = r.m[15] = 1.0;
    return r;
}

Mat4 Mat4::translation(double x, double y, double z)
{
    Mat4 r = identity();
    r.m[12] = x;
    r.m[13] = y;
    r.m[14] = z;
    return r;
}

Mat4 Mat4::rotation(double angleDegrees, double ax, double ay, double az)
{
    double length = std::sqrt(ax * ax + ay * ay + az * az);
    ax /= length;
    ay /= length;
    az /= length;
    double a = angleDegrees * std::numbers::pi / 180.0;
    double c = std::cos(a);
    double s = std::sin(a);
    double t = 1.0 - c;
    Mat4 r = identity();
    // Column-major: m[col * 4 + row].
    r.m[0] = ax * ax * t + c;
    r.m[1] = ay * ax * t + az * s;
    r.m[2] = az * ax * t - ay * s;
    r.m[4] = ax * ay * t - az * s;
    r.m[5] = ay * ay * t + c;
    r.m[6] = az * ay * t + ax * s;
    r.m[8] = ax * az * t + ay * s;
    r.m[9] = ay * az * t - ax * s;
    r.m[10] = az * az * t + c;
    return r;
}

Mat4 Mat4::operator*(const Mat4& other) const
{
    Mat4 r;
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) {
            double sum = 0.0;
            for (int k = 0; k < 4; ++k) {
                sum += m[k * 4 + row] * other.m[col * 4 + k];
            }
            r.m[col * 4 + row] = sum;
        }
    }
    return r;
}

Vec3 Mat4::transformPoint(Vec3 p) const
{
    return {m[0] * p.x + m[4] * p.y + m[8] * p.z + m[12],
            m[1] * p.x + m[5] * p.y + m[9] * p.z + m[13],
            m[2] * p.x + m[6] * p.y + m[10] * p.z + m[14]};
}

Vec3 Mat4::transformDirection(Vec3 d) const
{
    return {m[0] * d.x + m[4] * d.y + m[8] * d.z, m[1] * d.x + m[5] * d.y + m[9] * d.z,
            m[2] * d.x + m[6] * d.y + m[10] * d.z};
}

Mat4 Mat4::rigidInverse() const
{
    Mat4 r = identity();
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col) {
            r.m[col * 4 + row] = m[row * 4 + col];
        }
    }
    Vec3 t = r.transformDirection({m[12], m[13], m[14]});
    r.m[12] = -t.x;
    r.m[13] = -t.y;
    r.m[14] = -t.z;
    return r;
}

std::vector<Shape> sceneAt(double angleDegrees)
{
    // Placed so that silhouettes cross: the torus rings overlap a sphere and a cube in depth.
    struct Placement {
        Kind kind;
        double a, b;
        std::array<float, 3> colour;
        Vec3 position;
        Vec3 tiltAxis;
        double tilt;
        double spin; // own turn per degree of the group's turn
    };
    static const Placement placements[] = {
        {Kind::Sphere, 0.75, 0.0, {0.85f, 0.25f, 0.2f}, {-0.95, 0.35, 0.0}, {1, 0, 0}, 0, 0},
        {Kind::Sphere, 0.45, 0.0, {0.2f, 0.7f, 0.3f}, {0.85, -0.7, 0.8}, {1, 0, 0}, 0, 0},
        {Kind::Torus, 0.7, 0.22, {0.95f, 0.8f, 0.2f}, {0.75, 0.55, -0.35}, {1, 0.3, 0}, 62, 1.5},
        {Kind::Torus, 0.5, 0.16, {0.3f, 0.45f, 0.95f}, {-0.5, -0.8, 0.7}, {0.2, 1, 0}, 35,
         -2.0},
        {Kind::Cube, 0.5, 0.0, {0.8f, 0.35f, 0.85f}, {0.1, 0.05, -1.5}, {1, 1, 0.3}, 30, 1.0},
        {Kind::Cube, 0.32, 0.0, {0.2f, 0.8f, 0.85f}, {-1.45, -0.45, -0.9}, {0.3, 1, 1}, 50, -1.0},
    };
    Mat4 group = Mat4::rotation(angleDegrees, 0.0, 1.0, 0.0);
    std::vector<Shape> shapes;
    for (const Placement& p : placements) {
        Shape shape;
        shape.kind = p.kind;
        shape.a = p.a;
        shape.b = p.b;
        shape.colour = p.colour;
        Mat4 own = Mat4::rotation(p.tilt, p.tiltAxis.x, p.tiltAxis.y, p.tiltAxis.z)
                   * Mat4::rotation(angleDegrees * p.spin, 0.3, 1.0, 0.2);
        shape.model = group * Mat4::translation(p.position.x, p.position.y, p.position.z) * own;
        shapes.push_back(shape);
    }
    return shapes;
}

Camera cameraFor(int width, int height)
{
    Camera camera;
    camera.aspect = static_cast<double>(width) / height;
    camera.view = Mat4::translation(0.0, 0.0, -7.0) * Mat4::rotation(18.0, 1.0, 0.0, 0.0);
    return camera;
}

} // namespace shapes
