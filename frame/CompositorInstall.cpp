// The GL calls the compositor intercepts: its thunks, and the dispatch entries they take.
#include "frame/Compositor.h"

#include "shim/Context.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

namespace nprgl {

namespace {

Compositor& C() { return *tThread.context->compositor(); }

void APIENTRY cBegin(GLenum mode) { C().begin(mode); }
void APIENTRY cEnd() { C().end(); }

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
#define NPRGL_HELD_DRAW(name, place, params, args)                                              \
    void APIENTRY c_##name params                                                              \
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
NPRGL_HELD_DRAW(glDrawArrays, placeDraw(mode, true), (GLenum mode, GLint first, GLsizei count),
                (mode, first, count))
NPRGL_HELD_DRAW(glDrawElements, placeDraw(mode, true),
                (GLenum mode, GLsizei count, GLenum type, const void* indices),
                (mode, count, type, indices))
NPRGL_HELD_DRAW(glDrawRangeElements, placeDraw(mode, true),
                (GLenum mode, GLuint start, GLuint end, GLsizei count, GLenum type,
                 const void* indices),
                (mode, start, end, count, type, indices))
NPRGL_HELD_DRAW(glMultiDrawArrays, placeDraw(mode, true),
                (GLenum mode, const GLint* first, const GLsizei* count, GLsizei n),
                (mode, first, count, n))
NPRGL_HELD_DRAW(glRectf, placeDraw(GL_POLYGON, false),
                (GLfloat a, GLfloat b, GLfloat x, GLfloat y), (a, b, x, y))
NPRGL_HELD_DRAW(glRectd, placeDraw(GL_POLYGON, false),
                (GLdouble a, GLdouble b, GLdouble x, GLdouble y), (a, b, x, y))
NPRGL_HELD_DRAW(glRecti, placeDraw(GL_POLYGON, false), (GLint a, GLint b, GLint x, GLint y),
                (a, b, x, y))
NPRGL_HELD_DRAW(glRects, placeDraw(GL_POLYGON, false),
                (GLshort a, GLshort b, GLshort x, GLshort y), (a, b, x, y))
#undef NPRGL_HELD_DRAW

// Barriers: what is held is drawn first, so these see (or draw over) the finished scene.
#define NPRGL_BARRIER(ret, name, params, args)                                                  \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().barrier();                                                                          \
        return C().next().name args;                                                            \
    }
// Barriers that draw into colour, or give the framebuffer other pixels: its colour is no
// longer as the program cleared it (Scene::colourFresh).
#define NPRGL_DRAWING(ret, name, params, args)                                                  \
    ret APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().barrier();                                                                          \
        C().colourDrawn();                                                                      \
        return C().next().name args;                                                            \
    }
// Clears: barriers that also tell the page (paper) where the program's background is new.
#define NPRGL_CLEAR(name, colour, params, args)                                                 \
    void APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().clear(colour);                                                                      \
        C().next().name args;                                                                   \
    }
NPRGL_CLEAR(glClear, (mask & GL_COLOR_BUFFER_BIT) != 0, (GLbitfield mask), (mask))
NPRGL_CLEAR(glClearBufferiv, buffer == GL_COLOR, (GLenum buffer, GLint i, const GLint* v),
            (buffer, i, v))
NPRGL_CLEAR(glClearBufferuiv, buffer == GL_COLOR, (GLenum buffer, GLint i, const GLuint* v),
            (buffer, i, v))
NPRGL_CLEAR(glClearBufferfv, buffer == GL_COLOR, (GLenum buffer, GLint i, const GLfloat* v),
            (buffer, i, v))
NPRGL_CLEAR(glClearBufferfi, false, (GLenum buffer, GLint i, GLfloat depth, GLint stencil),
            (buffer, i, depth, stencil))
