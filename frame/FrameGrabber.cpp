#include "frame/FrameGrabber.h"

#include "common/Log.h"
#include "common/PngImage.h"
#include "shim/OwnGlCalls.h"
#include "shim/RealGl.h"

namespace nprgl {

namespace {

// Pack state glReadPixels obeys; saved and set to defaults around our read. Each is asked only
// of a context that knows it (an unknown name is a GL error): `gl` is the desktop GL version
// that has it, `es` the OpenGL ES one (0: ES has none).
struct PackParam {
    GLenum name;
    GLint defaultValue;
    int gl, es;
};
constexpr PackParam kPackParams[] = {
    {GL_PACK_SWAP_BYTES, 0, 10, 0},   {GL_PACK_LSB_FIRST, 0, 10, 0},
    {GL_PACK_ROW_LENGTH, 0, 10, 30},  {GL_PACK_IMAGE_HEIGHT, 0, 12, 0},
    {GL_PACK_SKIP_ROWS, 0, 10, 30},   {GL_PACK_SKIP_PIXELS, 0, 10, 30},
    {GL_PACK_SKIP_IMAGES, 0, 12, 0},  {GL_PACK_ALIGNMENT, 4, 10, 10},
};

bool knows(const ContextCaps& caps, int gl, int es)
{
    const int need = caps.es ? es : gl;
    return need != 0 && caps.atLeast(need / 10, need % 10);
}

} // namespace

const char* FrameGrabber::cannotRead(const ContextCaps& caps, int width, int height)
{
    if (caps.major == 0) return "no GL version";
    if (width <= 0 || height <= 0) return "unknown size";
    if (!caps.core && !caps.es) {
        // glReadBuffer would be compiled into the list instead of executed.
        GLint listIndex = 0;
        gRealGl.glGetIntegerv(GL_LIST_INDEX, &listIndex);
        if (listIndex != 0) return "the frame ends inside glNewList";
    }
    return nullptr;
}

GLenum FrameGrabber::readFrame(const ContextCaps& caps, int width, int height, uint8_t* rgba)
{
    const GlDispatch& gl = gRealGl;
    // A read the driver refuses (an incomplete read framebuffer...) is nprgl's error, not the
    // program's.
    OwnGlCalls own;
    GLint pack[std::size(kPackParams)] = {};
    for (size_t i = 0; i < std::size(kPackParams); ++i) {
        const PackParam& p = kPackParams[i];
        if (!knows(caps, p.gl, p.es)) continue;
        gl.glGetIntegerv(p.name, &pack[i]);
        if (pack[i] != p.defaultValue) gl.glPixelStorei(p.name, p.defaultValue);
    }
    GLint packBuffer = 0, readFramebuffer = 0, readBuffer = 0;
    if (knows(caps, 21, 30)) gl.glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
    if (packBuffer) gl.glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    auto bindFramebuffer = knows(caps, 30, 20)
        ? reinterpret_cast<PFNGLBINDFRAMEBUFFERPROC>(realProcAddress("glBindFramebuffer"))
        : nullptr;
    if (bindFramebuffer) {
        // ES 2 has one framebuffer binding for drawing and reading.
        const bool one = caps.es && caps.major < 3;
        gl.glGetIntegerv(one ? GL_FRAMEBUFFER_BINDING : GL_READ_FRAMEBUFFER_BINDING,
                         &readFramebuffer);
        if (readFramebuffer) bindFramebuffer(one ? GL_FRAMEBUFFER : GL_READ_FRAMEBUFFER, 0);
    }
    // ES before 3.0 reads the window's one colour buffer it draws into.
    const bool chooses = knows(caps, 10, 30);
    const GLenum wanted = caps.doubleBuffered ? GL_BACK : GL_FRONT;
    if (chooses) gl.glGetIntegerv(GL_READ_BUFFER, &readBuffer);
    const bool switchBuffer = chooses && GLenum(readBuffer) != wanted;
    if (switchBuffer) gl.glReadBuffer(wanted);

    gl.glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);

    if (switchBuffer) gl.glReadBuffer(GLenum(readBuffer));
    if (readFramebuffer) {
        bindFramebuffer(caps.es && caps.major < 3 ? GL_FRAMEBUFFER : GL_READ_FRAMEBUFFER,
                        GLuint(readFramebuffer));
    }
    if (packBuffer) gl.glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer));
    for (size_t i = 0; i < std::size(kPackParams); ++i) {
        const PackParam& p = kPackParams[i];
        if (knows(caps, p.gl, p.es) && pack[i] != p.defaultValue) {
            gl.glPixelStorei(p.name, pack[i]);
        }
    }
    return own.finish();
}

bool FrameGrabber::writeFrame(const ContextCaps& caps, int width, int height,
                              const std::string& path)
{
    if (const char* why = cannotRead(caps, width, height)) {
        NPRGL_WARN("cannot take a screenshot of this context (%s); skipping %s", why,
                   path.c_str());
        return false;
    }
    PngImage image;
    image.width = width;
    image.height = height;
    image.rgba.resize(size_t(width) * height * 4);
    const GLenum refused = readFrame(caps, width, height, image.rgba.data());
    if (refused != GL_NO_ERROR) {
        NPRGL_ERROR("screenshot %s: the driver refused the read (GL error 0x%x); skipped",
                    path.c_str(), refused);
        return false;
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
