// OverlayLegibility: a 2D draw's contrast, the --overlays line format, and the rule.
#include "common/OverlayLegibility.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace nprgl {

namespace {

// sRGB component to linear light, by 8-bit value.
const std::array<double, 256>& linearTable()
{
    static const std::array<double, 256> table = [] {
        std::array<double, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const double c = i / 255.0;
            t[size_t(i)] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
        }
        return t;
    }();
    return table;
}

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
    const auto& t = linearTable();
    return 0.2126 * t[rgb[0]] + 0.7152 * t[rgb[1]] + 0.0722 * t[rgb[2]];
}

float OverlayLegibility::ratio(double l1, double l2)
{
    const double hi = std::max(l1, l2), lo = std::min(l1, l2);
    return float((hi + 0.05) / (lo + 0.05));
}

OverlayDraw OverlayLegibility::measure(const uint8_t* before, const uint8_t* after, int width,
                                       int height)
{
    OverlayDraw d;
    int x0 = width, y0 = height, x1 = -1, y1 = -1;
    double fg = 0.0;
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 4;
            if (!changed(before + i, after + i)) continue;
            ++d.pixels;
            fg += luminance(after + i);
            x0 = std::min(x0, x), x1 = std::max(x1, x);
            y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    }
    if (d.pixels == 0) return d;
    // The changed pixels of the box around them grown by kRing, grown by kRing along rows
    // and then along columns: a square neighbourhood.
    x0 = std::max(0, x0 - kRing), y0 = std::max(0, y0 - kRing);
    x1 = std::min(width - 1, x1 + kRing), y1 = std::min(height - 1, y1 + kRing);
    const int w = x1 - x0 + 1, h = y1 - y0 + 1;
    std::vector<uint8_t> mine(size_t(w) * size_t(h)), rows(mine.size()), near(mine.size());
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t i = (size_t(y + y0) * size_t(width) + size_t(x + x0)) * 4;
            mine[size_t(y) * size_t(w) + size_t(x)] = changed(before + i, after + i);
        }
    }
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            bool any = false;
            for (int k = std::max(0, x - kRing); k <= std::min(w - 1, x + kRing) && !any; ++k)
                any = mine[size_t(y) * size_t(w) + size_t(k)] != 0;
            rows[size_t(y) * size_t(w) + size_t(x)] = any;
        }
    }
    double bg = 0.0;
    uint64_t ring = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t m = size_t(y) * size_t(w) + size_t(x);
            if (mine[m]) continue;
            bool any = false;
            for (int k = std::max(0, y - kRing); k <= std::min(h - 1, y + kRing) && !any; ++k)
                any = rows[size_t(k) * size_t(w) + size_t(x)] != 0;
            if (!any) continue;
            ++ring;
            bg += luminance(after + (size_t(y + y0) * size_t(width) + size_t(x + x0)) * 4);
        }
    }
    if (ring == 0) return d;
    d.surrounded = true;
    d.contrast = ratio(fg / d.pixels, bg / double(ring));
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
