#pragma once

#include "GlApi.h"
#include "Surface.h"

namespace demo {

// A double-buffered Xlib window with a legacy GLX context.
class GlxWindow : public Surface {
public:
    explicit GlxWindow(const GlApi& gl) : gl_(gl) {}
    ~GlxWindow() override;
    GlxWindow(const GlxWindow&) = delete;
    GlxWindow& operator=(const GlxWindow&) = delete;

    bool open(const Options& options, std::string& error) override;
    bool processEvents() override;
    void finishFrame() override {}
    void readPixels(Image& image) override;
    void present() override;
    void resize(int width, int height) override;
    void pressKeys(const std::string& keys, bool down) override;

private:
    void fixSize();

    GlApi gl_;
    Display* display_ = nullptr;
    Window window_ = 0;
    Colormap colormap_ = 0;
    GLXContext context_ = nullptr;
    Atom deleteAtom_ = 0;
    int width_ = 0;
    int height_ = 0;
};

} // namespace demo
