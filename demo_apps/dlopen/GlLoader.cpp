#include "GlLoader.h"

#include <dlfcn.h>

#include <cstdio>

namespace demo {

bool GlLoader::load(const std::string& libraryName, bool offscreen, std::string& error)
{
    offscreen_ = offscreen;
    std::string name = libraryName;
    if (name.empty()) {
        name = offscreen ? "libOSMesa.so.8" : "libGL.so.1";
    }
    handle_ = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle_ == nullptr) {
        const char* reason = dlerror();
        error = "cannot load " + name + ": " + (reason ? reason : "unknown error");
        return false;
    }

    if (offscreen) {
        osMesaGetProcAddress_ = reinterpret_cast<Proc (*)(const char*)>(
            dlsym(handle_, "OSMesaGetProcAddress"));
        if (osMesaGetProcAddress_ == nullptr) {
            error = name + " has no OSMesaGetProcAddress";
            return false;
        }
        resolve(api_.osMesaCreateContextExt, "OSMesaCreateContextExt", true);
        resolve(api_.osMesaMakeCurrent, "OSMesaMakeCurrent", true);
        resolve(api_.osMesaDestroyContext, "OSMesaDestroyContext", true);
    } else {
        glXGetProcAddressARB_ = reinterpret_cast<Proc (*)(const GLubyte*)>(
            dlsym(handle_, "glXGetProcAddressARB"));
        if (glXGetProcAddressARB_ == nullptr) {
            error = name + " has no glXGetProcAddressARB";
            return false;
        }
        resolve(api_.glXChooseVisual, "glXChooseVisual", true);
        resolve(api_.glXCreateContext, "glXCreateContext", true);
        resolve(api_.glXMakeCurrent, "glXMakeCurrent", true);
        resolve(api_.glXSwapBuffers, "glXSwapBuffers", true);
        resolve(api_.glXDestroyContext, "glXDestroyContext", true);
    }

    // GL: half through dlsym, half through the GetProcAddress function.
    resolve(api_.readPixels, "glReadPixels", true);
    resolve(api_.readBuffer, "glReadBuffer", false);
    resolve(api_.pixelStorei, "glPixelStorei", true);
    resolve(api_.getIntegerv, "glGetIntegerv", false);
    resolve(api_.finish, "glFinish", true);
    resolve(api_.flush, "glFlush", true);
    resolve(draw_.clear, "glClear", true);
    resolve(draw_.clearColor, "glClearColor", false);
    resolve(draw_.viewport, "glViewport", true);
    resolve(draw_.matrixMode, "glMatrixMode", false);
    resolve(draw_.loadIdentity, "glLoadIdentity", true);
    resolve(draw_.frustum, "glFrustum", false);
    resolve(draw_.translatef, "glTranslatef", true);
    resolve(draw_.rotatef, "glRotatef", false);
    resolve(draw_.pushMatrix, "glPushMatrix", true);
    resolve(draw_.popMatrix, "glPopMatrix", false);
    resolve(draw_.enable, "glEnable", true);
    resolve(draw_.lightfv, "glLightfv", false);
    resolve(draw_.materialfv, "glMaterialfv", true);
    resolve(draw_.begin, "glBegin", false);
    resolve(draw_.end, "glEnd", true);
    resolve(draw_.normal3f, "glNormal3f", false);
    resolve(draw_.vertex3f, "glVertex3f", false);

    if (!missing_.empty()) {
        error = "cannot resolve " + missing_ + " from " + name;
        return false;
    }
    return true;
}

GlLoader::Proc GlLoader::viaDlsym(const char* name)
{
    Proc proc = reinterpret_cast<Proc>(dlsym(handle_, name));
    if (proc == nullptr && missing_.empty()) {
        missing_ = name;
    }
    return proc;
}

GlLoader::Proc GlLoader::viaGetProcAddress(const char* name)
{
    Proc proc = offscreen_ ? osMesaGetProcAddress_(name)
                           : glXGetProcAddressARB_(reinterpret_cast<const GLubyte*>(name));
    if (proc == nullptr && missing_.empty()) {
        missing_ = name;
    }
    return proc;
}

void GlLoader::printResolved() const
{
    const char* getProcName = offscreen_ ? "OSMesaGetProcAddress" : "glXGetProcAddressARB";
    struct Entry {
        const char* name;
        const char* method;
        void* pointer;
    };
    const Entry entries[] = {
        {"glClear", "dlsym", reinterpret_cast<void*>(draw_.clear)},
        {"glVertex3f", getProcName, reinterpret_cast<void*>(draw_.vertex3f)},
    };
    for (const Entry& entry : entries) {
        Dl_info info{};
        const char* object = "?";
        if (dladdr(entry.pointer, &info) != 0 && info.dli_fname != nullptr) {
            object = info.dli_fname;
        }
        std::fprintf(stderr, "%s: %s (via %s)\n", entry.name, object, entry.method);
    }
}

} // namespace demo
