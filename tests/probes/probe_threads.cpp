// Two threads, each with its own OSMesa context, draw two frames of different colours: a
// recording holds one stream per context.
#include <GL/osmesa.h>
#include <cstdio>
#include <thread>
#include <vector>

namespace {

void drawFrames(float red, float green, float blue)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, nullptr);
    std::vector<unsigned char> pixels(48 * 32 * 4);
    if (!OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, 48, 32)) return;
    for (int frame = 0; frame < 2; ++frame) {
        glClearColor(red, green, blue, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        glColor3f(1, 1, 1);
        glVertex2f(-0.5f, -0.5f);
        glVertex2f(0.5f, -0.5f);
        glVertex2f(0.0f, 0.5f);
        glEnd();
        glFinish();
    }
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx);
}

} // namespace

int main()
{
    std::thread a(drawFrames, 1.0f, 0.0f, 0.0f);
    a.join(); // one after the other: the context numbers are then deterministic
    std::thread b(drawFrames, 0.0f, 0.0f, 1.0f);
    b.join();
    std::printf("ok\n");
    return 0;
}
