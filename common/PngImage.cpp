#include "common/PngImage.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <png.h>

namespace nprgl {

bool PngImage::write(const std::string& path, std::string& error) const
{
    if (width <= 0 || height <= 0 || rgba.size() != size_t(width) * height * 4) {
        error = "invalid image size";
        return false;
    }
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGBA;
    // Written beside and renamed into place: whoever watches for the file (a viewer, a
    // script waiting for frame N) never reads half a picture.
    const std::string partial = path + ".part";
    if (!png_image_write_to_file(&image, partial.c_str(), 0, rgba.data(), 0, nullptr)) {
        error = "cannot write " + path + ": " + image.message;
        std::remove(partial.c_str());
        return false;
    }
    if (std::rename(partial.c_str(), path.c_str()) != 0) {
        error = "cannot write " + path + ": " + std::strerror(errno);
        std::remove(partial.c_str());
        return false;
    }
    return true;
}

bool PngImage::read(const std::string& path, PngImage& out, std::string& error)
{
    png_image image;
    std::memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str())) {
        error = "cannot read " + path + ": " + image.message;
        return false;
    }
    image.format = PNG_FORMAT_RGBA;
    PngImage result;
    result.width = static_cast<int>(image.width);
    result.height = static_cast<int>(image.height);
    result.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, result.rgba.data(), 0, nullptr)) {
        error = "cannot decode " + path + ": " + image.message;
        png_image_free(&image);
        return false;
    }
    out = std::move(result);
    return true;
}

void PngImage::makeOpaque()
{
    for (size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;
}

void PngImage::flipRows()
{
    const size_t stride = size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y) {
        std::swap_ranges(rgba.begin() + y * stride, rgba.begin() + (y + 1) * stride,
                         rgba.begin() + (height - 1 - y) * stride);
    }
}

} // namespace nprgl
