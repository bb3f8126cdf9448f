#pragma once

#include <GL/glx.h>
#include <GL/osmesa.h>

namespace demo {

// The GL, GLX and OSMesa entry points the surfaces use. Going through pointers lets the same
// surface code serve apps that link libGL and demo_dlopen, which loads it at run time.
struct GlApi {
    void (*readPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*) = nullptr;
    void (*readBuffer)(GLenum) = nullptr;
    void (*pixelStorei)(GLenum, GLint) = nullptr;
    void (*getIntegerv)(GLenum, GLint*) = nullptr;
    void (*finish)() = nullptr;
    void (*flush)() = nullptr;

    XVisualInfo* (*glXChooseVisual)(Display*, int, int*) = nullptr;
    GLXContext (*glXCreateContext)(Display*, XVisualInfo*, GLXContext, Bool) = nullptr;
    Bool (*glXMakeCurrent)(Display*, GLXDrawable, GLXContext) = nullptr;
    void (*glXSwapBuffers)(Display*, GLXDrawable) = nullptr;
    void (*glXDestroyContext)(Display*, GLXContext) = nullptr;

    OSMesaContext (*osMesaCreateContextExt)(GLenum, GLint, GLint, GLint, OSMesaContext) = nullptr;
    GLboolean (*osMesaMakeCurrent)(OSMesaContext, void*, GLenum, GLsizei, GLsizei) = nullptr;
    void (*osMesaDestroyContext)(OSMesaContext) = nullptr;
};

} // namespace demo
