#pragma once

#include "Image.h"

#include <string>

namespace demo {

// Writes an 8-bit RGB PNG; returns false and sets error on failure.
bool writePng(const std::string& path, const Image& image, std::string& error);

} // namespace demo
