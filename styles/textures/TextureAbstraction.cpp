#include "styles/textures/TextureAbstraction.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace nprgl::styles {

namespace {

constexpr int kRangeBins = 1024;
constexpr float kMaxDistance2 = 3.0f; // the squared RGB distance from black to white

// exp(-d2 / 2 sigma^2) over the squared colour distance, looked up: a pass takes a weight
// per tap, and exp per tap would be most of its time.
const std::array<float, kRangeBins + 1>& rangeWeights()
{
    static const std::array<float, kRangeBins + 1> table = [] {
        std::array<float, kRangeBins + 1> t{};
        const float s2 = 2.0f * TextureAbstraction::kRangeSigma * TextureAbstraction::kRangeSigma;
        for (int i = 0; i <= kRangeBins; ++i) {
            t[size_t(i)] = std::exp(-(float(i) / kRangeBins * kMaxDistance2) / s2);
        }
        return t;
    }();
    return table;
}

float distance2(glm::vec3 a, glm::vec3 b)
{
    const glm::vec3 d = a - b;
    return glm::dot(d, d);
}

} // namespace

void TextureAbstraction::smoothPass(std::vector<glm::vec4>& texels, int width, int height,
                                    bool rows, int radius)
{
    const auto& range = rangeWeights();
    const float sigma = float(radius) / 1.5f + 0.5f;
    std::vector<float> spatial(size_t(2 * radius + 1));
    for (int k = -radius; k <= radius; ++k) {
        spatial[size_t(k + radius)] = std::exp(-float(k * k) / (2.0f * sigma * sigma));
    }
    const std::vector<glm::vec4> source = texels;
    const int along = rows ? width : height;
    const int lines = rows ? height : width;
    for (int line = 0; line < lines; ++line) {
        for (int i = 0; i < along; ++i) {
            auto at = [&](int j) -> const glm::vec4& {
                j = ((j % along) + along) % along; // the texture repeats
                return rows ? source[size_t(line) * size_t(width) + size_t(j)]
                            : source[size_t(j) * size_t(width) + size_t(line)];
            };
            const glm::vec4& centre = at(i);
            glm::vec3 sum(0.0f);
            float total = 0.0f;
            for (int k = -radius; k <= radius; ++k) {
                const glm::vec4& t = at(i + k);
                const float d2 =
                    std::min(distance2(glm::vec3(t), glm::vec3(centre)), kMaxDistance2);
                // Clear texels hardly count: their colour is never seen.
                const float w = spatial[size_t(k + radius)] *
                                range[size_t(d2 / kMaxDistance2 * kRangeBins)] *
                                (k == 0 ? 1.0f : std::max(t.a, 0.02f));
                sum += w * glm::vec3(t);
                total += w;
            }
            glm::vec4& out = rows ? texels[size_t(line) * size_t(width) + size_t(i)]
                                  : texels[size_t(i) * size_t(width) + size_t(line)];
            out = glm::vec4(sum / total, centre.a);
        }
    }
}

