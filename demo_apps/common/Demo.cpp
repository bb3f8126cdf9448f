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
    gl.flush = &glFlush;
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

void pushPixelProjection(int width, int height)
{
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0.0, width, 0.0, height, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
}

void pushIdentityMatrices()
{
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
}

void popMatrices()
{
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
}

void beginShinePass()
{
    glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_CURRENT_BIT);
    glDisable(GL_LIGHTING);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LEQUAL);
    glColor3f(0.35f, 0.2f, 0.05f);
}

void endShinePass() { glPopAttrib(); }

void drawSphere(float radius, int stacks, int slices, float textureRepeats)
{
    const float pi = 3.14159265358979f;
    for (int i = 0; i < stacks; ++i) {
        glBegin(GL_TRIANGLE_STRIP);
        for (int j = 0; j <= slices; ++j) {
            float lon = 2.0f * pi * j / slices;
            for (int k = 0; k <= 1; ++k) {
                float lat = pi * (i + k) / stacks - pi / 2.0f;
                float n[3] = {std::cos(lat) * std::cos(lon), std::sin(lat),
                              -std::cos(lat) * std::sin(lon)};
                glNormal3f(n[0], n[1], n[2]);
                if (textureRepeats > 0.0f) {
                    glTexCoord2f(textureRepeats * j / slices, static_cast<float>(i + k) / stacks);
                }
                glVertex3f(radius * n[0], radius * n[1], radius * n[2]);
            }
        }
        glEnd();
    }
}

void drawTorus(float major, float minor, int rings, int sides)
{
    const float pi = 3.14159265358979f;
    for (int i = 0; i < rings; ++i) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= sides; ++j) {
            float v = 2.0f * pi * j / sides;
            for (int k = 1; k >= 0; --k) {
                float u = 2.0f * pi * (i + k) / rings;
                float r = major + minor * std::cos(v);
                glNormal3f(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
                glVertex3f(r * std::cos(u), r * std::sin(u), minor * std::sin(v));
            }
        }
        glEnd();
    }
}

} // namespace demo
