// Draws a lit cube on OSMesa for a number of frames and rewrites a file between two frames
// (--at K --text T: after frame K, T replaces --file, by a rename as editors do, its folder
// made when missing), replaces it by a FIFO the same way (--fifo-at K) or removes the file's
// folder (--remove-folder K, after frame K): the configuration-reload tests change nprgl's
// configuration at a known frame, no clock.
// Every frame is saved as DIR/reload_<frame>.png.
#include "common/PngImage.h"
#include "tests/probes/ProbeCube.h"

#include <GL/osmesa.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

constexpr int kSize = 128;

} // namespace

int main(int argc, char** argv)
{
    int frames = 4;
    std::string file, dir = ".";
    std::map<int, std::string> rewrites;
    std::map<int, bool> removals, fifos;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string option = argv[i];
        if (option == "--frames") {
            frames = std::atoi(argv[i + 1]);
        } else if (option == "--file") {
            file = argv[i + 1];
        } else if (option == "--fifo-at") {
            fifos[std::atoi(argv[i + 1])] = true;
        } else if (option == "--remove-folder") {
            removals[std::atoi(argv[i + 1])] = true;
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
        nprgl::probes::drawCube(frame);
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
        const std::filesystem::path folder = std::filesystem::path(file).parent_path();
        if (removals.count(frame) && !folder.empty()) std::filesystem::remove_all(folder);
        if (auto r = rewrites.find(frame); r != rewrites.end() && !file.empty()) {
            if (!folder.empty()) std::filesystem::create_directories(folder);
            const std::string temp = file + ".new";
            std::ofstream(temp) << r->second << "\n";
            std::rename(temp.c_str(), file.c_str());
        }
        if (fifos.count(frame) && !file.empty()) {
            const std::string temp = file + ".new";
            if (mkfifo(temp.c_str(), 0644) != 0 || std::rename(temp.c_str(), file.c_str()) != 0) {
                std::perror("probe_reload: FIFO");
                return 1;
            }
        }
    }
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx);
    std::printf("ok\n");
    return 0;
}
