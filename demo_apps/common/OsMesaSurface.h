#pragma once

#include "GlApi.h"
#include "Surface.h"

#include <vector>

namespace demo {

// An OSMesa context rendering into a buffer in memory.
class OsMesaSurface : public Surface {
public:
    explicit OsMesaSurface(const GlApi& gl) : gl_(gl) {}
    ~OsMesaSurface() override;
    OsMesaSurface(const OsMesaSurface&) = delete;
    OsMesaSurface& operator=(const OsMesaSurface&) = delete;

    bool open(const Options& options, std::string& error) override;
    bool processEvents() override { return true; }
    void finishFrame() override;
    void readPixels(Image& image) override;
    void present() override {}

private:
    GlApi gl_;
    OSMesaContext context_ = nullptr;
    std::vector<uint32_t> buffer_;
    int width_ = 0;
    int height_ = 0;
};

} // namespace demo
