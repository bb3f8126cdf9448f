#include "styles/textures/HalftoneScreens.h"

#include "styles/textures/TextureNoise.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace nprgl::styles {

namespace {

constexpr float kLevel[3] = {0.0f, 0.33f, 0.66f}; // where B' and C' start (thesis)

// The raw grey of screen `level` (0 = A, 1 = B, 2 = C) for a texel whose combined value
// should be `target`: inside the screen's own range it ramps so that the remapping of
// combine() gives `target` back; below it the screen is solid ink, above it blank.
uint8_t rawFor(int level, float target)
{
    const float lo = kLevel[level], hi = level == 2 ? 1.0f : kLevel[level + 1];
    if (target >= hi) return 255;
    const float raw = std::max(0.0f, target - lo) / (1.0f - lo);
    return uint8_t(std::lround(255.0f * std::clamp(raw, 0.0f, 1.0f)));
}

// Spreads a field of "spot" values evenly over [0, 1) by rank, so that the share of texels
// below a threshold equals the threshold: ink coverage then follows darkness linearly.
std::vector<float> equalise(const std::vector<float>& spot)
{
    std::vector<uint32_t> order(spot.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](uint32_t a, uint32_t b) { return spot[a] < spot[b]; });
    std::vector<float> rank(spot.size());
    for (size_t i = 0; i < order.size(); ++i) rank[order[i]] = float(i) / float(order.size());
    return rank;
}

// Splits an equalised target field into the three screens.
HalftoneScreens::Set split(const std::vector<float>& target, int size)
{
    HalftoneScreens::Set s;
    TextureImage* screens[3] = {&s.a, &s.b, &s.c};
    for (int level = 0; level < 3; ++level) {
        *screens[level] = TextureImage::grey(size, size, 255);
        for (size_t i = 0; i < target.size(); ++i) {
            screens[level]->pixels[i] = rawFor(level, target[i]);
        }
    }
    return s;
}

// Distance from `v` to the nearest multiple of `period` shifted by `offset`.
float lineDistance(float v, float period, float offset)
{
    const float t = v - offset;
    return std::abs(t - period * std::floor(t / period + 0.5f));
}

// A ramped line screen: 0 on the line, rising to 1 at `halfWidth` from it, 255 beyond.
uint8_t lineRaw(int level, float dist, float halfWidth)
{
    if (dist >= halfWidth) return 255;
    const float lo = kLevel[level], hi = level == 2 ? 1.0f : kLevel[level + 1];
    return rawFor(level, lo + (hi - lo) * dist / halfWidth);
}

HalftoneScreens::Set dots(int size)
{
    // Dots on a 45-degree lattice (centres at the corners and the middle of 8 x 8 cells) like
    // a newspaper screen; the spot value is the distance to the nearest centre.
    const float p = 8.0f;
    std::vector<float> spot(size_t(size) * size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float px = float(x) + 0.5f, py = float(y) + 0.5f;
            const float ax = lineDistance(px, p, 0.0f), ay = lineDistance(py, p, 0.0f);
            const float bx = lineDistance(px, p, p / 2), by = lineDistance(py, p, p / 2);
            const float d = std::min(std::hypot(ax, ay), std::hypot(bx, by));
            // Tiny position-dependent tie-breaker keeps the ranking deterministic but even.
            spot[size_t(y) * size + x] = d + 1e-4f * TextureNoise::hash(5, x, y);
        }
    }
    return split(equalise(spot), size);
}

HalftoneScreens::Set lines(int size)
{
    // Diagonal lines of three densities: A every 16 texels (along x), B halfway between them,
    // C between those; each darker screen doubles the density.
    HalftoneScreens::Set s;
    s.a = TextureImage::grey(size, size, 255);
    s.b = s.a;
    s.c = s.a;
    const float sq = std::sqrt(2.0f);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float v = float(x) + float(y) + 1.0f; // constant along one diagonal
            s.a.at(x, y) = lineRaw(0, lineDistance(v, 16.0f, 0.0f) / sq, 2.0f);
            s.b.at(x, y) = lineRaw(1, lineDistance(v, 16.0f, 8.0f) / sq, 2.0f);
            s.c.at(x, y) = lineRaw(2, lineDistance(v, 8.0f, 4.0f) / sq, 1.5f);
        }
    }
    return s;
}

