#include "common/FrameFidelity.h"

#include "common/SrgbLinear.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace nprgl {

namespace {

float labF(float t)
{
    constexpr float kE = 216.0f / 24389.0f, kK = 24389.0f / 27.0f;
    return t > kE ? std::cbrt(t) : (kK * t + 16.0f) / 116.0f;
}

struct LabSum {
    double l = 0.0, a = 0.0, b = 0.0;
    void add(const Lab& c)
    {
        l += c.l;
        a += c.a;
        b += c.b;
    }
    FrameFidelity::Tone tone(uint32_t n) const
    {
        FrameFidelity::Tone t;
        if (n == 0) return t;
        const double ma = a / n, mb = b / n;
        t.lightness = float(l / n);
        t.chroma = float(std::hypot(ma, mb));
        double h = std::atan2(mb, ma) * 180.0 / M_PI;
        t.hue = float(h < 0.0 ? h + 360.0 : h);
        return t;
    }
};

struct Accumulator {
    FrameFidelity::Object object;
    LabSum native, styled;
    double deltaE = 0.0;
};

float hueDistance(float x, float y)
{
    const float d = std::fabs(x - y);
    return std::min(d, 360.0f - d);
}

} // namespace

Lab Lab::fromSrgb(const uint8_t* rgb)
{
    const float r = srgbLinear(rgb[0]), g = srgbLinear(rgb[1]), b = srgbLinear(rgb[2]);
    const float x = (0.4124564f * r + 0.3575761f * g + 0.1804375f * b) / 0.95047f;
    const float y = 0.2126729f * r + 0.7151522f * g + 0.0721750f * b;
    const float z = (0.0193339f * r + 0.1191920f * g + 0.9503041f * b) / 1.08883f;
    const float fx = labF(x), fy = labF(y), fz = labF(z);
    return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

float Lab::deltaE(const Lab& x, const Lab& y)
{
    return std::sqrt((x.l - y.l) * (x.l - y.l) + (x.a - y.a) * (x.a - y.a) +
                     (x.b - y.b) * (x.b - y.b));
}

void FrameFidelity::clearColour(const PngImage& native, uint8_t rgb[3])
{
    std::map<uint32_t, uint32_t> counts;
    const int w = native.width, h = native.height;
    auto count = [&](int x, int y) {
        const uint8_t* p = &native.rgba[(size_t(y) * w + x) * 4];
        ++counts[uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]];
    };
    for (int x = 0; x < w; ++x) {
        count(x, 0);
        count(x, h - 1);
    }
    for (int y = 1; y + 1 < h; ++y) {
        count(0, y);
        count(w - 1, y);
    }
    uint32_t best = 0, most = 0;
    for (const auto& [colour, n] : counts) {
        if (n > most) most = n, best = colour;
    }
    rgb[0] = uint8_t(best >> 16);
    rgb[1] = uint8_t(best >> 8);
    rgb[2] = uint8_t(best);
}

uint32_t FrameFidelity::paletteFailures() const
{
    uint32_t n = 0;
    for (const Object& o : objects) n += o.judged && !o.paletteOk();
    return n;
}

uint32_t FrameFidelity::paletteJudged() const
{
    uint32_t n = 0;
    for (const Object& o : objects) n += o.judged;
    return n;
}

