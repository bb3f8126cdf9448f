#include "Demo.h"

#include "FrameLoop.h"
#include "GlApi.h"

#include <GL/gl.h>

#include <cmath>
#include <numbers>

namespace demo {

namespace {

GlApi linkedGlApi()
{
    GlApi gl;
    gl.readPixels = &glReadPixels;
    gl.readBuffer = &glReadBuffer;
    gl.pixelStorei = &glPixelStorei;
    gl.getIntegerv = &glGetIntegerv;
    gl.finish = &glFinish;
    gl.glXChooseVisual = &glXChooseVisual;
    gl.glXCreateContext = &glXCreateContext;
    gl.glXMakeCurrent = &glXMakeCurrent;
    gl.glXSwapBuffers = &glXSwapBuffers;
    gl.glXDestroyContext = &glXDestroyContext;
    gl.osMesaCreateContextExt = &OSMesaCreateContextExt;
    gl.osMesaMakeCurrent = &OSMesaMakeCurrent;
    gl.osMesaDestroyContext = &OSMesaDestroyContext;
    return gl;
}

} // namespace

int run(int argc, char** argv, const char* shortName, Scene& scene)
{
    Options options;
    int status = parseOptions(argc, argv, shortName, scene.extraOptions(), options);
    if (status >= 0) {
        return status;
    }
    return runFrames(options, linkedGlApi(), scene);
}

void setPerspective(double fovYDegrees, double aspect, double zNear, double zFar)
{
    double top = zNear * std::tan(fovYDegrees * std::numbers::pi / 360.0);
    double right = top * aspect;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-right, right, -top, top, zNear, zFar);
    glMatrixMode(GL_MODELVIEW);
}

} // namespace demo
