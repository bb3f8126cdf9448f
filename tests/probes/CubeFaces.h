#pragma once

// CubeFaces: the corners of the unit cube's six faces, the table the array and buffer probes
// build their cubes from.

namespace nprgl::probes {

// Per face (+z, -z, +x, -x, +y, -y), its four corners counter-clockwise seen from outside.
inline constexpr int kCubeFaces[6][4][3] = {
    {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
    {{1, -1, -1}, {-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}},
    {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {1, 1, 1}},
    {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
    {{-1, 1, 1}, {1, 1, 1}, {1, 1, -1}, {-1, 1, -1}},
    {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
};

} // namespace nprgl::probes
