// Draws a lit cube on OSMesa for a number of frames and rewrites a file between two frames
// (--at K --text T: after frame K, T replaces --file, by a rename as editors do): the
// configuration-reload tests change nprgl's configuration at a known frame, no clock.
// Every frame is saved as DIR/reload_<frame>.png.
#include "common/PngImage.h"

#include <GL/osmesa.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

constexpr int kSize = 128;

void drawCube(int frame)
{
    glClearColor(0.3f, 0.3f, 0.35f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1.5, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const float light[4] = {0.4f, 0.6f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glTranslatef(0, 0, -4);
    glRotatef(30.0f + float(frame), 1, 1, 0);
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}};
    glColor3f(0.8f, 0.5f, 0.2f);
    glBegin(GL_QUADS);
    for (const auto& f : n) {
        // Two axes across the face, so the corners go round it.
        const float u[3] = {f[1] != 0 || f[2] != 0 ? 1.0f : 0.0f, f[0] != 0 ? 1.0f : 0.0f, 0};
        const float v[3] = {f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2],
                            f[0] * u[1] - f[1] * u[0]};
        glNormal3fv(f);
        const float s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : s) {
            glVertex3f(f[0] + c[0] * u[0] + c[1] * v[0], f[1] + c[0] * u[1] + c[1] * v[1],
                       f[2] + c[0] * u[2] + c[1] * v[2]);
        }
    }
    glEnd();
}

} // namespace

int main(int argc, char** argv)
{
    int frames = 4;
    std::string file, dir = ".";
    std::map<int, std::string> rewrites;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string option = argv[i];
        if (option == "--frames") {
            frames = std::atoi(argv[i + 1]);
        } else if (option == "--file") {
            file = argv[i + 1];
        } else if (option == "--save-dir") {
            dir = argv[i + 1];
        } else if (option == "--at" && i + 3 < argc && std::strcmp(argv[i + 2], "--text") == 0) {
            rewrites[std::atoi(argv[i + 1])] = argv[i + 3];
            i += 2;
        } else {
            std::fprintf(stderr, "probe_reload: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    std::vector<unsigned char> buffer(kSize * kSize * 4);
    if (!ctx || !OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
        std::fprintf(stderr, "probe_reload: no OSMesa context\n");
        return 1;
    }
    glViewport(0, 0, kSize, kSize);
    for (int frame = 1; frame <= frames; ++frame) {
        drawCube(frame);
        glFinish(); // the frame's end on OSMesa
        nprgl::PngImage image;
        image.width = image.height = kSize;
        image.rgba.resize(buffer.size());
        glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
        image.flipRows();
        std::string error;
        if (!image.write(dir + "/reload_" + std::to_string(frame) + ".png", error)) {
            std::fprintf(stderr, "probe_reload: %s\n", error.c_str());
            return 1;
        }
        if (auto r = rewrites.find(frame); r != rewrites.end() && !file.empty()) {
            const std::string temp = file + ".new";
            std::ofstream(temp) << r->second << "\n";
            std::rename(temp.c_str(), file.c_str());
        }
    }
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx);
    std::printf("ok\n");
    return 0;
}
