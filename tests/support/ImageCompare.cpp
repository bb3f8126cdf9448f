#include "tests/support/ImageCompare.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace nprgl::test {

namespace {

// Whether `from`'s colour at (x, y) is within `tolerance` of a pixel of `in` around it.
bool nearby(const PngImage& from, const PngImage& in, int x, int y, int tolerance)
{
    const uint8_t* want = &from.rgba[(size_t(y) * from.width + x) * 4];
    for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= in.width || ny >= in.height) continue;
            const uint8_t* have = &in.rgba[(size_t(ny) * in.width + nx) * 4];
            int delta = 0;
            for (int c = 0; c < 3; ++c) delta = std::max(delta, std::abs(want[c] - have[c]));
            if (delta <= tolerance) return true;
        }
    }
    return false;
}

} // namespace

ImageDiff compareImages(const std::string& a, const std::string& b, int tolerance)
{
    ImageDiff diff;
    PngImage ia, ib;
    if (!PngImage::read(a, ia, diff.error) || !PngImage::read(b, ib, diff.error)) return diff;
    if (ia.width != ib.width || ia.height != ib.height) {
        diff.error = "sizes differ";
        return diff;
    }
    diff.comparable = true;
    for (size_t i = 0; i < ia.rgba.size(); i += 4) {
        int delta = 0;
        for (int c = 0; c < 3; ++c)
            delta = std::max(delta, std::abs(ia.rgba[i + c] - ib.rgba[i + c]));
        if (delta > tolerance) {
            ++diff.differingPixels;
            const int x = int(i / 4 % ia.width), y = int(i / 4 / ia.width);
            if (!nearby(ia, ib, x, y, tolerance) || !nearby(ib, ia, x, y, tolerance))
                ++diff.offEdgePixels;
        }
        diff.maxChannelDelta = std::max(diff.maxChannelDelta, delta);
    }
    return diff;
}

double coveredFraction(const PngImage& image)
{
    size_t covered = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        if (image.rgba[i] + image.rgba[i + 1] + image.rgba[i + 2] > 24) ++covered;
    }
    return image.rgba.empty() ? 0.0 : double(covered) / (image.rgba.size() / 4);
}

void expectGlxgearsPicture(const std::string& path)
{
    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(path, image, error)) << error;
    EXPECT_EQ(image.width, 300);
    size_t red = 0, green = 0, blue = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        int r8 = image.rgba[i], g8 = image.rgba[i + 1], b8 = image.rgba[i + 2];
        red += r8 > 120 && g8 < 60 && b8 < 60;
        green += g8 > 120 && r8 < 60 && b8 < 60;
        blue += b8 > 120 && r8 < 60 && g8 < 60;
    }
    EXPECT_GT(red, 1000u) << path;
    EXPECT_GT(green, 300u) << path;
    EXPECT_GT(blue, 300u) << path;
}

std::vector<uint8_t> readRgba(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int differingRgbPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b)
{
    if (a.size() != b.size() || a.empty()) return -1;
    int n = 0;
    for (size_t i = 0; i + 3 < a.size(); i += 4) {
        n += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
    }
    return n;
}

} // namespace nprgl::test
