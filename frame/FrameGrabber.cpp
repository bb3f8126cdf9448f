#include "frame/FrameGrabber.h"

#include "common/Log.h"
#include "common/PngImage.h"
#include "shim/RealGl.h"

namespace nprgl {

namespace {

// Pack state glReadPixels obeys; saved and set to defaults around our read.
constexpr GLenum kPackParams[] = {
    GL_PACK_SWAP_BYTES,   GL_PACK_LSB_FIRST,  GL_PACK_ROW_LENGTH,  GL_PACK_IMAGE_HEIGHT,
    GL_PACK_SKIP_ROWS,    GL_PACK_SKIP_PIXELS, GL_PACK_SKIP_IMAGES, GL_PACK_ALIGNMENT,
};
constexpr GLint kPackDefaults[] = {0, 0, 0, 0, 0, 0, 0, 4};

} // namespace

bool FrameGrabber::writeFrame(const ContextCaps& caps, int width, int height,
                              const std::string& path)
{
    const GlDispatch& gl = gRealGl;
    if (caps.es || width <= 0 || height <= 0) {
        NPRGL_WARN("cannot take a screenshot of this context (%s); skipping %s",
                   caps.es ? "OpenGL ES" : "unknown size", path.c_str());
        return false;
    }
    if (!caps.core) {
        // glReadBuffer would be compiled into the list instead of executed.
        GLint listIndex = 0;
        gl.glGetIntegerv(GL_LIST_INDEX, &listIndex);
        if (listIndex != 0) {
            NPRGL_WARN("frame ends inside glNewList; skipping screenshot %s", path.c_str());
            return false;
        }
    }

    GLint pack[std::size(kPackParams)];
    for (size_t i = 0; i < std::size(kPackParams); ++i) {
        gl.glGetIntegerv(kPackParams[i], &pack[i]);
        if (pack[i] != kPackDefaults[i]) gl.glPixelStorei(kPackParams[i], kPackDefaults[i]);
    }
    GLint packBuffer = 0, readFramebuffer = 0, readBuffer = 0;
    gl.glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
    if (packBuffer) gl.glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    auto bindFramebuffer = caps.atLeast(3, 0)
        ? reinterpret_cast<PFNGLBINDFRAMEBUFFERPROC>(realProcAddress("glBindFramebuffer"))
        : nullptr;
    if (bindFramebuffer) {
        gl.glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer);
        if (readFramebuffer) bindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    }
    gl.glGetIntegerv(GL_READ_BUFFER, &readBuffer);
    const GLenum wanted = caps.doubleBuffered ? GL_BACK : GL_FRONT;
    if (GLenum(readBuffer) != wanted) gl.glReadBuffer(wanted);

    PngImage image;
    image.width = width;
    image.height = height;
    image.rgba.resize(size_t(width) * height * 4);
    gl.glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());

    if (GLenum(readBuffer) != wanted) gl.glReadBuffer(readBuffer);
    if (readFramebuffer) bindFramebuffer(GL_READ_FRAMEBUFFER, readFramebuffer);
    if (packBuffer) gl.glBindBuffer(GL_PIXEL_PACK_BUFFER, packBuffer);
    for (size_t i = 0; i < std::size(kPackParams); ++i) {
        if (pack[i] != kPackDefaults[i]) gl.glPixelStorei(kPackParams[i], pack[i]);
    }

    image.flipRows();
    image.makeOpaque();
    std::string error;
    if (!image.write(path, error)) {
        NPRGL_ERROR("screenshot: %s", error.c_str());
        return false;
    }
    NPRGL_DEBUG("screenshot %s (%dx%d)", path.c_str(), width, height);
    return true;
}

} // namespace nprgl
