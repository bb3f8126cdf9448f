// The frames probe_reload saves, and how many pixels two of them differ in (test_config).
#pragma once

#include "common/PngImage.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace nprgl::test {

// probe_reload's frame n in dir (reload_<n>.png).
inline PngImage frame(const std::string& dir, int n)
{
    PngImage image;
    std::string error;
    EXPECT_TRUE(PngImage::read(dir + "/reload_" + std::to_string(n) + ".png", image, error))
        << error;
    return image;
}

// Pixels whose colour differs by more than a rounding step (-1: sizes differ).
inline int differing(const PngImage& a, const PngImage& b)
{
    if (a.rgba.size() != b.rgba.size()) return -1;
    int n = 0;
    for (size_t i = 0; i < a.rgba.size(); i += 4) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d += std::abs(int(a.rgba[i + c]) - int(b.rgba[i + c]));
        n += d > 6;
    }
    return n;
}

} // namespace nprgl::test
