#pragma once

// The analytic scene of demo_shapes, free of GL: the GL renderer (main.cpp) and the CPU ray
// caster (RayCaster.cpp) both draw exactly this.

#include <array>
#include <vector>

namespace shapes {

struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;
};

inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// A 4x4 matrix, column-major like GL's.
struct Mat4 {
    std::array<double, 16> m{};

    static Mat4 identity();
    static Mat4 translation(double x, double y, double z);
    // Rotation by angleDegrees about the axis (ax, ay, az), like glRotated.
    static Mat4 rotation(double angleDegrees, double ax, double ay, double az);

    Mat4 operator*(const Mat4& other) const;
    Vec3 transformPoint(Vec3 p) const;
    Vec3 transformDirection(Vec3 d) const;
    // Inverse of a rotation plus translation, which is all the scene uses.
    Mat4 rigidInverse() const;
};

enum class Kind { Sphere, Torus, Cube };

// One shape in its own frame: a sphere of radius a at the origin; a torus around the z axis
// with major radius a and tube radius b; a cube with half side a.
struct Shape {
    Kind kind = Kind::Sphere;
    double a = 1.0;
    double b = 0.0;
    std::array<float, 3> colour{};
    Mat4 model; // shape frame to world
};

struct Camera {
    double fovYDegrees = 40.0;
    double aspect = 1.0;
    double zNear = 1.0;
    double zFar = 40.0;
    Mat4 view; // world to eye
};

// The shapes at a turn of angleDegrees; each shape's id in the truth is its index + 1.
std::vector<Shape> sceneAt(double angleDegrees);
Camera cameraFor(int width, int height);

} // namespace shapes
