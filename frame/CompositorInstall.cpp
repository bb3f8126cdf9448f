// The GL calls the compositor intercepts: a thunk per kind (gen_codec.py's COMPOSITOR table).
#include "frame/Compositor.h"

#include "shim/Context.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

namespace nprgl {

namespace {

Compositor& C() { return *tThread.context->compositor(); }

void APIENTRY c_glBegin(GLenum mode) { C().begin(mode); }
void APIENTRY c_glEnd() { C().end(); }

void APIENTRY c_glCallList(GLuint list) { C().callList(list); }

// glCallLists as a whole, held when every list it calls would be.
void APIENTRY c_glCallLists(GLsizei n, GLenum type, const void* lists)
{
    Compositor& c = C();
    const bool held = c.holdLists(n, type, lists);
    const bool masked = held && c.shading();
    if (masked) c.mask();
    else if (!held) c.tintBegin();
    c.next().glCallLists(n, type, lists);
    if (masked) c.unmask();
    else if (!held) c.tintEnd();
}

// A draw that may be held back. With a shading style in the chain a held draw is only
// recorded (the style draws it); without one it goes to the driver as it is (the outline
// styles draw over the program's own picture). A possible layer (a blended pass over held
// geometry) is recorded only, then merged into its object or drawn as the program's.
#define NPRGL_COMPOSITOR_HELD_DRAW(ret, name, place, params, args)                              \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        Compositor& c = C();                                                                    \
        const Compositor::Placement placed = c.place;                                           \
        if (placed == Compositor::Placement::Layer) {                                           \
            const size_t mark = c.streamSize();                                                 \
            c.heldNext().name args;                                                             \
            if (c.settleLayer(mark) != Compositor::Settled::Draw) return;                       \
            c.tintBegin();                                                                      \
            gRealGl.name args; /* recorded already */                                           \
            c.tintEnd();                                                                        \
            return;                                                                             \
        }                                                                                       \
        if (placed == Compositor::Placement::Held && c.shading()) return c.heldNext().name args; \
        c.tintBegin();                                                                          \
        c.next().name args;                                                                     \
        c.tintEnd();                                                                            \
    }
// Barriers: what is held is drawn first, so these see (or draw over) the finished scene.
#define NPRGL_COMPOSITOR_BARRIER(ret, name, params, args)                                       \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().barrier();                                                                          \
        return C().next().name args;                                                            \
    }
// Barriers that draw into colour, or give the framebuffer other pixels: its colour is no
// longer as the program cleared it (Scene::colourFresh).
#define NPRGL_COMPOSITOR_DRAWING(ret, name, params, args)                                       \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().barrier();                                                                          \
        C().colourDrawn();                                                                      \
        C().endOverlayRun();                                                                    \
        return C().next().name args;                                                            \
    }
// Raster images (glBitmap, glDrawPixels): drawings into colour that may be 2D overlays (a
// bitmap font's glyphs), measured as such with OverlayContrast enabled.
#define NPRGL_COMPOSITOR_RASTER(ret, name, params, args)                                        \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        Compositor& c = C();                                                                    \
        c.barrier();                                                                            \
        c.colourDrawn();                                                                        \
        c.overlayBegin();                                                                       \
        c.next().name args;                                                                     \
        c.overlayEnd();                                                                         \
    }
// Clears: barriers that also tell the page (paper) where the program's background is new.
#define NPRGL_COMPOSITOR_CLEAR(ret, name, colour, params, args)                                 \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().clear(colour);                                                                      \
        C().next().name args;                                                                   \
    }
// Copies into a texture: barriers whose flush is the texture's content, not the window's.
#define NPRGL_COMPOSITOR_COPY_TO_TEXTURE(ret, name, params, args)                               \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().copyToTexture();                                                                    \
        C().next().name args;                                                                   \
    }
// Render to texture: what is held for a framebuffer is drawn before the program changes
// which framebuffer is bound or what it is attached to, builds mipmaps from it or blits it;
// a binding also tells the tracker whether the program now draws data (framebufferBound).
#define NPRGL_COMPOSITOR_BIND_FRAMEBUFFER(ret, name, params, args)                              \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().barrier();                                                                          \
        C().next().name args;                                                                   \
        C().framebufferBound();                                                                 \
    }

void APIENTRY c_glReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format,
                             GLenum type, void* p)
{
    C().readPixels();
    C().next().glReadPixels(x, y, w, h, format, type, p);
}

GLint APIENTRY c_glRenderMode(GLenum mode) { return C().renderMode(mode); }

#include "nprgl_compositor.inc"

#undef NPRGL_COMPOSITOR_HELD_DRAW
#undef NPRGL_COMPOSITOR_BARRIER
#undef NPRGL_COMPOSITOR_DRAWING
#undef NPRGL_COMPOSITOR_RASTER
#undef NPRGL_COMPOSITOR_CLEAR
#undef NPRGL_COMPOSITOR_COPY_TO_TEXTURE
#undef NPRGL_COMPOSITOR_BIND_FRAMEBUFFER

} // namespace

void Compositor::install(GlDispatch& d)
{
    mNext = d;
    fillCompositorDispatch(d);
}

void Compositor::installEnd(GlDispatch& d) { d.glEnd = c_glEnd; }

} // namespace nprgl
