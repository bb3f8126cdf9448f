// What the tracker knows of each texture object's level 0: one record per texture.
#include "frame/TextureTable.h"

#include <xxhash.h>

#include <algorithm>
#include <iterator>

namespace nprgl {

namespace {

// A format of depth (a shadow map), given as glTexImage2D's format or as an internal format.
bool depthFormat(GLenum format)
{
    switch (format) {
    case GL_DEPTH_COMPONENT:
    case GL_DEPTH_COMPONENT16:
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH_STENCIL:
    case GL_DEPTH24_STENCIL8:
    case GL_DEPTH32F_STENCIL8: return true;
    default: return false;
    }
}

} // namespace

void TextureTable::image2D(GLuint texture, GLint internalFormat, GLsizei width, GLsizei height,
                           GLenum format, GLenum type, const void* pixels, size_t bytes)
{
    if (texture == 0) mDefaultImage = width > 0 && height > 0;
    TextureRecord& t = mTextures[texture];
    t = {};
    t.depth = depthFormat(format);
    t.alphaOnly = format == GL_ALPHA;
    t.size = glm::ivec2(width, height);
    t.alpha = textureAlpha(internalFormat);
    // No pixels (storage only, or from a pixel-unpack buffer): the content is not known here.
    // Storage alone is filled by glTexSubImage2D next (SFML's way): those decide.
    if (!pixels || bytes == 0) {
        t.filledLater = !pixels;
        t.known = !pixels;
        return;
    }
    t.known = true;
    const TextureImage image(width, height, format, type, pixels, bytes, t.alpha);
    t.opaque = image.opaque();
    glm::vec3 mean;
    if (image.mean(mean)) t.mean = mean;
    const float feature = image.cutFeature({width, height});
    t.cutFeature = feature > 0.0f ? feature : 0.0f;
    const uint64_t shape[4] = {uint64_t(width), uint64_t(height), format, type};
    const uint64_t hash = XXH3_64bits_withSeed(pixels, bytes, XXH3_64bits(shape, sizeof shape));
    t.hash = hash == 0 ? 1 : hash;
}

void TextureTable::storage2D(GLuint texture, GLenum internalFormat, bool empty)
{
    // Nothing of an earlier upload holds any more. Formats without alpha read alpha 1.
    TextureRecord& t = mTextures[texture];
    t = {};
    t.filledLater = empty;
    t.known = empty;
    t.alpha = textureAlpha(GLint(internalFormat));
    t.depth = depthFormat(internalFormat);
    const GLenum alphaOnly[] = {GL_ALPHA, GL_ALPHA4, GL_ALPHA8, GL_ALPHA12, GL_ALPHA16};
    t.alphaOnly = std::find(std::begin(alphaOnly), std::end(alphaOnly), internalFormat) !=
                  std::end(alphaOnly);
    t.opaque = t.depth || t.alpha == TextureAlpha::One;
}

void TextureTable::overwritten(GLuint texture)
{
    auto it = mTextures.find(texture);
    if (it == mTextures.end()) return;
    it->second.known = false;
    it->second.hash = 0;
    it->second.mean.reset();
}

void TextureTable::subImage2D(GLuint texture, GLint x, GLint y, GLsizei width, GLsizei height,
                              GLenum format, GLenum type, const void* pixels, size_t bytes)
{
    // Into a texture never made here nothing is known to change.
    auto it = mTextures.find(texture);
    if (it == mTextures.end()) return;
    TextureRecord& t = it->second;
    // Into storage made without pixels: opaque while every part filled so far is (parts never
    // filled are undefined in GL). Into an image of known pixels: a part with alpha below 1
    // makes it not opaque; an opaque part changes nothing. The internal format decides which
    // of the part's channels is its alpha.
    const TextureImage image(width, height, format, type, pixels, bytes, t.alpha);
    const bool opaque = t.alpha == TextureAlpha::One || (pixels && bytes != 0 && image.opaque());
    // Its content is the upload and the parts since: a texture filled part by part (SFML's
    // way, glyph caches) is known by them, so the styles can cache what they make of it.
    t.known = t.known && pixels && bytes != 0;
    if (t.known) {
        const uint64_t part[7] = {t.hash, uint64_t(x), uint64_t(y), uint64_t(width),
                                  uint64_t(height), format, type};
        const uint64_t hash = XXH3_64bits_withSeed(pixels, bytes, XXH3_64bits(part, sizeof part));
        t.hash = hash == 0 ? 1 : hash;
    } else {
        t.hash = 0;
    }
    t.mean.reset();
    // The finest cut of the parts filled (an image given in parts, or by parts only).
    const float feature = t.size ? image.cutFeature(*t.size) : 0.0f;
    if (feature > 0.0f && (t.cutFeature <= 0.0f || feature < t.cutFeature)) {
        t.cutFeature = feature;
    }
    if (!opaque) {
        t.opaque = false;
        t.filledLater = false;
    } else if (t.filledLater) {
        t.opaque = true;
    }
}

void TextureTable::cubeFace(GLuint cube, int face, GLsizei width, GLsizei height,
                            GLenum format, GLenum type, const void* pixels, size_t bytes)
{
    if (face < 0 || face >= 6) return;
    glm::vec3 mean;
    mCubeFaces[cube][size_t(face)] =
        TextureImage(width, height, format, type, pixels, bytes).mean(mean)
            ? glm::vec4(mean, 1.0f)
            : glm::vec4(0.0f);
}

const TextureRecord* TextureTable::find(GLuint texture) const
{
    auto it = mTextures.find(texture);
    return it == mTextures.end() ? nullptr : &it->second;
}

uint64_t TextureTable::hash(GLuint texture) const
{
    const TextureRecord* t = find(texture);
    return t ? t->hash : 0;
}

bool TextureTable::opaque(GLuint texture) const
{
    const TextureRecord* t = find(texture);
    return t && t->opaque;
}

bool TextureTable::alphaOnly(GLuint texture) const
{
    const TextureRecord* t = find(texture);
    return t && t->alphaOnly;
}

bool TextureTable::depth(GLuint texture) const
{
    const TextureRecord* t = find(texture);
    return t && t->depth;
}

float TextureTable::cutFeature(GLuint texture) const
{
    const TextureRecord* t = find(texture);
    return t ? t->cutFeature : 0.0f;
}

const glm::vec3* TextureTable::mean(GLuint texture) const
{
    const TextureRecord* t = find(texture);
    return t && t->mean ? &*t->mean : nullptr;
}

bool TextureTable::cubeMean(GLuint cube, glm::vec3& mean) const
{
    auto it = mCubeFaces.find(cube);
    if (it == mCubeFaces.end()) return false;
    glm::vec4 sum(0.0f);
    for (const glm::vec4& face : it->second) sum += face;
    if (sum.w == 0.0f) return false;
    mean = glm::vec3(sum) / sum.w;
    return true;
}

} // namespace nprgl
