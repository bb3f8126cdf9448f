#include "shim/Overlay.h"

#include "common/Log.h"
#include "frame/Compositor.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

#include <imgui.h>
#include <backends/imgui_impl_opengl2.h>

#include <X11/keysym.h>

#include <mutex>
#include <utility>

namespace nprgl {

namespace {

// ImGui's current context is one global: overlays of contexts on several threads take turns.
std::mutex& imguiMutex()
{
    static std::mutex* m = new std::mutex; // lives past exit, as the contexts do
    return *m;
}

} // namespace

// Fixed-function state the program may leave on that would change how ImGui's backend draws
// (which sets blending, scissor, culling, depth, lighting, matrices and its arrays itself).
// What was on is remembered and switched on again after the attribute stacks are popped: not
// every driver saves all of it there (Mesa's pop leaves GL_COLOR_SUM off).
void Overlay::neutralState(bool doubleBuffered)
{
    const GlDispatch& gl = gRealGl;
    mSwitchedOff.clear();
    auto off = [&](Switch kind, GLint unit, GLenum what) {
        const bool on = kind == Switch::Attrib ? false : gl.glIsEnabled(what) == GL_TRUE;
        if (kind == Switch::Attrib) {
            GLint enabled = 0;
            gl.glGetVertexAttribiv(what, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
            if (!enabled) return;
            gl.glDisableVertexAttribArray(what);
        } else if (!on) {
            return;
        } else if (kind == Switch::Cap) {
            gl.glDisable(what);
        } else {
            gl.glDisableClientState(what);
        }
        mSwitchedOff.push_back({kind, unit, what});
    };
    GLint units = 1;
    gl.glGetIntegerv(GL_MAX_TEXTURE_UNITS, &units);
    for (GLint unit = units - 1; unit >= 0; --unit) {
        gl.glActiveTexture(GLenum(GL_TEXTURE0 + unit));
        gl.glClientActiveTexture(GLenum(GL_TEXTURE0 + unit));
        for (GLenum target :
             {GL_TEXTURE_1D, GL_TEXTURE_2D, GL_TEXTURE_3D, GL_TEXTURE_CUBE_MAP, GL_TEXTURE_GEN_S,
              GL_TEXTURE_GEN_T, GL_TEXTURE_GEN_R, GL_TEXTURE_GEN_Q}) {
            off(Switch::Cap, unit, target);
        }
        off(Switch::ClientArray, unit, GL_TEXTURE_COORD_ARRAY);
    }
    for (GLenum cap :
         {GL_FOG, GL_ALPHA_TEST, GL_STENCIL_TEST, GL_COLOR_LOGIC_OP, GL_POLYGON_STIPPLE,
          GL_COLOR_SUM, GL_RASTERIZER_DISCARD, GL_PRIMITIVE_RESTART, GL_FRAMEBUFFER_SRGB,
          GL_VERTEX_PROGRAM_ARB, GL_FRAGMENT_PROGRAM_ARB, GL_SAMPLE_ALPHA_TO_COVERAGE}) {
        off(Switch::Cap, 0, cap);
    }
    for (int plane = 0; plane < 6; ++plane)
        off(Switch::Cap, 0, GLenum(GL_CLIP_PLANE0 + plane));
    for (GLenum array :
         {GL_SECONDARY_COLOR_ARRAY, GL_FOG_COORD_ARRAY, GL_INDEX_ARRAY, GL_EDGE_FLAG_ARRAY}) {
        off(Switch::ClientArray, 0, array);
    }
    GLint attribs = 0;
    gl.glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &attribs);
    for (GLint i = 0; i < attribs; ++i)
        off(Switch::Attrib, 0, GLenum(i));
    gl.glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.glDrawBuffer(doubleBuffered ? GL_BACK : GL_FRONT);
    gl.glMatrixMode(GL_TEXTURE);
    gl.glLoadIdentity(); // unit 0's; pushed and popped around by beginGl/endGl
}

void Overlay::switchBackOn()
{
    const GlDispatch& gl = gRealGl;
    GLint active = 0, client = 0;
    gl.glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    gl.glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &client);
    for (const Switched& s : mSwitchedOff) {
        switch (s.kind) {
        case Switch::Cap:
            if (gl.glIsEnabled(s.what)) break;
            gl.glActiveTexture(GLenum(GL_TEXTURE0 + s.unit));
            gl.glEnable(s.what);
            break;
        case Switch::ClientArray:
            gl.glClientActiveTexture(GLenum(GL_TEXTURE0 + s.unit));
            if (!gl.glIsEnabled(s.what)) gl.glEnableClientState(s.what);
            break;
        case Switch::Attrib:
            gl.glEnableVertexAttribArray(s.what);
            break;
        }
    }
    gl.glActiveTexture(GLenum(active));
    gl.glClientActiveTexture(GLenum(client));
}

