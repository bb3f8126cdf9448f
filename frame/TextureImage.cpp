#include "frame/TextureImage.h"

#include <algorithm>
#include <iterator>
#include <vector>

namespace nprgl {

TextureAlpha textureAlpha(GLint internalFormat)
{
    static constexpr GLenum noAlpha[] = {
        1, 3, GL_RGB, GL_RGB4, GL_RGB5, GL_RGB8, GL_RGB10, GL_RGB12, GL_RGB16, GL_R3_G3_B2,
        GL_SRGB, GL_SRGB8, GL_LUMINANCE, GL_LUMINANCE4, GL_LUMINANCE8, GL_LUMINANCE12,
        GL_LUMINANCE16, GL_RED, GL_R8, GL_R16, GL_RG, GL_RG8, GL_RG16};
    static constexpr GLenum intensity[] = {GL_INTENSITY,   GL_INTENSITY4,  GL_INTENSITY8,
                                           GL_INTENSITY12, GL_INTENSITY16, GL_INTENSITY16F_ARB,
                                           GL_INTENSITY32F_ARB};
    const GLenum format = GLenum(internalFormat);
    if (std::find(std::begin(noAlpha), std::end(noAlpha), format) != std::end(noAlpha)) {
        return TextureAlpha::One;
    }
    if (std::find(std::begin(intensity), std::end(intensity), format) != std::end(intensity)) {
        return TextureAlpha::FromIntensity;
    }
    return TextureAlpha::FromAlpha;
}

TextureImage::TextureImage(GLsizei width, GLsizei height, GLenum format, GLenum type,
                           const void* pixels, size_t bytes, TextureAlpha alpha)
    : mWidth(width), mHeight(height), mFormat(format), mType(type),
      mPixels(static_cast<const unsigned char*>(pixels)), mBytes(pixels ? bytes : 0), mAlpha(alpha)
{
}

int TextureImage::channels(bool& hasAlpha) const
{
    hasAlpha = false;
    if (mType != GL_UNSIGNED_BYTE) return 0;
    switch (mFormat) {
    case GL_RGBA: case GL_BGRA: hasAlpha = true; return 4;
    case GL_RGB: case GL_BGR: return 3;
    case GL_LUMINANCE_ALPHA: hasAlpha = true; return 2;
    case GL_ALPHA: hasAlpha = true; return 1;
    case GL_LUMINANCE: return 1;
    default: return 0;
    }
}

size_t TextureImage::rowBytes(int channels) const
{
    if (!mPixels || channels <= 0 || mWidth <= 0 || mHeight <= 0) return 0;
    // Rows as the recorder laid them out (the unpack alignment's padding included).
    const size_t row = mBytes / size_t(mHeight);
    return row >= size_t(mWidth) * size_t(channels) ? row : 0;
}

int TextureImage::alphaByte(int channels, bool hasAlpha) const
{
    if (channels <= 0 || mAlpha == TextureAlpha::One) return -1;
    if (mAlpha == TextureAlpha::FromAlpha) return hasAlpha ? channels - 1 : -1;
    // The intensity is the pixels' red (luminance) channel; GL_ALPHA pixels have none (0).
    if (mFormat == GL_ALPHA) return -1;
    return mFormat == GL_BGR || mFormat == GL_BGRA ? 2 : 0;
}

bool TextureImage::opaque() const
{
    if (mAlpha == TextureAlpha::One) return true;
    const bool noAlpha =
        mFormat == GL_RGB || mFormat == GL_BGR || mFormat == GL_LUMINANCE || mFormat == GL_RED;
    if (mAlpha == TextureAlpha::FromAlpha && noAlpha) return true;
    bool hasAlpha = false;
    const int n = channels(hasAlpha);
    const int a = alphaByte(n, hasAlpha);
    const size_t row = a >= 0 ? rowBytes(n) : 0;
    if (row == 0) return false;
    for (GLsizei y = 0; y < mHeight; ++y) {
        const unsigned char* p = mPixels + size_t(y) * row + size_t(a);
        for (GLsizei x = 0; x < mWidth; ++x) {
            if (p[size_t(x) * size_t(n)] != 255) return false;
        }
    }
    return true;
}

bool TextureImage::mean(glm::vec3& mean) const
{
    bool hasAlpha = false;
    const int n = channels(hasAlpha);
    // Colour formats only: an alpha texture has no colour of its own.
    const size_t row = mFormat != GL_ALPHA ? rowBytes(n) : 0;
    if (row == 0) return false;
    const int stepX = std::max(1, int(mWidth) / 64), stepY = std::max(1, int(mHeight) / 64);
    glm::dvec3 sum(0.0);
    size_t count = 0;
    for (int y = 0; y < mHeight; y += stepY) {
        for (int x = 0; x < mWidth; x += stepX) {
            const unsigned char* t = mPixels + size_t(y) * row + size_t(x) * size_t(n);
            glm::dvec3 c = n >= 3 ? glm::dvec3(t[0], t[1], t[2]) : glm::dvec3(t[0]);
            if (mFormat == GL_BGRA || mFormat == GL_BGR) std::swap(c.r, c.b);
            sum += c;
            ++count;
        }
    }
    mean = glm::vec3(sum / (255.0 * double(count)));
    return true;
}

float TextureImage::cutFeature(glm::ivec2 level) const
{
    bool hasAlpha = false;
    const int n = channels(hasAlpha);
    const int a = alphaByte(n, hasAlpha);
    const size_t row = a >= 0 ? rowBytes(n) : 0;
    if (row == 0 || level.x <= 0 || level.y <= 0) return 0.0f;
    const unsigned char* alpha = mPixels + a;
    // The runs of the lines walked, each as a fraction of its line. Medians, not means: a
    // font's few long bars would hide its thin strokes, a tree's trunk its twigs.
    std::vector<float> kept, enclosed;
    bool anyClear = false;
    // count texels of a line of the level `across` texels long.
    auto walk = [&](const unsigned char* first, size_t stride, int count, int across) {
        int run = 0, clearRun = 0;
        bool inKept = false, seenKept = false;
        for (int i = 0; i <= count; ++i) {
            const bool k = i < count && first[size_t(i) * stride] >= 128;
            if (k && !inKept && seenKept && clearRun > 0) {
                enclosed.push_back(float(clearRun) / float(across));
            }
            if (!k && inKept) kept.push_back(float(run) / float(across));
            if (k) {
                run = inKept ? run + 1 : 1;
                seenKept = true;
            } else if (i < count) {
                clearRun = inKept ? 1 : clearRun + 1;
                anyClear = true;
            }
            inKept = k;
        }
    };
    const int stepY = std::max(1, int(mHeight) / 64), stepX = std::max(1, int(mWidth) / 64);
    for (int y = 0; y < mHeight; y += stepY) {
        walk(alpha + size_t(y) * row, size_t(n), mWidth, level.x);
    }
    for (int x = 0; x < mWidth; x += stepX) {
        walk(alpha + size_t(x) * size_t(n), row, mHeight, level.y);
    }
    if (kept.empty()) return 0.0f;
    if (!anyClear) return kKeptWhole; // its shape is its polygons
    auto median = [](std::vector<float>& runs) {
        auto middle = runs.begin() + std::ptrdiff_t(runs.size() / 2);
        std::nth_element(runs.begin(), middle, runs.end());
        return *middle;
    };
    const float keptMedian = median(kept);
    return enclosed.empty() ? keptMedian : std::min(keptMedian, median(enclosed));
}

} // namespace nprgl
