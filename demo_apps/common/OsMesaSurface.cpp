#include "OsMesaSurface.h"

#include "Readback.h"

namespace demo {

OsMesaSurface::~OsMesaSurface()
{
    if (context_ != nullptr) {
        gl_.osMesaDestroyContext(context_);
    }
}

bool OsMesaSurface::open(const Options& options, std::string& error)
{
    width_ = options.width;
    height_ = options.height;
    context_ = gl_.osMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (context_ == nullptr) {
        error = "OSMesaCreateContextExt failed";
        return false;
    }
    buffer_.assign(static_cast<size_t>(width_) * height_, 0);
    if (!gl_.osMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width_, height_)) {
        error = "OSMesaMakeCurrent failed";
        return false;
    }
    return true;
}

void OsMesaSurface::finishFrame()
{
    // glFinish marks the end of an OSMesa frame for interposers, so call it exactly once here.
    gl_.finish();
}

void OsMesaSurface::readPixels(Image& image)
{
    readFramebuffer(gl_, width_, height_, image);
}

} // namespace demo