std::vector<glm::vec3> TextureAbstraction::palette(const std::vector<glm::vec4>& texels)
{
    // A fixed stride over the image: the same texture always gives the same palette.
    std::vector<glm::vec4> sample;
    const size_t stride = std::max<size_t>(1, texels.size() / kSample);
    for (size_t i = 0; i < texels.size(); i += stride) {
        if (texels[i].a > 0.0f) sample.push_back(texels[i]);
    }
    if (sample.empty()) return {};
    auto lightness = [](const glm::vec4& c) { return 0.3f * c.r + 0.59f * c.g + 0.11f * c.b; };
    std::vector<glm::vec4> sorted = sample;
    std::sort(sorted.begin(), sorted.end(),
              [&](const glm::vec4& a, const glm::vec4& b) { return lightness(a) < lightness(b); });
    // The darkest and the lightest colour are kept as they are: a glow's black surround (unseen
    // under additive blending) stays black and a mask's full cover stays full, where a mean
    // of the dark end would lighten the whole surround. The others are k-means, started at
    // evenly spaced quantiles between.
    std::vector<glm::vec3> ends = {glm::vec3(sorted.front())};
    if (distance2(ends[0], glm::vec3(sorted.back())) > 0.0f)
        ends.push_back(glm::vec3(sorted.back()));
    std::vector<glm::vec3> means;
    for (int k = 1; k + 1 < kPaletteSize; ++k) {
        const size_t at = (sorted.size() - 1) * size_t(2 * k + 1) / size_t(2 * kPaletteSize);
        means.push_back(glm::vec3(sorted[at]));
    }
    auto joined = [&] {
        std::vector<glm::vec3> all = ends;
        all.insert(all.end(), means.begin(), means.end());
        return all;
    };
    for (int iteration = 0; iteration < 10; ++iteration) {
        const std::vector<glm::vec3> centres = joined();
        std::vector<glm::vec3> sums(centres.size(), glm::vec3(0.0f));
        std::vector<float> weights(centres.size(), 0.0f);
        for (const glm::vec4& texel : sample) {
            const glm::vec3 c(texel);
            size_t best = 0;
            for (size_t k = 1; k < centres.size(); ++k) {
                if (distance2(c, centres[k]) < distance2(c, centres[best])) best = k;
            }
            sums[best] += texel.a * c;
            weights[best] += texel.a;
        }
        // A mean closer than kMergeDistance to an end or another mean is one with it: a
        // region's leftover grain does not take palette entries that a flat region would show
        // as blotches.
        std::vector<glm::vec3> next;
        std::vector<float> nextWeights;
        for (size_t k = ends.size(); k < centres.size(); ++k) {
            if (weights[k] <= 0.0f) continue;
            const glm::vec3 c = sums[k] / weights[k];
            const bool atEnd = std::any_of(ends.begin(), ends.end(), [&](const glm::vec3& e) {
                return distance2(c, e) < kMergeDistance * kMergeDistance;
            });
            if (atEnd) continue;
            size_t merged = next.size();
            for (size_t j = 0; j < next.size(); ++j) {
                if (distance2(c, next[j]) < kMergeDistance * kMergeDistance) merged = j;
            }
            if (merged == next.size()) {
                next.push_back(c);
                nextWeights.push_back(weights[k]);
            } else {
                const float w = nextWeights[merged] + weights[k];
                next[merged] = (next[merged] * nextWeights[merged] + c * weights[k]) / w;
                nextWeights[merged] = w;
            }
        }
        means = std::move(next);
    }
    return joined();
}

TextureImage TextureAbstraction::abstracted(const TextureImage& rgba, float detail)
{
    TextureImage out;
    if (rgba.channels != 4 || rgba.empty() ||
        rgba.pixels.size() != size_t(rgba.width) * size_t(rgba.height) * 4) {
        return out;
    }
    detail = std::clamp(std::isfinite(detail) ? detail : 0.0f, 0.0f, 1.0f);
    const size_t n = size_t(rgba.width) * size_t(rgba.height);
    std::vector<glm::vec4> texels(n);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = &rgba.pixels[i * 4];
        texels[i] = glm::vec4(p[0], p[1], p[2], p[3]) / 255.0f;
    }
    // The radius grows with the texture: a region's texture detail is a few texels of a small
    // texture and more of a large one.
    const int radius = std::clamp(std::min(rgba.width, rgba.height) / 64, 1, 3);
    for (int pass = 0; pass < kPasses; ++pass) {
        smoothPass(texels, rgba.width, rgba.height, true, radius);
        smoothPass(texels, rgba.width, rgba.height, false, radius);
    }
    const std::vector<glm::vec3> colours = palette(texels);
    out.width = rgba.width;
    out.height = rgba.height;
    out.channels = 4;
    out.pixels.resize(n * 4);
    for (size_t i = 0; i < n; ++i) {
        const uint8_t* p = &rgba.pixels[i * 4];
        const glm::vec3 original = glm::vec3(p[0], p[1], p[2]) / 255.0f;
        glm::vec3 flat = glm::vec3(texels[i]);
        if (!colours.empty()) {
            size_t best = 0;
            for (size_t k = 1; k < colours.size(); ++k) {
                if (distance2(flat, colours[k]) < distance2(flat, colours[best])) best = k;
            }
            flat = colours[best];
        }
        const glm::vec3 c = glm::mix(flat, original, detail);
        for (int ch = 0; ch < 3; ++ch) {
            out.pixels[i * 4 + size_t(ch)] =
                uint8_t(std::lround(std::clamp(c[ch], 0.0f, 1.0f) * 255.0f));
        }
        out.pixels[i * 4 + 3] = p[3];
    }
    return out;
}

} // namespace nprgl::styles
