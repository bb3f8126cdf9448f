#include "FrameLoop.h"

#include "GlxWindow.h"
#include "Image.h"
#include "OsMesaSurface.h"
#include "PngWriter.h"

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>

namespace demo {

namespace {

int fail(const Options& options, const std::string& message)
{
    std::fprintf(stderr, "%s: %s\n", options.appName.c_str(), message.c_str());
    return 1;
}

} // namespace

int runFrames(const Options& options, const GlApi& gl, Scene& scene)
{
    if (!options.saveDir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(options.saveDir, ec);
        if (ec) {
            return fail(options, "cannot create " + options.saveDir + ": " + ec.message());
        }
    }

    std::unique_ptr<Surface> surface;
    if (options.offscreen) {
        surface = std::make_unique<OsMesaSurface>(gl);
    } else {
        surface = std::make_unique<GlxWindow>(gl);
    }
    std::string error;
    if (!surface->open(options, error)) {
        return fail(options, error);
    }
    if (!scene.init(options, error)) {
        return fail(options, error);
    }

    Image image;
    int framesDone = 0;
    auto start = std::chrono::steady_clock::now();
    for (int frame = 1; options.frames == 0 || frame <= options.frames; ++frame) {
        if (!surface->processEvents()) {
            break;
        }
        if (frame == options.growAt) surface->resize(2 * options.width, 2 * options.height);
        const bool press = frame == options.pressAt;
        if (press) surface->pressKeys(options.pressKeys, true);
        scene.draw(frame);
        surface->finishFrame();
        if (options.shouldSave(frame)) {
            surface->readPixels(image);
            std::string path = options.saveDir + "/" + options.shortName + "_"
                               + std::to_string(frame) + ".png";
            if (!writePng(path, image, error)) {
                scene.shutdown();
                return fail(options, error);
            }
        }
        if (options.flushFrames) gl.flush();
        else surface->present();
        if (press) surface->pressKeys(options.pressKeys, false);
        ++framesDone;
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
                         .count();
    scene.shutdown();

    if (options.report) {
        double fps = seconds > 0.0 ? framesDone / seconds : 0.0;
        std::printf("frames=%d seconds=%.6f fps=%.3f\n", framesDone, seconds, fps);
        std::fflush(stdout);
    }
    // As most programs end: the surface and its context are never destroyed.
    if (options.exitUndestroyed) std::exit(0);
    return 0;
}

} // namespace demo
