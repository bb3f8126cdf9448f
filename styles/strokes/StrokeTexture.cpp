#include "styles/strokes/StrokeTexture.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace nprgl::styles::strokes {

namespace {

constexpr float kPi = 3.14159265f;

float hash(int x, int y, uint32_t seed)
{
    uint32_t h = uint32_t(x) * 0x8da6b343u ^ uint32_t(y) * 0xd8163841u ^ seed * 0xcb1ab31fu;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return float(h & 0xffffffu) / float(0xffffff);
}

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

// Value noise, periodic with `period` cells along x (so the middle of the texture tiles).
float noise(float x, float y, int period, uint32_t seed)
{
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = int(fx), iy = int(fy);
    const float tx = smooth(x - fx), ty = smooth(y - fy);
    auto at = [&](int i, int j) { return hash(((i % period) + period) % period, j, seed); };
    const float a = at(ix, iy), b = at(ix + 1, iy), c = at(ix, iy + 1), d = at(ix + 1, iy + 1);
    return (a + (b - a) * tx) + ((c + (d - c) * tx) - (a + (b - a) * tx)) * ty;
}

float clamp01(float x) { return std::clamp(x, 0.0f, 1.0f); }

// Soft-edged coverage across the stroke: 1 inside |v - 0.5| < half, falling off over `soft`.
float band(float v, float half, float soft)
{
    return clamp01((half - std::abs(v - 0.5f)) / soft + 0.5f);
}

} // namespace

void StrokeTexture::generate(Kind kind, PngImage& out)
{
    out.width = kWidth;
    out.height = kHeight;
    out.rgba.assign(size_t(kWidth) * kHeight * 4, 255);
    const uint32_t seed = 17u + uint32_t(kind);
    for (int y = 0; y < kHeight; ++y) {
        const float v = (float(y) + 0.5f) / float(kHeight);
        for (int x = 0; x < kWidth; ++x) {
            const float u = (float(x) + 0.5f) / float(kWidth);
            // Phase along the stroke, continuous from the start cap through the middle to the
            // end cap; the middle covers exactly whole noise periods so it tiles.
            const float along = (u - kU1) / (kU2 - kU1);
            // Pressure: 0 at the very tips, 1 once the caps are done.
            const float startTip = clamp01(u / kU1), endTip = clamp01((1.0f - u) / (1.0f - kU2));
            float coverage = 0.0f, shade = 1.0f;
            switch (kind) {
            case Kind::Pencil: {
                const float taper = std::sqrt(std::min(startTip, endTip));
                const float wobble = 0.04f * (noise(along * 6.0f, 0.0f, 6, seed) - 0.5f);
                const float core = band(v + wobble, 0.12f + 0.34f * taper, 0.06f);
                const float grain = noise(along * 96.0f, v * 24.0f, 96, seed + 1);
                const float fine = hash(int(std::floor(along * 256.0f)) & 255, y, seed + 2);
                coverage = core * (0.62f + 0.28f * grain + 0.10f * fine) * (0.6f + 0.4f * taper);
                break;
            }
            case Kind::Ink: {
                const float taper = std::pow(std::min(startTip, endTip), 0.4f);
                const float wobble = 0.03f * (noise(along * 8.0f, 0.0f, 8, seed) - 0.5f);
                coverage = band(v + wobble, 0.08f + 0.40f * taper, 0.04f);
                coverage *= 0.92f + 0.08f * noise(along * 32.0f, v * 8.0f, 32, seed + 1);
                break;
            }
            case Kind::Brush: {
                // A swelling body that starts with a press and lifts off dry at the end.
                const float press = std::sin(kPi * std::min(1.0f, startTip) * 0.5f);
                const float lift = std::pow(endTip, 0.7f);
                const float swell = 0.85f + 0.15f * std::sin(2.0f * kPi * along);
                const float half = (0.12f + 0.36f * std::min(press, lift)) * swell;
                const float bristles = noise(along * 4.0f, v * 14.0f, 4, seed + 1);
                const float dry = clamp01(1.2f - (1.0f - endTip) * 1.4f * (1.0f - bristles));
                coverage = band(v, half, 0.04f) * (0.75f + 0.25f * bristles) * dry;
                shade = 0.85f + 0.15f * bristles;
                break;
            }
            case Kind::Chalk: {
                const float taper = std::sqrt(std::min(startTip, endTip));
                const float edge = 0.05f * (noise(along * 24.0f, v * 3.0f, 24, seed) - 0.5f);
                const float body = band(v + edge, 0.12f + 0.34f * taper, 0.05f);
                const float grain = noise(along * 128.0f, v * 28.0f, 128, seed + 1);
                coverage = body * clamp01((grain - 0.28f) * 2.2f) * 0.95f;
                shade = 0.9f + 0.1f * grain;
                break;
            }
            }
            uint8_t* p = &out.rgba[(size_t(y) * kWidth + size_t(x)) * 4];
            const uint8_t s = uint8_t(std::lround(clamp01(shade) * 255.0f));
            p[0] = p[1] = p[2] = s;
            p[3] = uint8_t(std::lround(clamp01(coverage) * 255.0f));
        }
    }
}

bool StrokeTexture::load(const std::string& path, PngImage& out, std::string& error)
{
    if (!PngImage::read(path, out, error)) return false;
    if (out.width < 4 || out.height < 2) {
        error = path + " is too small for a stroke texture";
        return false;
    }
    bool opaque = true;
    for (size_t i = 3; i < out.rgba.size() && opaque; i += 4) opaque = out.rgba[i] == 255;
    if (opaque) {
        for (size_t i = 0; i < out.rgba.size(); i += 4) {
            const float luminance =
                (0.299f * out.rgba[i] + 0.587f * out.rgba[i + 1] + 0.114f * out.rgba[i + 2]) /
                255.0f;
            out.rgba[i] = out.rgba[i + 1] = out.rgba[i + 2] = 255;
            out.rgba[i + 3] = uint8_t(std::lround((1.0f - luminance) * 255.0f));
        }
    }
    return true;
}

} // namespace nprgl::styles::strokes
