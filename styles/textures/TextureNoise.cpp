#include "styles/textures/TextureNoise.h"

#include <cmath>

namespace nprgl::styles {

namespace {

uint32_t mix(uint32_t h)
{
    h ^= h >> 16;
    h *= 0x7feb352du;
    h ^= h >> 15;
    h *= 0x846ca68bu;
    h ^= h >> 16;
    return h;
}

int wrap(int i, int n) { return ((i % n) + n) % n; }

float smooth(float t) { return t * t * (3.0f - 2.0f * t); }

} // namespace

float TextureNoise::hash(uint32_t seed, int a, int b)
{
    uint32_t h = mix(seed * 0x9e3779b9u ^ mix(uint32_t(a) * 0x85ebca6bu ^ mix(uint32_t(b))));
    return float(h >> 8) / float(1u << 24);
}

float TextureNoise::value(uint32_t seed, float x, float y, int cell, int period)
{
    const int n = period / cell;
    const float fx = x / float(cell), fy = y / float(cell);
    const int ix = int(std::floor(fx)), iy = int(std::floor(fy));
    const float tx = smooth(fx - float(ix)), ty = smooth(fy - float(iy));
    auto at = [&](int i, int j) { return hash(seed, wrap(i, n), wrap(j, n)); };
    const float top = at(ix, iy) + (at(ix + 1, iy) - at(ix, iy)) * tx;
    const float bottom = at(ix, iy + 1) + (at(ix + 1, iy + 1) - at(ix, iy + 1)) * tx;
    return top + (bottom - top) * ty;
}

float TextureNoise::line(uint32_t seed, int lineIndex, float t, int cell, int period)
{
    const int n = period / cell;
    const float f = t / float(cell);
    const int i = int(std::floor(f));
    const float s = smooth(f - float(i));
    const float a = hash(seed, lineIndex, wrap(i, n)), b = hash(seed, lineIndex, wrap(i + 1, n));
    return a + (b - a) * s;
}

} // namespace nprgl::styles
