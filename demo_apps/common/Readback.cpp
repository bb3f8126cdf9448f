#include "Readback.h"

#include <algorithm>
#include <cstring>

namespace demo {

void readFramebuffer(const GlApi& gl, int width, int height, Image& image)
{
    image.width = width;
    image.height = height;
    size_t rowBytes = static_cast<size_t>(width) * 3;
    image.rgb.resize(rowBytes * height);

    // RGB rows are not 4-byte aligned in general, so pack tightly and put the app's value back.
    GLint oldAlignment = 4;
    gl.getIntegerv(GL_PACK_ALIGNMENT, &oldAlignment);
    gl.pixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.readPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, image.rgb.data());
    gl.pixelStorei(GL_PACK_ALIGNMENT, oldAlignment);

    // GL returns the bottom row first; PNG wants the top row first.
    for (int y = 0; y < height / 2; ++y) {
        uint8_t* top = image.rgb.data() + rowBytes * y;
        uint8_t* bottom = image.rgb.data() + rowBytes * (height - 1 - y);
        std::swap_ranges(top, top + rowBytes, bottom);
    }
}

} // namespace demo
