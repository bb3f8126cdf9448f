#include "SkinImage.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>

namespace character {

namespace {

uint32_t u32(const std::vector<uint8_t>& d, size_t at)
{
    return uint32_t(d[at]) | uint32_t(d[at + 1]) << 8 | uint32_t(d[at + 2]) << 16 |
           uint32_t(d[at + 3]) << 24;
}

} // namespace

bool SkinImage::loadBmp(const std::string& path, std::string& error)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot open texture file " + path;
        return false;
    }
    std::vector<uint8_t> d((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (d.size() < 54 || d[0] != 'B' || d[1] != 'M') {
        error = path + ": not a BMP file";
        return false;
    }
    const uint32_t pixels = u32(d, 10), header = u32(d, 14);
    const int32_t w = int32_t(u32(d, 18)), h = int32_t(u32(d, 22));
    const int bits = d[28] | d[29] << 8;
    const uint32_t compression = u32(d, 30);
    uint32_t colours = u32(d, 46);
    if (w <= 0 || h <= 0 || w > 8192 || h > 8192 || compression != 0 ||
        (bits != 8 && bits != 24)) {
        error = path + ": only uncompressed bottom-up 8- or 24-bit BMP files are read";
        return false;
    }
    if (bits == 8 && colours == 0) colours = 256;
    const size_t palette = 14 + size_t(header);
    const size_t stride = (size_t(w) * bits / 8 + 3) / 4 * 4;
    if (pixels + stride * size_t(h) > d.size() || (bits == 8 && palette + 4 * colours > d.size())) {
        error = path + ": truncated BMP file";
        return false;
    }
    width = w;
    height = h;
    rgb.resize(size_t(w) * h * 3);
    for (int y = 0; y < h; ++y) {
        const uint8_t* row = d.data() + pixels + size_t(y) * stride;
        for (int x = 0; x < w; ++x) {
            const uint8_t* bgr = bits == 24 ? row + 3 * x
                                            : d.data() + palette + 4 * std::min<uint32_t>(
                                                                       row[x], colours - 1);
            uint8_t* out = rgb.data() + (size_t(y) * w + x) * 3;
            out[0] = bgr[2];
            out[1] = bgr[1];
            out[2] = bgr[0];
        }
    }
    return true;
}

} // namespace character
