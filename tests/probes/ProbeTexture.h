#pragma once

// ProbeTexture: a probe's generated RGB texels as a GL texture.

#include <GL/gl.h>

#include <cstdint>
#include <vector>

namespace nprgl::probes {

// A size x size GL_RGB texture of tightly packed texels, filtered by `filter`; left unbound.
inline GLuint uploadRgbTexture(const std::vector<uint8_t>& texels, int size, GLint filter)
{
    GLuint name = 0;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, size, size, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    glBindTexture(GL_TEXTURE_2D, 0);
    return name;
}

} // namespace nprgl::probes