#undef NPRGL_CLEAR
NPRGL_DRAWING(void, glAccum, (GLenum op, GLfloat value), (op, value))
void APIENTRY c_glReadPixels(GLint x, GLint y, GLsizei w, GLsizei h, GLenum format,
                             GLenum type, void* p)
{
    C().readPixels();
    C().next().glReadPixels(x, y, w, h, format, type, p);
}
NPRGL_DRAWING(void, glCopyPixels, (GLint x, GLint y, GLsizei w, GLsizei h, GLenum type),
              (x, y, w, h, type))
NPRGL_DRAWING(void, glBitmap,
              (GLsizei w, GLsizei h, GLfloat x, GLfloat y, GLfloat dx, GLfloat dy,
               const GLubyte* bits),
              (w, h, x, y, dx, dy, bits))
NPRGL_DRAWING(void, glDrawPixels,
              (GLsizei w, GLsizei h, GLenum format, GLenum type, const void* p),
              (w, h, format, type, p))
// Copies into a texture: barriers whose flush is the texture's content, not the window's.
#define NPRGL_COPY_TO_TEXTURE(name, params, args)                                               \
    void APIENTRY c_##name params                                                               \
    {                                                                                           \
        C().copyToTexture();                                                                    \
        C().next().name args;                                                                   \
    }
NPRGL_COPY_TO_TEXTURE(glCopyTexImage1D,
                      (GLenum t, GLint l, GLenum f, GLint x, GLint y, GLsizei w, GLint b),
                      (t, l, f, x, y, w, b))
NPRGL_COPY_TO_TEXTURE(glCopyTexImage2D,
                      (GLenum t, GLint l, GLenum f, GLint x, GLint y, GLsizei w, GLsizei h,
                       GLint b),
                      (t, l, f, x, y, w, h, b))
NPRGL_COPY_TO_TEXTURE(glCopyTexSubImage1D,
                      (GLenum t, GLint l, GLint xo, GLint x, GLint y, GLsizei w),
                      (t, l, xo, x, y, w))
NPRGL_COPY_TO_TEXTURE(glCopyTexSubImage2D,
                      (GLenum t, GLint l, GLint xo, GLint yo, GLint x, GLint y, GLsizei w,
                       GLsizei h),
                      (t, l, xo, yo, x, y, w, h))
NPRGL_COPY_TO_TEXTURE(glCopyTexSubImage3D,
                      (GLenum t, GLint l, GLint xo, GLint yo, GLint zo, GLint x, GLint y,
                       GLsizei w, GLsizei h),
                      (t, l, xo, yo, zo, x, y, w, h))
#undef NPRGL_COPY_TO_TEXTURE
NPRGL_BARRIER(void, glFinish, (), ())
NPRGL_BARRIER(void, glFlush, (), ())
NPRGL_BARRIER(void, glDrawBuffer, (GLenum mode), (mode))
NPRGL_BARRIER(void, glDrawBuffers, (GLsizei n, const GLenum* bufs), (n, bufs))
NPRGL_BARRIER(void, glViewport, (GLint x, GLint y, GLsizei w, GLsizei h), (x, y, w, h))
// Render to texture: what is held for a framebuffer is drawn before the program changes
// which framebuffer is bound or what it is attached to, builds mipmaps from it or blits it;
// a binding also tells the tracker whether the program now draws data (framebufferBound).
#define NPRGL_BIND_FRAMEBUFFER(name)                                                            \
    void APIENTRY c_##name(GLenum target, GLuint fb)                                            \
    {                                                                                           \
        C().barrier();                                                                          \
        C().next().name(target, fb);                                                            \
        C().framebufferBound();                                                                 \
    }
NPRGL_BIND_FRAMEBUFFER(glBindFramebuffer)
NPRGL_BIND_FRAMEBUFFER(glBindFramebufferEXT)
#undef NPRGL_BIND_FRAMEBUFFER
NPRGL_DRAWING(void, glFramebufferTexture1D,
              (GLenum t, GLenum a, GLenum tt, GLuint tex, GLint l), (t, a, tt, tex, l))
