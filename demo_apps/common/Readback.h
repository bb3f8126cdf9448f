#pragma once

#include "GlApi.h"
#include "Image.h"

namespace demo {

// Reads the current read buffer as RGB into image (resized to width x height), top row first.
void readFramebuffer(const GlApi& gl, int width, int height, Image& image);

} // namespace demo
