#pragma once

#include <cstddef>
#include <cstdint>

namespace nprgl {

// How many values a glLight/glMaterial/glFog/glTexParameter/... setter reads for a pname
// (1 for names it does not know: the driver refuses those, and reading more could fault).
size_t pnameCount(uint32_t pname);

// Bytes read by glCallLists(n, type, lists).
size_t callListsBytes(int n, uint32_t type);

// Bytes per index of glDrawElements (0 for an invalid type).
size_t indexBytes(uint32_t type);

// The pixel-unpack state that lays out an image in client memory.
struct UnpackState {
    int alignment = 4;
    int rowLength = 0;
    int imageHeight = 0;
    int skipPixels = 0;
    int skipRows = 0;
    int skipImages = 0;
};

// Bytes of client memory glTexImage*/glDrawPixels/glBitmap read, from the pointer, for an
// image of width x height x depth (0 for invalid arguments).
size_t imageBytes(uint32_t format, uint32_t type, int width, int height, int depth,
                  const UnpackState& unpack);

// Components per element for a client array of `size` (GL_BGRA counts as 4).
size_t arrayElementBytes(int size, uint32_t type);

} // namespace nprgl
