#pragma once

// Overlay: nprgl's in-program window (Dear ImGui), drawn over the frame just before the swap.

#include "frame/SavedGlState.h"
#include "shim/OverlayInput.h"
#include "shim/OverlayPanel.h"

#include <chrono>
#include <string>
#include <vector>

struct ImGuiContext;

namespace nprgl {

class Compositor;

// One per GL context that opened it. Drawn with the driver's functions only (the thunks point
// at the driver while it draws: ImGui's OpenGL 2 backend calls gl* by name, which in this
// library are our own entry points), with all of the program's state saved around it and its
// pending GL error kept. Input is the pointer, polled; the program's events are untouched, so
// a click on the overlay reaches the program too.
class Overlay {
public:
    Overlay(std::string programName, std::string programFile);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    bool open() const { return mOpen; }
    void setOpen(bool open);

    // Draws into the current context's default framebuffer (`width` x `height`, the back
    // buffer when `doubleBuffered`) and applies what the user changed to `compositor` for the
    // next frame.
    void draw(Compositor& compositor, _XDisplay* display, Window window, int width, int height,
              bool doubleBuffered);

private:
    // Saves the program's state and sets what ImGui's backend expects; false: not drawable.
    bool beginGl(bool doubleBuffered);
    // Keys from XQueryKeymap into ImGui (text fields, Ctrl+click typing into a slider).
    void pollKeyboard(_XDisplay* display);
    void endGl(Compositor& compositor);
    void neutralState(bool doubleBuffered);
    // Switches on again what neutralState() switched off and the stacks did not restore.
    void switchBackOn();

    OverlayPanel mPanel;
    OverlayInput mInput;
    SavedGlState mSaved;
    ImGuiContext* mImGui = nullptr;
    bool mOpen = false;
    bool mBroken = false; // the driver lacks what saving the state needs: never drawn
    std::chrono::steady_clock::time_point mLastFrame{};
    double mFrameMs = 0.0;
    int mFramesOpen = 0;
    _XDisplay* mKeysOf = nullptr; // the display ImGui's key map is for
    std::vector<unsigned> mShift, mCtrl, mAlt;
    GLenum mProgramError = GL_NO_ERROR; // taken from the driver before drawing, given back
    GLint mElements = 0;
    enum class Switch : uint8_t { Cap, ClientArray, Attrib };
    struct Switched {
        Switch kind;
        GLint unit; // the texture unit (Cap, ClientArray)
        GLenum what;
    };
    std::vector<Switched> mSwitchedOff; // kept between frames: no allocation once grown
    PFNGLBINDVERTEXARRAYPROC mBindVertexArray = nullptr;
    PFNGLBINDFRAMEBUFFERPROC mBindFramebuffer = nullptr;
};

} // namespace nprgl
