#pragma once

#include "GlApi.h"

#include <string>

namespace demo {

// The GL entry points demo_dlopen draws with.
struct DrawFunctions {
    void (*clear)(GLbitfield) = nullptr;
    void (*clearColor)(GLclampf, GLclampf, GLclampf, GLclampf) = nullptr;
    void (*viewport)(GLint, GLint, GLsizei, GLsizei) = nullptr;
    void (*matrixMode)(GLenum) = nullptr;
    void (*loadIdentity)() = nullptr;
    void (*frustum)(GLdouble, GLdouble, GLdouble, GLdouble, GLdouble, GLdouble) = nullptr;
    void (*translatef)(GLfloat, GLfloat, GLfloat) = nullptr;
    void (*rotatef)(GLfloat, GLfloat, GLfloat, GLfloat) = nullptr;
    void (*pushMatrix)() = nullptr;
    void (*popMatrix)() = nullptr;
    void (*enable)(GLenum) = nullptr;
    void (*lightfv)(GLenum, GLenum, const GLfloat*) = nullptr;
    void (*materialfv)(GLenum, GLenum, const GLfloat*) = nullptr;
    void (*begin)(GLenum) = nullptr;
    void (*end)() = nullptr;
    void (*normal3f)(GLfloat, GLfloat, GLfloat) = nullptr;
    void (*vertex3f)(GLfloat, GLfloat, GLfloat) = nullptr;
};

// Loads libGL (or libOSMesa) with dlopen, the way SDL does, and resolves every entry point:
// GLX/OSMesa functions with dlsym, GL functions half with dlsym and half through
// glXGetProcAddressARB / OSMesaGetProcAddress.
class GlLoader {
public:
    // libraryName empty means the default for the mode. On failure error is one line.
    bool load(const std::string& libraryName, bool offscreen, std::string& error);

    const GlApi& api() const { return api_; }
    const DrawFunctions& draw() const { return draw_; }
    // Prints "glClear: /path/libGL.so.1 (via dlsym)": the shared object each pointer lies in.
    void printResolved() const;

private:
    using Proc = void (*)();

    Proc viaDlsym(const char* name);
    Proc viaGetProcAddress(const char* name);
    template <typename T>
    void resolve(T& slot, const char* name, bool useDlsym)
    {
        slot = reinterpret_cast<T>(useDlsym ? viaDlsym(name) : viaGetProcAddress(name));
    }

    void* handle_ = nullptr;
    bool offscreen_ = false;
    Proc (*glXGetProcAddressARB_)(const GLubyte*) = nullptr;
    Proc (*osMesaGetProcAddress_)(const char*) = nullptr;
    std::string missing_; // first entry point that could not be resolved
    GlApi api_;
    DrawFunctions draw_;
};

} // namespace demo