bool FrameFidelity::measure(const PngImage& native, const PngImage& styled, const PngImage& ids,
                            bool makeDiff, FrameFidelity& out, std::string& error,
                            const PngImage& shading, const uint8_t* clear)
{
    out = FrameFidelity();
    const int w = native.width, h = native.height;
    if (w <= 0 || h <= 0 || styled.width != w || styled.height != h ||
        (!ids.rgba.empty() && (ids.width != w || ids.height != h)) ||
        (!shading.rgba.empty() && (shading.width != w || shading.height != h))) {
        error = "the frames differ in size (" + std::to_string(w) + "x" + std::to_string(h) +
                " natively, " + std::to_string(styled.width) + "x" +
                std::to_string(styled.height) + " styled)";
        return false;
    }
    if (clear) std::copy(clear, clear + 3, out.clear);
    else clearColour(native, out.clear);
    out.clearFromStream = clear != nullptr;
    const Lab clearLab = Lab::fromSrgb(out.clear);
    if (makeDiff) {
        out.diff.width = 3 * w;
        out.diff.height = h;
        out.diff.rgba.assign(size_t(3 * w) * h * 4, 255);
    }
    // Per pixel: its colours and the object of the style's that covers it (0: none): an id
    // in the ids frame where the program's own frame shows something else.
    const size_t count = size_t(w) * h;
    std::vector<Lab> nativeLab(count), styledLab(count);
    std::vector<uint32_t> idAt(count, 0);
    std::vector<bool> drawnNatively(count);
    // The style's background: what it shows where the program drew nothing and no object
    // covers (the clear colour again, or a page); its mean tells a pixel lost to it.
    double bgL = 0.0, bgA = 0.0, bgB = 0.0;
    uint64_t bgCount = 0;
    for (size_t p = 0; p < count; ++p) {
        const uint8_t* n = &native.rgba[p * 4];
        nativeLab[p] = Lab::fromSrgb(n);
        styledLab[p] = Lab::fromSrgb(&styled.rgba[p * 4]);
        if (!ids.rgba.empty()) {
            const uint8_t* d = &ids.rgba[p * 4];
            if (d[0] != n[0] || d[1] != n[1] || d[2] != n[2]) idAt[p] = idOf(d);
        }
        drawnNatively[p] = Lab::deltaE(nativeLab[p], clearLab) > kDrawn;
        if (idAt[p] == 0 && !drawnNatively[p]) {
            bgL += styledLab[p].l, bgA += styledLab[p].a, bgB += styledLab[p].b;
            ++bgCount;
        }
    }
    const Lab background = bgCount ? Lab{float(bgL / bgCount), float(bgA / bgCount),
                                         float(bgB / bgCount)}
                                   : clearLab;
    std::unordered_map<uint32_t, Accumulator> perObject;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const size_t p = size_t(y) * w + x;
            const Lab& ln = nativeLab[p];
            const Lab& ls = styledLab[p];
            const uint32_t id = idAt[p];
            const bool nativeDrawn = drawnNatively[p];
            const float de = Lab::deltaE(ln, ls);
            // Up to rasterisation: the two may cover an edge or a speck a pixel apart.
            bool match = de <= kMatch;
            for (int dy = -1; dy <= 1 && !match; ++dy) {
                for (int dx = -1; dx <= 1 && !match; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                    match = Lab::deltaE(ln, styledLab[size_t(ny) * w + nx]) <= kMatch;
                }
            }
            const bool drawn = nativeDrawn || id != 0;
            out.nativeDrawn += nativeDrawn;
            out.drawn += drawn;
            out.matching += drawn && match;
            // Drawn natively; in the style no object there, and the background or page shows
            // where the program's pixel did not look like it (a dim fringe or a faint star
            // that looks like a dark page lost nothing one could see).
            const bool lost = nativeDrawn && id == 0 && !match &&
                              Lab::deltaE(ls, background) <= kMatch &&
                              Lab::deltaE(ln, background) > kMatch;
            out.missing += lost;
            if (id != 0) {
                Accumulator& a = perObject[id];
                if (a.object.pixels == 0) a.object.box = {x, y, x, y};
                a.object.id = id;
                ++a.object.pixels;
                a.deltaE += de;
                a.native.add(ln);
                a.styled.add(shading.rgba.empty() ? ls
                                                  : Lab::fromSrgb(&shading.rgba[p * 4]));
                auto& b = a.object.box;
                b = {std::min(b[0], x), std::min(b[1], y), std::max(b[2], x), std::max(b[3], y)};
            }
            if (makeDiff) {
                const uint8_t* n = &native.rgba[p * 4];
                const uint8_t* s = &styled.rgba[p * 4];
                uint8_t* d = out.diff.rgba.data();
                const size_t row = size_t(y) * 3 * w;
                std::copy(n, n + 3, d + (row + x) * 4);
                std::copy(s, s + 3, d + (row + w + x) * 4);
                uint8_t* m = d + (row + 2 * w + x) * 4;
                // Matching pixels dimmed grey; different ones red by how far; lost ones blue.
                const uint8_t grey = uint8_t(ln.l * 0.6f);
                if (lost) m[0] = 0, m[1] = 80, m[2] = 255;
                else if (!match && drawn) {
                    m[0] = uint8_t(std::min(255.0f, 120.0f + 3.0f * de)), m[1] = 0, m[2] = 0;
                } else m[0] = m[1] = m[2] = grey;
            }
        }
    }
    for (auto& [id, a] : perObject) {
        Object o = a.object;
        o.meanDeltaE = a.deltaE / o.pixels;
        o.native = a.native.tone(o.pixels);
        o.styled = a.styled.tone(o.pixels);
        o.judged = o.pixels >= kPaletteMinPixels;
        o.hueKept = o.native.chroma < kChromatic ||
                    hueDistance(o.native.hue, o.styled.hue) <= kHueKept;
        out.objects.push_back(o);
    }
    std::sort(out.objects.begin(), out.objects.end(),
              [](const Object& x, const Object& y) { return x.id < y.id; });
    // Lightness order: of two judged objects clearly apart natively, the lighter does not
    // become clearly the darker (a style that evens them, as cel bands do, keeps the order).
    for (Object& p : out.objects) {
        if (!p.judged) continue;
        for (const Object& q : out.objects) {
            if (!q.judged || &p == &q) continue;
            const float apart = p.native.lightness - q.native.lightness;
            if (std::fabs(apart) < kLighterBy) continue;
            const float now = p.styled.lightness - q.styled.lightness;
            if (apart > 0.0f ? now < -kOrderSlack : now > kOrderSlack) p.orderKept = false;
        }
    }
    return true;
}

} // namespace nprgl
