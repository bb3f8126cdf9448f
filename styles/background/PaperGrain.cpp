#include "styles/background/PaperGrain.h"

#include "styles/textures/TextureNoise.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nprgl::styles {

namespace {

int wrap(int i, int n) { return ((i % n) + n) % n; }

// Adds a soft round dab of `amount` at (x, y) to a wrapped field of n x n.
void dab(std::vector<float>& field, int n, float x, float y, float radius, float amount)
{
    const int r = int(std::ceil(radius + 1.0f));
    const int cx = int(std::floor(x)), cy = int(std::floor(y));
    for (int j = cy - r; j <= cy + r; ++j) {
        for (int i = cx - r; i <= cx + r; ++i) {
            const float dx = float(i) + 0.5f - x, dy = float(j) + 0.5f - y;
            const float d = std::sqrt(dx * dx + dy * dy);
            const float cover = std::clamp(radius + 0.5f - d, 0.0f, 1.0f);
            if (cover <= 0.0f) continue;
            float& v = field[size_t(wrap(j, n)) * size_t(n) + size_t(wrap(i, n))];
            // The strongest dab wins, so crossing fibres do not pile up into blots.
            if (std::abs(amount * cover) > std::abs(v)) v = amount * cover;
        }
    }
}

} // namespace

TextureImage PaperGrain::make(const Options& o)
{
    const int n = std::max(64, o.size / 64 * 64);
    const uint32_t seed = o.seed;
    // Fibres: short, gently bending strokes laid down as a chain of dabs; mostly darker,
    // some lighter (bleached pulp), all wrapped so the tile repeats without seams.
    std::vector<float> fibres(size_t(n) * size_t(n), 0.0f);
    for (int f = 0; f < o.fibres; ++f) {
        float x = TextureNoise::hash(seed, f, 0) * float(n);
        float y = TextureNoise::hash(seed, f, 1) * float(n);
        float angle = TextureNoise::hash(seed, f, 2) * 6.2831853f;
        const float bend = (TextureNoise::hash(seed, f, 3) - 0.5f) * 0.25f;
        const int length = 6 + int(TextureNoise::hash(seed, f, 4) * 26.0f);
        const bool light = TextureNoise::hash(seed, f, 5) < 0.3f;
        const float strength = (0.5f + 0.5f * TextureNoise::hash(seed, f, 6)) * o.fibre;
        const float amount = light ? 0.5f * strength : -strength;
        const float radius = 0.35f + 0.3f * TextureNoise::hash(seed, f, 7);
        for (int s = 0; s < length; ++s) {
            // Thin out towards both ends, like a real fibre.
            const float t = float(s) / float(length - 1);
            const float taper = std::sin(3.1415927f * t);
            dab(fibres, n, x, y, radius, amount * (0.4f + 0.6f * taper));
            angle += bend + (TextureNoise::hash(seed + 1, f, s) - 0.5f) * 0.2f;
            x += std::cos(angle) * 0.7f;
            y += std::sin(angle) * 0.7f;
        }
    }
    std::vector<float> value(size_t(n) * size_t(n));
    float brightest = 0.0f;
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const float fx = float(x), fy = float(y);
            // Formation: a few octaves of cloudy value noise.
            const float cloud = 0.5f * TextureNoise::value(seed + 2, fx, fy, 64, n) +
                                0.3f * TextureNoise::value(seed + 3, fx, fy, 32, n) +
                                0.2f * TextureNoise::value(seed + 4, fx, fy, 16, n);
            // Tooth: the fine bumps that catch the pigment.
            const float tooth = 0.6f * TextureNoise::value(seed + 5, fx, fy, 2, n) +
                                0.4f * TextureNoise::value(seed + 6, fx, fy, 4, n);
            const float v = 1.0f - o.cloud * cloud - o.tooth * tooth +
                            fibres[size_t(y) * size_t(n) + size_t(x)];
            value[size_t(y) * size_t(n) + size_t(x)] = v;
            brightest = std::max(brightest, v);
        }
    }
    // The brightest texel leaves the page untouched; the rest only ever darkens.
    TextureImage image = TextureImage::grey(n, n, 255);
    for (size_t i = 0; i < value.size(); ++i) {
        const float v = std::clamp(value[i] + (1.0f - brightest), 0.0f, 1.0f);
        image.pixels[i] = uint8_t(std::lround(v * 255.0f));
    }
    return image;
}

} // namespace nprgl::styles
