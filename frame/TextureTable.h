// What the tracker knows of each texture object's level 0: one record per texture.
#pragma once

#include "frame/TextureImage.h"
#include "shim/Api.h"

#include <glm/glm.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>

namespace nprgl {

// Level 0 of one 2D texture object, as its uploads made it (Mesa keeps one gl_texture_object
// per name; this is the part of it the hold policy and the styles ask about).
struct TextureRecord {
    // XXH3 of the uploaded image with its shape, chained with each part uploaded since (where
    // it went and its pixels); 0: content not known.
    uint64_t hash = 0;
    std::optional<glm::vec3> mean; // its mean colour, where known
    float cutFeature = 0.0f;       // TextureImage::cutFeature; 0: not known
    std::optional<glm::ivec2> size; // as glTexImage2D gave it (glTexStorage2D's is not followed)
    TextureAlpha alpha = TextureAlpha::FromAlpha; // by its internal format
    bool opaque = false;      // alpha 1 everywhere
    bool alphaOnly = false;   // GL_ALPHA: GL_REPLACE keeps the fragment's colour
    bool depth = false;       // GL_DEPTH_COMPONENT or GL_DEPTH_STENCIL: a shadow map
    bool filledLater = false; // made without pixels, no part below alpha 1 filled since
    // Every texel is what the stream's uploads put there (or undefined, before any): false
    // once the framebuffer was copied or rendered into it, or pixels came from a buffer.
    bool known = false;
};

// The records by GL name, and the cube maps' face means. Fed the bound texture of each
// upload; asked per draw (no record: nothing is known, every answer is the default's).
class TextureTable {
public:
    // glTexImage2D of level 0 (`bytes` of pixels; none: content not known here).
    void image2D(GLuint texture, GLint internalFormat, GLsizei width, GLsizei height,
                 GLenum format, GLenum type, const void* pixels, size_t bytes);
    // glCopyTexImage2D or glTexStorage2D of level 0: made in `internalFormat`, content not
    // known (`empty`: glTexSubImage2D fills it).
    void storage2D(GLuint texture, GLenum internalFormat, bool empty);
    // glTexSubImage2D into level 0, at (x, y).
    void subImage2D(GLuint texture, GLint x, GLint y, GLsizei width, GLsizei height,
                    GLenum format, GLenum type, const void* pixels, size_t bytes);
    // Level 0 written by GL itself (glCopyTexSubImage2D, or attached to a framebuffer): its
    // content is no longer known.
    void overwritten(GLuint texture);
    // Level 0 of face (0..5: +X -X +Y -Y +Z -Z) of a cube map.
    void cubeFace(GLuint cube, int face, GLsizei width, GLsizei height, GLenum format,
                  GLenum type, const void* pixels, size_t bytes);

    // Null when nothing was uploaded to it.
    const TextureRecord* find(GLuint texture) const;
    uint64_t hash(GLuint texture) const;
    bool opaque(GLuint texture) const;
    bool alphaOnly(GLuint texture) const;
    bool depth(GLuint texture) const;
    float cutFeature(GLuint texture) const;
    const glm::vec3* mean(GLuint texture) const;
    // The mean of the faces whose mean is known; false: none is.
    bool cubeMean(GLuint cube, glm::vec3& mean) const;
    // Texture object 0 has a level 0 image (it is then drawn, as styles::kDefaultTexture).
    bool defaultImage() const { return mDefaultImage; }

private:
    std::unordered_map<GLuint, TextureRecord> mTextures;
    // Each face's mean with w 1 where known.
    std::unordered_map<GLuint, std::array<glm::vec4, 6>> mCubeFaces;
    bool mDefaultImage = false;
};

} // namespace nprgl