Overlay::Overlay(std::string programName, std::string programFile)
    : mPanel(std::move(programName), std::move(programFile))
{
}

Overlay::~Overlay()
{
    if (!mImGui) return;
    std::lock_guard lock(imguiMutex());
    // The GL context may be gone or not current: its font texture goes with it, so only the
    // ImGui side is torn down here.
    ImGui::SetCurrentContext(mImGui);
    ImGui::GetIO().BackendRendererUserData = nullptr;
    ImGui::GetIO().Fonts->SetTexID(nullptr);
    ImGui::DestroyContext(mImGui);
}

void Overlay::setOpen(bool open)
{
    if (open == mOpen) return;
    mOpen = open;
    mLastFrame = {};
    mFramesOpen = 0;
    NPRGL_INFO("overlay %s", open ? "open" : "closed");
}

void Overlay::draw(Compositor& compositor, _XDisplay* display, Window window, int width, int height,
                   bool doubleBuffered)
{
    const auto now = std::chrono::steady_clock::now();
    if (mLastFrame != std::chrono::steady_clock::time_point{}) {
        mFrameMs = std::chrono::duration<double, std::milli>(now - mLastFrame).count();
    }
    mLastFrame = now;
    if (!mOpen || mBroken || width <= 0 || height <= 0) return;

    std::lock_guard lock(imguiMutex());
    if (!mImGui) {
        mBindVertexArray =
            reinterpret_cast<PFNGLBINDVERTEXARRAYPROC>(realProcAddress("glBindVertexArray"));
        mBindFramebuffer =
            reinterpret_cast<PFNGLBINDFRAMEBUFFERPROC>(realProcAddress("glBindFramebuffer"));
        if (!mSaved.resolve() || !mBindVertexArray || !mBindFramebuffer) {
            NPRGL_WARN("overlay: the driver lacks framebuffer objects; no overlay here");
            mBroken = true;
            return;
        }
        IMGUI_CHECKVERSION();
        mImGui = ImGui::CreateContext();
        ImGui::SetCurrentContext(mImGui);
        ImGuiIO& io = ImGui::GetIO();
        io.IniFilename = nullptr; // nothing written into the program's folder
        io.LogFilename = nullptr;
        ImGui::StyleColorsDark();
        ImGui::GetStyle().Alpha = 0.92f;
        ImGui_ImplOpenGL2_Init();
    }
    ImGui::SetCurrentContext(mImGui);
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(float(width), float(height));
    io.DeltaTime = mFrameMs > 0.0 ? float(mFrameMs / 1000.0) : 1.0f / 60.0f;
    const PointerState pointer = mInput.poll(display, window, width, height);
    io.MousePos = pointer.inside ? ImVec2(pointer.x, pointer.y) : ImVec2(-FLT_MAX, -FLT_MAX);
    for (int b = 0; b < 3; ++b)
        io.MouseDown[b] = pointer.buttons[b];
    pollKeyboard(display);

    // Whatever the thunks reach from here on (ImGui's backend calls gl* by name) goes
    // straight to the driver: not recorded, followed or held.
    ReentryGuard direct;
    if (!beginGl(doubleBuffered)) return;
    ImGui_ImplOpenGL2_NewFrame(); // the font texture, the first time
    ImGui::NewFrame();
    // The second frame open has its final layout (the first measures): said once at debug.
    if (mFramesOpen < 2 && ++mFramesOpen == 2) mPanel.noteLayout();
    OverlayFigures figures;
    figures.counts = &compositor.lastFrameCounts();
    figures.frameMs = mFrameMs;
    figures.composeMs = compositor.lastFrameComposeMs();
    // A click off the panel in pick mode picks the program's object under the pointer.
    if (mPanel.picking() && ImGui::IsMouseClicked(0) && !io.WantCaptureMouse) {
        uint64_t hash = 0;
        const PickResult hit = compositor.pick(int(pointer.x), int(pointer.y), height, hash);
        mPanel.picked(hit, hash);
    }
    OverlayPanel::Changes changes =
        mPanel.build(compositor.settings(), compositor.enabled(), compositor.rules(), figures);
    ImGui::Render();
    ImGui_ImplOpenGL2_RenderDrawData(ImGui::GetDrawData());
    endGl(compositor);

    if (changes.toggle) compositor.setEnabled(!compositor.enabled());
    if (changes.restyle) compositor.restyle(changes.settings, false);
    if (changes.rules) compositor.setRules(std::move(changes.leave));
}

