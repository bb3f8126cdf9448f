// OverlayLegibility: a 2D draw's contrast, the --overlays line format, and the rule.
#include "common/OverlayLegibility.h"

#include "common/SrgbLinear.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace nprgl {

namespace {

bool changed(const uint8_t* a, const uint8_t* b)
{
    for (int c = 0; c < 3; ++c) {
        if (std::abs(int(a[c]) - int(b[c])) > OverlayLegibility::kChanged) return true;
    }
    return false;
}

} // namespace

double OverlayLegibility::luminance(const uint8_t* rgb)
{
    return 0.2126 * srgbLinear(rgb[0]) + 0.7152 * srgbLinear(rgb[1]) +
           0.0722 * srgbLinear(rgb[2]);
}

float OverlayLegibility::ratio(double l1, double l2)
{
    const double hi = std::max(l1, l2), lo = std::min(l1, l2);
    return float((hi + 0.05) / (lo + 0.05));
}

void OverlayLegibility::changedPixels(const uint8_t* before, const uint8_t* after, int width,
                                      int height, std::vector<uint32_t>& out)
{
    out.clear();
    const size_t n = size_t(width) * size_t(height);
    for (size_t i = 0; i < n; ++i) {
        if (changed(before + i * 4, after + i * 4)) out.push_back(uint32_t(i));
    }
}

OverlayDraw OverlayLegibility::measure(const std::vector<uint32_t>& pixels, const uint8_t* shown,
                                       int width, int height, const uint8_t* later)
{
    OverlayDraw d;
    d.pixels = uint32_t(pixels.size());
    if (pixels.empty()) return d;
    int x0 = width, y0 = height, x1 = -1, y1 = -1;
    for (const uint32_t i : pixels) {
        const int x = int(i % uint32_t(width)), y = int(i / uint32_t(width));
        x0 = std::min(x0, x), x1 = std::max(x1, x);
        y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
    // The draw's pixels in the box around them grown by kRing, grown by kRing along rows and
    // then along columns: a square neighbourhood.
    x0 = std::max(0, x0 - kRing), y0 = std::max(0, y0 - kRing);
    x1 = std::min(width - 1, x1 + kRing), y1 = std::min(height - 1, y1 + kRing);
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    auto at = [w](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
    std::vector<uint8_t> mine(size_t(w) * size_t(h)), rows(mine.size());
    for (const uint32_t i : pixels) {
        mine[at(int(i % uint32_t(width)) - x0, int(i / uint32_t(width)) - y0)] = 1;
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool any = false;
            for (int k = std::max(0, x - kRing); k <= std::min(w - 1, x + kRing) && !any; ++k)
                any = mine[at(k, y)] != 0;
            rows[at(x, y)] = any;
        }
    }
    double ring = 0.0;
    uint64_t ringPixels = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y + y0) * size_t(width) + size_t(x + x0);
            if (mine[at(x, y)] || (later && later[i])) continue;
            bool any = false;
            for (int k = std::max(0, y - kRing); k <= std::min(h - 1, y + kRing) && !any; ++k)
                any = rows[at(x, k)] != 0;
            if (!any) continue;
            ++ringPixels;
            ring += luminance(shown + i * 4);
        }
    }
    if (ringPixels == 0) return d;
    ring /= double(ringPixels);
    // Each pixel against the mean of the surroundings; the draw's figure is the quantile
    // kStrokes of them: its strokes' cores, not their antialiased fringe.
    std::vector<float> each;
    each.reserve(pixels.size());
    for (const uint32_t i : pixels)
        each.push_back(ratio(luminance(shown + size_t(i) * 4), ring));
    const size_t q = std::min(each.size() - 1, size_t(double(each.size()) * kStrokes));
    std::nth_element(each.begin(), each.begin() + std::ptrdiff_t(q), each.end());
    d.surrounded = true;
    d.contrast = each[q];
    return d;
}

bool OverlayLegibility::parse(const std::string& text, std::vector<OverlayDraw>& out)
{
    out.clear();
    unsigned long count = 0;
    int used = 0;
    if (std::sscanf(text.c_str(), "%lu measured:%n", &count, &used) != 1 || used <= 0) {
        return false;
    }
    const char* p = text.c_str() + used;
    while (*p == ' ') {
        ++p;
        char* end = nullptr;
        const unsigned long pixels = std::strtoul(p, &end, 10);
        if (end == p || *end != ':') return false;
        p = end + 1;
        OverlayDraw d;
        d.pixels = uint32_t(std::min<unsigned long>(pixels, UINT32_MAX));
        if (*p == '-') {
            ++p;
        } else {
            d.contrast = std::strtof(p, &end);
            if (end == p || !(d.contrast >= 1.0f) || d.contrast > 22.0f) return false;
            d.surrounded = true;
            p = end;
        }
        out.push_back(d);
    }
    return *p == '\0' && out.size() == count;
}

std::string OverlayLegibility::describe(const std::vector<OverlayDraw>& draws)
{
    std::string out = std::to_string(draws.size()) + " measured:";
    for (const OverlayDraw& d : draws) {
        char item[48];
        if (d.surrounded)
            std::snprintf(item, sizeof item, " %u:%.2f", d.pixels, d.contrast);
        else
            std::snprintf(item, sizeof item, " %u:-", d.pixels);
        out += item;
    }
    return out;
}

OverlayLegibility OverlayLegibility::judge(const std::vector<OverlayDraw>& native,
                                           const std::vector<OverlayDraw>& styled)
{
    OverlayLegibility out;
    if (native.size() != styled.size()) {
        out.mismatch = std::to_string(native.size()) + " 2D draws natively, " +
                       std::to_string(styled.size()) + " in the style";
        return out;
    }
    for (size_t i = 0; i < native.size(); ++i) {
        const OverlayDraw& n = native[i];
        const OverlayDraw& s = styled[i];
        if (n.pixels < kMinPixels || !n.surrounded) continue;
        ++out.judged;
        // Shown on far more pixels than natively (a shadow pass in the clear colour, seen on
        // the page): the style lost nothing of it.
        if (float(s.pixels) > kGained * float(n.pixels)) continue;
        const bool seen = s.surrounded && float(s.pixels) >= kSeen * float(n.pixels);
        const float kept = seen ? s.contrast : 1.0f;
        if (kept >= std::min(n.contrast, kTarget) * kSlack) continue;
        out.shortOf.push_back({i, n.pixels, n.contrast, kept});
    }
    return out;
}

std::string OverlayLegibility::summary() const
{
    if (!mismatch.empty()) return "not judged (" + mismatch + ")";
    std::string out = std::to_string(shortOf.size()) + " of " + std::to_string(judged) +
                      " short of their contrast";
    if (shortOf.empty()) return out;
    // The worst: the most contrast lost against what was to keep.
    const auto worst = std::max_element(shortOf.begin(), shortOf.end(), [](auto& a, auto& b) {
        return std::min(a.native, kTarget) / a.styled < std::min(b.native, kTarget) / b.styled;
    });
    char text[160];
    std::snprintf(text, sizeof text, " (worst: draw %zu, %u px, %.1f:1 natively, %.1f:1)",
                  worst->index, worst->pixels, worst->native, worst->styled);
    return out + text;
}

} // namespace nprgl
