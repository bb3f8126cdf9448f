#include "RayCaster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace shapes {

namespace {

constexpr double miss = -1.0;

double intersectSphere(double radius, Vec3 o, Vec3 d)
{
    // |o + t d|^2 = r^2 with |d| = 1.
    double b = dot(o, d);
    double c = dot(o, o) - radius * radius;
    double discriminant = b * b - c;
    if (discriminant < 0.0) {
        return miss;
    }
    double root = std::sqrt(discriminant);
    double t = -b - root;
    if (t < 0.0) {
        t = -b + root;
    }
    return t >= 0.0 ? t : miss;
}

double intersectCube(double half, Vec3 o, Vec3 d)
{
    // Slabs: the last entry before the first exit.
    double enter = -std::numeric_limits<double>::infinity();
    double exit = std::numeric_limits<double>::infinity();
    const double origin[3] = {o.x, o.y, o.z};
    const double direction[3] = {d.x, d.y, d.z};
    for (int axis = 0; axis < 3; ++axis) {
        if (std::fabs(direction[axis]) < 1e-300) {
            if (std::fabs(origin[axis]) > half) {
                return miss;
            }
            continue;
        }
        double t0 = (-half - origin[axis]) / direction[axis];
        double t1 = (half - origin[axis]) / direction[axis];
        enter = std::max(enter, std::min(t0, t1));
        exit = std::min(exit, std::max(t0, t1));
    }
    if (enter > exit || exit < 0.0) {
        return miss;
    }
    return enter >= 0.0 ? enter : exit;
}

double torusDistance(double major, double minor, Vec3 p)
{
    double ring = std::sqrt(p.x * p.x + p.y * p.y) - major;
    return std::sqrt(ring * ring + p.z * p.z) - minor;
}

double intersectTorus(double major, double minor, Vec3 o, Vec3 d)
{
    // Sphere tracing on the signed distance, which never steps over the surface; only the
    // stretch inside the bounding sphere is traced.
    double bound = intersectSphere(major + minor, o, d);
    if (bound < 0.0) {
        return miss;
    }
    double b = dot(o, d);
    double c = dot(o, o) - (major + minor) * (major + minor);
    double farEnd = -b + std::sqrt(std::max(0.0, b * b - c));
    double t = c > 0.0 ? bound : 0.0;
    for (int step = 0; step < 4000 && t <= farEnd; ++step) {
        double distance = torusDistance(major, minor, o + t * d);
        if (distance < 1e-9) {
            return t;
        }
        t += distance;
    }
    return miss;
}

} // namespace

double intersect(const Shape& shape, Vec3 origin, Vec3 direction)
{
    switch (shape.kind) {
    case Kind::Sphere: return intersectSphere(shape.a, origin, direction);
    case Kind::Torus: return intersectTorus(shape.a, shape.b, origin, direction);
    case Kind::Cube: return intersectCube(shape.a, origin, direction);
    }
    return miss;
}

TruthFrame castRays(const std::vector<Shape>& shapes, const Camera& camera, int width,
                    int height)
{
    TruthFrame frame;
    frame.width = width;
    frame.height = height;
    frame.ids.assign(static_cast<size_t>(width) * height, 0);
    frame.depths.assign(frame.ids.size(), std::numeric_limits<double>::infinity());

    // Each shape's eye-to-shape transform; rigid, so ray lengths are kept.
    std::vector<Mat4> eyeToShape;
    for (const Shape& shape : shapes) {
        eyeToShape.push_back((camera.view * shape.model).rigidInverse());
    }
    double tanHalf = std::tan(camera.fovYDegrees * std::numbers::pi / 360.0);
    for (int row = 0; row < height; ++row) {
        // Window y grows upwards; the image's first row is the top one.
        double ndcY = 2.0 * (height - 1 - row + 0.5) / height - 1.0;
        for (int x = 0; x < width; ++x) {
            double ndcX = 2.0 * (x + 0.5) / width - 1.0;
            Vec3 direction = {ndcX * tanHalf * camera.aspect, ndcY * tanHalf, -1.0};
            direction = (1.0 / std::sqrt(dot(direction, direction))) * direction;
            double nearest = std::numeric_limits<double>::infinity();
            int id = 0;
            for (size_t i = 0; i < shapes.size(); ++i) {
                Vec3 o = eyeToShape[i].transformPoint({0.0, 0.0, 0.0});
                Vec3 d = eyeToShape[i].transformDirection(direction);
                double t = intersect(shapes[i], o, d);
                if (t >= 0.0 && t < nearest) {
                    nearest = t;
                    id = static_cast<int>(i) + 1;
                }
            }
            size_t index = static_cast<size_t>(row) * width + x;
            frame.ids[index] = id;
            if (id != 0) {
                frame.depths[index] = -nearest * direction.z;
            }
        }
    }
    return frame;
}

std::vector<uint8_t> silhouettes(const TruthFrame& frame, double relativeJump)
{
    int w = frame.width;
    int h = frame.height;
    std::vector<uint8_t> mask(static_cast<size_t>(w) * h, 0);
    auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < w && y < h; };
    auto index = [&](int x, int y) { return static_cast<size_t>(y) * w + x; };
    // Inverse depth is affine in screen space across a plane, so its steps along a row stay
    // equal on a grazing face and only a true occlusion makes one step stand out.
    auto inverse = [&](size_t i) { return 1.0 / frame.depths[i]; };
    const int offsets[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            size_t i = index(x, y);
            int id = frame.ids[i];
            if (id == 0) {
                continue;
            }
            double depth = frame.depths[i];
            for (const auto& o : offsets) {
                int nx = x + o[0];
                int ny = y + o[1];
                if (!inside(nx, ny)) {
                    continue;
                }
                size_t j = index(nx, ny);
                // The nearer pixel of a pair carries the line, so it is one pixel wide.
                if (frame.ids[j] != id) {
                    if (frame.depths[j] > depth) {
                        mask[i] = 1;
                    }
                    continue;
                }
                if (frame.depths[j] <= depth * (1.0 + relativeJump)) {
                    continue;
                }
                double jump = inverse(i) - inverse(j);
                double step = 0.0;
                if (inside(x - o[0], y - o[1]) && frame.ids[index(x - o[0], y - o[1])] == id) {
                    step = std::max(step, std::fabs(inverse(index(x - o[0], y - o[1]))
                                                     - inverse(i)));
                }
                if (inside(nx + o[0], ny + o[1])
                    && frame.ids[index(nx + o[0], ny + o[1])] == id) {
                    step = std::max(step, std::fabs(inverse(j)
                                                     - inverse(index(nx + o[0], ny + o[1]))));
                }
                if (jump > 3.0 * step) {
                    mask[i] = 1;
                }
            }
        }
    }
    return mask;
}

} // namespace shapes