HalftoneScreens::Set noise(int size)
{
    // Charcoal: one screen of grainy multi-scale noise, equalised so darkness maps to
    // coverage; B and C stay blank (the thesis needs only one screen for noise).
    std::vector<float> spot(size_t(size) * size);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float px = float(x), py = float(y);
            // Coarse smudges plus strong paper grain; the middle octave is stretched along x
            // like charcoal dragged over the paper.
            const float n = 0.35f * TextureNoise::value(11, px, py, 32, size) +
                            0.3f * TextureNoise::value(12, px, py * 4.0f, 16, size * 4) +
                            0.35f * TextureNoise::value(13, px, py, 2, size);
            spot[size_t(y) * size + x] = n;
        }
    }
    const std::vector<float> target = equalise(spot);
    HalftoneScreens::Set s;
    s.a = TextureImage::grey(size, size, 255);
    for (size_t i = 0; i < target.size(); ++i) {
        s.a.pixels[i] = uint8_t(std::lround(255.0f * target[i]));
    }
    return s;
}

HalftoneScreens::Set bricks(int size)
{
    // A: the mortar between 32 x 16 bricks in staggered rows; B: hatching inside the bricks;
    // C: the crossing hatch.
    HalftoneScreens::Set s;
    s.a = TextureImage::grey(size, size, 255);
    s.b = s.a;
    s.c = s.a;
    const float sq = std::sqrt(2.0f);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float px = float(x) + 0.5f, py = float(y) + 0.5f;
            const int row = y / 16;
            const float shift = (row % 2) ? 16.0f : 0.0f;
            const float mortar = std::min(lineDistance(py, 16.0f, 0.0f),
                                          lineDistance(px + shift, 32.0f, 0.0f));
            s.a.at(x, y) = lineRaw(0, mortar, 1.5f);
            s.b.at(x, y) = lineRaw(1, lineDistance(px + py, 8.0f, 0.0f) / sq, 1.8f);
            s.c.at(x, y) = lineRaw(2, lineDistance(px - py + float(size), 8.0f, 4.0f) / sq, 1.8f);
        }
    }
    return s;
}

} // namespace

bool HalftoneScreens::parsePattern(const std::string& name, Pattern& out)
{
    if (name == "dots") out = Pattern::Dots;
    else if (name == "lines") out = Pattern::Lines;
    else if (name == "noise") out = Pattern::Noise;
    else if (name == "bricks") out = Pattern::Bricks;
    else return false;
    return true;
}

HalftoneScreens::Set HalftoneScreens::make(Pattern pattern, int size)
{
    switch (pattern) {
    case Pattern::Dots: return dots(size);
    case Pattern::Lines: return lines(size);
    case Pattern::Noise: return noise(size);
    case Pattern::Bricks: return bricks(size);
    }
    return {};
}

TextureImage HalftoneScreens::combine(const Set& screens)
{
    const TextureImage* layers[3] = {&screens.a, &screens.b, &screens.c};
    const TextureImage* first = nullptr;
    for (const TextureImage* l : layers) {
        if (!l->empty()) {
            first = l;
            break;
        }
    }
    if (!first) return TextureImage::grey(1, 1, 255);
    TextureImage out = TextureImage::grey(first->width, first->height, 255);
    for (int level = 0; level < 3; ++level) {
        const TextureImage& l = *layers[level];
        if (l.empty()) continue;
        const float lo = kLevel[level];
        for (int y = 0; y < out.height; ++y) {
            for (int x = 0; x < out.width; ++x) {
                // Screens of another size repeat over the combined tile.
                const int sx = x % l.width, sy = y % l.height;
                const float raw =
                    float(l.pixels[(size_t(sy) * l.width + sx) * size_t(l.channels)]) / 255.0f;
                const float remapped = lo + (1.0f - lo) * raw;
                uint8_t& o = out.at(x, y);
                o = std::min(o, uint8_t(std::lround(255.0f * remapped)));
            }
        }
    }
    return out;
}

} // namespace nprgl::styles