NPRGL_DRAWING(void, glFramebufferTexture2D,
              (GLenum t, GLenum a, GLenum tt, GLuint tex, GLint l), (t, a, tt, tex, l))
NPRGL_DRAWING(void, glFramebufferTexture3D,
              (GLenum t, GLenum a, GLenum tt, GLuint tex, GLint l, GLint z),
              (t, a, tt, tex, l, z))
NPRGL_DRAWING(void, glFramebufferTextureLayer,
              (GLenum t, GLenum a, GLuint tex, GLint l, GLint layer), (t, a, tex, l, layer))
NPRGL_DRAWING(void, glFramebufferRenderbuffer, (GLenum t, GLenum a, GLenum rt, GLuint rb),
              (t, a, rt, rb))
NPRGL_BARRIER(void, glGenerateMipmap, (GLenum target), (target))
NPRGL_DRAWING(void, glBlitFramebuffer,
              (GLint sx0, GLint sy0, GLint sx1, GLint sy1, GLint dx0, GLint dy0, GLint dx1,
               GLint dy1, GLbitfield mask, GLenum filter),
              (sx0, sy0, sx1, sy1, dx0, dy0, dx1, dy1, mask, filter))
#undef NPRGL_BARRIER
#undef NPRGL_DRAWING

GLint APIENTRY c_glRenderMode(GLenum mode) { return C().renderMode(mode); }

} // namespace

void Compositor::install(GlDispatch& d)
{
    mNext = d;
    d.glBegin = cBegin;
    d.glEnd = cEnd;
    d.glDrawArrays = c_glDrawArrays;
    d.glDrawElements = c_glDrawElements;
    d.glDrawRangeElements = c_glDrawRangeElements;
    d.glMultiDrawArrays = c_glMultiDrawArrays;
    d.glCallList = c_glCallList;
    d.glRectf = c_glRectf;
    d.glRectd = c_glRectd;
    d.glRecti = c_glRecti;
    d.glRects = c_glRects;
    d.glCallLists = c_glCallLists;
    d.glClear = c_glClear;
    d.glClearBufferiv = c_glClearBufferiv;
    d.glClearBufferuiv = c_glClearBufferuiv;
    d.glClearBufferfv = c_glClearBufferfv;
    d.glClearBufferfi = c_glClearBufferfi;
    d.glAccum = c_glAccum;
    d.glReadPixels = c_glReadPixels;
    d.glCopyPixels = c_glCopyPixels;
    d.glBitmap = c_glBitmap;
    d.glDrawPixels = c_glDrawPixels;
    d.glCopyTexImage1D = c_glCopyTexImage1D;
    d.glCopyTexImage2D = c_glCopyTexImage2D;
    d.glCopyTexSubImage1D = c_glCopyTexSubImage1D;
    d.glCopyTexSubImage2D = c_glCopyTexSubImage2D;
    d.glCopyTexSubImage3D = c_glCopyTexSubImage3D;
    d.glFinish = c_glFinish;
    d.glFlush = c_glFlush;
    d.glDrawBuffer = c_glDrawBuffer;
    d.glDrawBuffers = c_glDrawBuffers;
    d.glViewport = c_glViewport;
    d.glBindFramebuffer = c_glBindFramebuffer;
    d.glBindFramebufferEXT = c_glBindFramebufferEXT;
    d.glFramebufferTexture1D = c_glFramebufferTexture1D;
    d.glFramebufferTexture2D = c_glFramebufferTexture2D;
    d.glFramebufferTexture3D = c_glFramebufferTexture3D;
    d.glFramebufferTextureLayer = c_glFramebufferTextureLayer;
    d.glFramebufferRenderbuffer = c_glFramebufferRenderbuffer;
    d.glGenerateMipmap = c_glGenerateMipmap;
    d.glBlitFramebuffer = c_glBlitFramebuffer;
    d.glRenderMode = c_glRenderMode;
}

void Compositor::installEnd(GlDispatch& d) { d.glEnd = cEnd; }

} // namespace nprgl