void Overlay::pollKeyboard(_XDisplay* display)
{
    ImGuiIO& io = ImGui::GetIO();
    char keymap[32] = {};
    if (!mInput.pollKeys(display, keymap)) return;
    auto down = [&](unsigned code) {
        return code < 256 && (keymap[code >> 3] & (1 << (code & 7)));
    };
    if (display != mKeysOf) {
        // ImGui's keys by X key code on this display.
        mKeysOf = display;
        const std::pair<ImGuiKey, unsigned long> keys[] = {{ImGuiKey_Tab, XK_Tab},
                                                           {ImGuiKey_LeftArrow, XK_Left},
                                                           {ImGuiKey_RightArrow, XK_Right},
                                                           {ImGuiKey_UpArrow, XK_Up},
                                                           {ImGuiKey_DownArrow, XK_Down},
                                                           {ImGuiKey_Home, XK_Home},
                                                           {ImGuiKey_End, XK_End},
                                                           {ImGuiKey_Delete, XK_Delete},
                                                           {ImGuiKey_Backspace, XK_BackSpace},
                                                           {ImGuiKey_Enter, XK_Return},
                                                           {ImGuiKey_Escape, XK_Escape},
                                                           {ImGuiKey_KeyPadEnter, XK_KP_Enter},
                                                           {ImGuiKey_A, XK_a},
                                                           {ImGuiKey_C, XK_c},
                                                           {ImGuiKey_V, XK_v},
                                                           {ImGuiKey_X, XK_x},
                                                           {ImGuiKey_Z, XK_z}};
        for (const auto& [key, sym] : keys)
            io.KeyMap[key] = int(mInput.keycode(display, sym));
        for (unsigned long sym : {XK_Shift_L, XK_Shift_R})
            mShift.push_back(mInput.keycode(display, sym));
        for (unsigned long sym : {XK_Control_L, XK_Control_R})
            mCtrl.push_back(mInput.keycode(display, sym));
        for (unsigned long sym : {XK_Alt_L, XK_Alt_R})
            mAlt.push_back(mInput.keycode(display, sym));
    }
    auto any = [&](const std::vector<unsigned>& codes) {
        bool on = false;
        for (unsigned code : codes)
            on = on || (code && down(code));
        return on;
    };
    io.KeyShift = any(mShift);
    io.KeyCtrl = any(mCtrl);
    io.KeyAlt = any(mAlt);
    for (unsigned code = 8; code < 256; ++code) {
        const bool now = down(code);
        const bool pressed = now && !io.KeysDown[code];
        io.KeysDown[code] = now;
        // A key that went down since the last frame types its character (the field that
        // has the focus takes it; there is no auto-repeat between frames).
        if (!pressed || io.KeyCtrl || io.KeyAlt) continue;
        const unsigned long sym = mInput.keysym(display, code, io.KeyShift);
        if (sym >= 0x20 && sym <= 0x7e) io.AddInputCharacter(unsigned(sym));
    }
}

bool Overlay::beginGl(bool doubleBuffered)
{
    const GlDispatch& gl = gRealGl;
    mProgramError = gl.glGetError();
    GLint textureDepth = 0, textureMax = 0;
    gl.glGetIntegerv(GL_TEXTURE_STACK_DEPTH, &textureDepth);
    gl.glGetIntegerv(GL_MAX_TEXTURE_STACK_DEPTH, &textureMax);
    if (textureDepth >= textureMax || !mSaved.save()) {
        static bool said = false;
        if (!said) NPRGL_WARN("overlay: the program's state stacks are full; not drawn");
        said = true;
        return false;
    }
    gl.glUseProgram(0);
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
    mBindVertexArray(0);
    mBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    // Vertex array 0's element buffer is the program's: kept, and put back.
    gl.glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &mElements);
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    gl.glActiveTexture(GL_TEXTURE0);
    gl.glMatrixMode(GL_TEXTURE);
    gl.glPushMatrix();
    neutralState(doubleBuffered);
    gl.glActiveTexture(GL_TEXTURE0);
    gl.glClientActiveTexture(GL_TEXTURE0);
    gl.glMatrixMode(GL_MODELVIEW);
    return true;
}

void Overlay::endGl(Compositor& compositor)
{
    const GlDispatch& gl = gRealGl;
    gl.glActiveTexture(GL_TEXTURE0);
    gl.glMatrixMode(GL_TEXTURE);
    gl.glPopMatrix();
    gl.glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, GLuint(mElements));
    mSaved.restore();
    switchBackOn();
    while (gl.glGetError() != GL_NO_ERROR) {
    }
    compositor.keepProgramError(mProgramError); // for the program's next glGetError
}

} // namespace nprgl
