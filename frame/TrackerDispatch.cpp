// The tracking dispatch: per GL command, the function that forwards it to the current tracker.
#include "frame/TrackerDispatch.h"

#include "frame/StateTracker.h"
#include "stream/GlSizes.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace nprgl {

namespace {

// Initial-exec like tThread: read per vertex, no __tls_get_addr call.
constinit thread_local StateTracker* tTracker __attribute__((tls_model("initial-exec"))) =
    nullptr;

template <typename T>
T zeroValue()
{
    return T{};
}
template <>
void zeroValue<void>()
{
}

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include "nprgl_track.inc"
#pragma GCC diagnostic pop

StateTracker& T() { return *tTracker; }

template <typename F>
glm::mat4 toMat(const F* m)
{
    glm::mat4 out;
    for (int i = 0; i < 16; ++i) glm::value_ptr(out)[i] = float(m[i]);
    return out;
}

// Hand-written tracking functions: state that decides where and how geometry is drawn.
void APIENTRY tBegin(GLenum mode) { T().begin(mode); }
void APIENTRY tEnd() { T().end(); }
void APIENTRY tMatrixMode(GLenum mode) { T().matrixMode(mode); }
void APIENTRY tLoadIdentity() { T().topMatrix() = glm::mat4(1.0f); }
void APIENTRY tLoadMatrixf(const GLfloat* m) { T().topMatrix() = toMat(m); }
void APIENTRY tLoadMatrixd(const GLdouble* m) { T().topMatrix() = toMat(m); }
void APIENTRY tMultMatrixf(const GLfloat* m) { T().topMatrix() *= toMat(m); }
void APIENTRY tMultMatrixd(const GLdouble* m) { T().topMatrix() *= toMat(m); }
void APIENTRY tLoadTransposeMatrixf(const GLfloat* m)
{
    T().topMatrix() = glm::transpose(toMat(m));
}
void APIENTRY tLoadTransposeMatrixd(const GLdouble* m)
{
    T().topMatrix() = glm::transpose(toMat(m));
}
void APIENTRY tMultTransposeMatrixf(const GLfloat* m)
{
    T().topMatrix() *= glm::transpose(toMat(m));
}
void APIENTRY tMultTransposeMatrixd(const GLdouble* m)
{
    T().topMatrix() *= glm::transpose(toMat(m));
}
void rotate(float angle, float x, float y, float z)
{
    glm::vec3 axis(x, y, z);
    if (glm::length(axis) > 0.0f) {
        T().topMatrix() = glm::rotate(T().topMatrix(), glm::radians(angle), glm::normalize(axis));
    }
}
void APIENTRY tRotatef(GLfloat a, GLfloat x, GLfloat y, GLfloat z) { rotate(a, x, y, z); }
void APIENTRY tRotated(GLdouble a, GLdouble x, GLdouble y, GLdouble z)
{
    rotate(float(a), float(x), float(y), float(z));
}
void APIENTRY tTranslatef(GLfloat x, GLfloat y, GLfloat z)
{
    T().topMatrix() = glm::translate(T().topMatrix(), glm::vec3(x, y, z));
}
void APIENTRY tTranslated(GLdouble x, GLdouble y, GLdouble z)
{
    tTranslatef(GLfloat(x), GLfloat(y), GLfloat(z));
}
void APIENTRY tScalef(GLfloat x, GLfloat y, GLfloat z)
{
    T().topMatrix() = glm::scale(T().topMatrix(), glm::vec3(x, y, z));
}
void APIENTRY tScaled(GLdouble x, GLdouble y, GLdouble z)
{
    tScalef(GLfloat(x), GLfloat(y), GLfloat(z));
}
void APIENTRY tFrustum(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f)
{
    T().topMatrix() *= glm::frustum(float(l), float(r), float(b), float(t), float(n), float(f));
}
void APIENTRY tOrtho(GLdouble l, GLdouble r, GLdouble b, GLdouble t, GLdouble n, GLdouble f)
{
    T().topMatrix() *= glm::ortho(float(l), float(r), float(b), float(t), float(n), float(f));
}
void APIENTRY tPushMatrix() { T().pushMatrix(); }
void APIENTRY tPopMatrix() { T().popMatrix(); }
void APIENTRY tEnable(GLenum cap) { T().setEnabled(cap, true); }
void APIENTRY tDisable(GLenum cap) { T().setEnabled(cap, false); }
void APIENTRY tUseProgram(GLuint program) { T().useProgram(program); }
void APIENTRY tMaterialfv(GLenum face, GLenum pname, const GLfloat* v)
{
    T().material(face, pname, v);
}
void APIENTRY tMaterialf(GLenum face, GLenum pname, GLfloat v)
{
    // Only single-valued pnames are valid here (the driver refuses the others).
    const float values[4] = {v, 0.0f, 0.0f, 0.0f};
    if (pnameCount(pname) == 1) T().material(face, pname, values);
}
// glMateriali is glMaterialf's integer twin: its one value (the shininess) an exponent.
void APIENTRY tMateriali(GLenum face, GLenum pname, GLint v) { tMaterialf(face, pname, float(v)); }
void APIENTRY tMaterialiv(GLenum face, GLenum pname, const GLint* v)
{
    float f[4];
    for (size_t i = 0; i < pnameCount(pname) && i < 4; ++i) f[i] = float(v[i]) / 2147483647.0f;
    if (pname == GL_SHININESS) f[0] = float(v[0]); // an exponent, not a colour
    T().material(face, pname, f);
}
void APIENTRY tNewList(GLuint list, GLenum mode) { T().newList(list, mode); }
void APIENTRY tEndList() { T().endList(); }
void APIENTRY tCallList(GLuint list) { T().callList(list); }
void APIENTRY tListBase(GLuint base) { T().listBase(base); }
void APIENTRY tDeleteLists(GLuint list, GLsizei range) { T().deleteLists(list, range); }
void APIENTRY tBindTexture(GLenum target, GLuint texture) { T().bindTexture(target, texture); }
// glTexGen{i,f,d}[v]: the mode (one value) and the planes (four).
template <typename P> void APIENTRY tTexGen(GLenum coord, GLenum pname, P param)
{
    const double value = double(param);
    T().texGen(coord, pname, &value, 1);
}
template <typename P> void APIENTRY tTexGenv(GLenum coord, GLenum pname, const P* params)
{
    if (!params) return;
    const size_t count = pname == GL_TEXTURE_GEN_MODE ? 1 : 4;
    double values[4] = {};
    for (size_t i = 0; i < count; ++i) values[i] = double(params[i]);
    T().texGen(coord, pname, values, count);
}
void APIENTRY tTexEnvi(GLenum target, GLenum pname, GLint param)
{
    T().texEnv(target, pname, GLenum(param));
}
void APIENTRY tTexEnvf(GLenum target, GLenum pname, GLfloat param)
{
    T().texEnv(target, pname, enumOf(param));
}
void APIENTRY tTexEnviv(GLenum target, GLenum pname, const GLint* params)
{
    if (params) T().texEnv(target, pname, GLenum(params[0]));
}
void APIENTRY tTexEnvfv(GLenum target, GLenum pname, const GLfloat* params)
{
    // GL_TEXTURE_ENV_COLOR is four floats; the mode is one.
    if (params && (pname == GL_TEXTURE_ENV_MODE || pname == GL_RGB_SCALE)) {
        T().texEnv(target, pname, enumOf(params[0]));
    }
}
void APIENTRY tTexImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                          GLsizei height, GLint, GLenum format, GLenum type, const void* pixels)
{
    T().texImage2D(target, level, internalFormat, width, height, format, type, pixels);
}
void APIENTRY tCopyTexImage2D(GLenum target, GLint level, GLenum internalFormat, GLint, GLint,
                              GLsizei, GLsizei, GLint)
{
    T().texStorage2D(target, level, internalFormat, false);
}
void APIENTRY tTexStorage2D(GLenum target, GLsizei, GLenum internalFormat, GLsizei, GLsizei)
{
    T().texStorage2D(target, 0, internalFormat, true);
}
void APIENTRY tTexSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei width,
                             GLsizei height, GLenum format, GLenum type, const void* pixels)
{
    T().texSubImage2D(target, level, x, y, width, height, format, type, pixels);
}
void APIENTRY tCopyTexSubImage2D(GLenum target, GLint level, GLint, GLint, GLint, GLint,
                                 GLsizei, GLsizei)
{
    T().texCopiedInto(target, level);
}
void APIENTRY tFramebufferTexture2D(GLenum, GLenum, GLenum, GLuint texture, GLint level)
{
    if (level == 0) T().textureAttached(texture);
}
void APIENTRY tActiveTexture(GLenum unit) { T().activeTexture(unit); }
void APIENTRY tEnableClientState(GLenum cap) { T().enableArray(cap, true); }
void APIENTRY tDisableClientState(GLenum cap) { T().enableArray(cap, false); }
void APIENTRY tClientActiveTexture(GLenum unit) { T().clientActiveTexture(unit); }
void APIENTRY tVertexPointer(GLint size, GLenum type, GLsizei stride, const void* p)
{
    T().arrayPointer(kVertexArray, size, type, stride, p);
}
void APIENTRY tNormalPointer(GLenum type, GLsizei stride, const void* p)
{
    T().arrayPointer(kNormalArray, 3, type, stride, p);
}
void APIENTRY tColorPointer(GLint size, GLenum type, GLsizei stride, const void* p)
{
    T().arrayPointer(kColorArray, size, type, stride, p);
}
void APIENTRY tTexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* p)
{
    T().arrayPointer(T().texCoordSlot(), size, type, stride, p);
}
void APIENTRY tBindBuffer(GLenum target, GLuint buffer) { T().bindBuffer(target, buffer); }
void APIENTRY tBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum)
{
    T().bufferData(target, size, data);
}
void APIENTRY tBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, const void* data)
{
    T().bufferSubData(target, offset, size, data);
}
void APIENTRY tDrawArrays(GLenum mode, GLint first, GLsizei count)
{
    T().drawArrays(mode, first, count);
}
void APIENTRY tDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices)
{
    T().drawElements(mode, count, type, indices);
}
void APIENTRY tDrawRangeElements(GLenum mode, GLuint, GLuint, GLsizei count, GLenum type,
                                 const void* indices)
{
    T().drawElements(mode, count, type, indices);
}
void APIENTRY tMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count, GLsizei n)
{
    for (GLsizei i = 0; first && count && i < n; ++i) T().drawArrays(mode, first[i], count[i]);
}
void APIENTRY tArrayElement(GLint i) { T().arrayElement(i); }
void APIENTRY tRectf(GLfloat a, GLfloat b, GLfloat c, GLfloat d) { T().rect(a, b, c, d); }
void APIENTRY tRectd(GLdouble a, GLdouble b, GLdouble c, GLdouble d)
{
    T().rect(float(a), float(b), float(c), float(d));
}
void APIENTRY tRecti(GLint a, GLint b, GLint c, GLint d)
{
    T().rect(float(a), float(b), float(c), float(d));
}
void APIENTRY tRects(GLshort a, GLshort b, GLshort c, GLshort d)
{
    T().rect(float(a), float(b), float(c), float(d));
}

void APIENTRY tLightfv(GLenum light, GLenum pname, const GLfloat* v) { T().light(light, pname, v); }
void APIENTRY tLightiv(GLenum light, GLenum pname, const GLint* v)
{
    // Integer colours map their range onto -1..1; positions and the rest are taken as they are.
    const bool colour = pname == GL_AMBIENT || pname == GL_DIFFUSE || pname == GL_SPECULAR;
    float f[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < pnameCount(pname) && i < 4; ++i)
        f[i] = colour ? float(v[i]) / 2147483647.0f : float(v[i]);
    T().light(light, pname, f);
}
void APIENTRY tLightf(GLenum light, GLenum pname, GLfloat v) { T().light(light, pname, &v); }
void APIENTRY tLighti(GLenum light, GLenum pname, GLint v)
{
    const float f = float(v);
    T().light(light, pname, &f);
}
void APIENTRY tLightModelfv(GLenum pname, const GLfloat* v) { T().lightModel(pname, v); }
void APIENTRY tLightModeliv(GLenum pname, const GLint* v)
{
    float f[4] = {0, 0, 0, 0};
    if (pname == GL_LIGHT_MODEL_AMBIENT) {
        for (size_t i = 0; i < 4; ++i) f[i] = float(v[i]) / 2147483647.0f;
    } else if (v) {
        f[0] = float(v[0]);
    }
    T().lightModel(pname, f);
}
// Scalar forms (GL_LIGHT_MODEL_LOCAL_VIEWER, GL_LIGHT_MODEL_TWO_SIDE): as a vector's first.
void APIENTRY tLightModelf(GLenum pname, GLfloat v)
{
    const float f[4] = {v, 0, 0, 0};
    if (pname != GL_LIGHT_MODEL_AMBIENT) T().lightModel(pname, f);
}
void APIENTRY tLightModeli(GLenum pname, GLint v) { tLightModelf(pname, float(v)); }
void APIENTRY tShadeModel(GLenum mode) { T().shadeModel(mode); }
void APIENTRY tPolygonMode(GLenum face, GLenum mode) { T().polygonMode(face, mode); }
void APIENTRY tColorMaterial(GLenum face, GLenum mode) { T().colorMaterial(face, mode); }
void APIENTRY tColorMask(GLboolean r, GLboolean g, GLboolean b, GLboolean a)
{
    T().colorMask(r, g, b, a);
}
void APIENTRY tViewport(GLint x, GLint y, GLsizei w, GLsizei h)
{
    if (w >= 0 && h >= 0) T().setViewport({x, y, w, h});
}
void APIENTRY tDepthRange(GLdouble n, GLdouble f) { T().setDepthRange(float(n), float(f)); }
void APIENTRY tDepthRangef(GLfloat n, GLfloat f) { T().setDepthRange(n, f); }
void APIENTRY tScissor(GLint x, GLint y, GLsizei w, GLsizei h)
{
    if (w >= 0 && h >= 0) T().setScissor({x, y, w, h});
}
void APIENTRY tBlendFunc(GLenum src, GLenum dst) { T().blendFunc(src, dst); }
void APIENTRY tBlendFuncSeparate(GLenum srcRgb, GLenum dstRgb, GLenum, GLenum)
{
    T().blendFunc(srcRgb, dstRgb);
}
void APIENTRY tDepthMask(GLboolean flag) { T().depthMask(flag == GL_TRUE); }
void APIENTRY tDepthFunc(GLenum func) { T().depthFunc(func); }
void APIENTRY tAlphaFunc(GLenum func, GLfloat ref) { T().alphaFunc(func, ref); }
void APIENTRY tPolygonOffset(GLfloat factor, GLfloat units) { T().polygonOffset(factor, units); }
void APIENTRY tCullFace(GLenum mode)
{
    if (mode == GL_FRONT || mode == GL_BACK || mode == GL_FRONT_AND_BACK) T().cullMode(mode);
}
void APIENTRY tFrontFace(GLenum mode)
{
    if (mode == GL_CW || mode == GL_CCW) T().frontFace(mode);
}
void APIENTRY tFogf(GLenum pname, GLfloat v) { T().fog(pname, &v, 1); }
void APIENTRY tFogi(GLenum pname, GLint v)
{
    const float f = float(v);
    T().fog(pname, &f, 1);
}
void APIENTRY tFogfv(GLenum pname, const GLfloat* v)
{
    if (v) T().fog(pname, v, pname == GL_FOG_COLOR ? 4 : 1);
}
void APIENTRY tFogiv(GLenum pname, const GLint* v)
{
    if (!v) return;
    // Integer colours map the full int range to [-1, 1], as glFogiv's do.
    float f[4] = {};
    const size_t n = pname == GL_FOG_COLOR ? 4 : 1;
    for (size_t i = 0; i < n; ++i) {
        f[i] = pname == GL_FOG_COLOR ? float(v[i]) / 2147483647.0f : float(v[i]);
    }
    T().fog(pname, f, n);
}
void APIENTRY tPushAttrib(GLbitfield mask) { T().pushAttrib(mask); }
void APIENTRY tPopAttrib() { T().popAttrib(); }
void APIENTRY tPushClientAttrib(GLbitfield) { T().pushClientAttrib(); }
void APIENTRY tPopClientAttrib() { T().popClientAttrib(); }
void APIENTRY tBitmap(GLsizei, GLsizei, GLfloat, GLfloat, GLfloat, GLfloat, const GLubyte*)
{
    T().otherDraw();
}
void APIENTRY tDrawPixels(GLsizei, GLsizei, GLenum, GLenum, const void*) { T().otherDraw(); }
void APIENTRY tCopyPixels(GLint, GLint, GLsizei, GLsizei, GLenum) { T().otherDraw(); }

// While a list compiles: what it will call (for deciding whether it can be held).
void APIENTRY tCallListCompiled(GLuint list) { T().noteCompiledCall(list); }
// While a list compiles, a material between glBegin and glEnd still colours the batch's
// vertices from there on (its state change is kept for the list's execution).
void APIENTRY tMaterialfvCompiled(GLenum face, GLenum pname, const GLfloat* v)
{
    T().batchMaterial(face, pname, v);
}
void APIENTRY tCallListsCompiled(GLsizei, GLenum, const void*) { T().otherDraw(); }

void APIENTRY tCallLists(GLsizei n, GLenum type, const void* lists)
{
    T().callLists(n, type, lists);
}

} // namespace

StateTracker& currentTracker() { return *tTracker; }

TrackerScope::TrackerScope(StateTracker& tracker) : mPrevious(tTracker) { tTracker = &tracker; }

TrackerScope::~TrackerScope() { tTracker = mPrevious; }

void fillTrackerDispatch(GlDispatch& d, GlDispatch& compileOnly)
{
    fillTrackingDispatch(compileOnly);
    fillTrackingDispatch(d);
    d.glBegin = tBegin;
    d.glEnd = tEnd;
    d.glMatrixMode = tMatrixMode;
    d.glLoadIdentity = tLoadIdentity;
    d.glLoadMatrixf = tLoadMatrixf;
    d.glLoadMatrixd = tLoadMatrixd;
    d.glMultMatrixf = tMultMatrixf;
    d.glMultMatrixd = tMultMatrixd;
    d.glLoadTransposeMatrixf = tLoadTransposeMatrixf;
    d.glLoadTransposeMatrixd = tLoadTransposeMatrixd;
    d.glMultTransposeMatrixf = tMultTransposeMatrixf;
    d.glMultTransposeMatrixd = tMultTransposeMatrixd;
    d.glRotatef = tRotatef;
    d.glRotated = tRotated;
    d.glTranslatef = tTranslatef;
    d.glTranslated = tTranslated;
    d.glScalef = tScalef;
    d.glScaled = tScaled;
    d.glFrustum = tFrustum;
    d.glOrtho = tOrtho;
    d.glPushMatrix = tPushMatrix;
    d.glPopMatrix = tPopMatrix;
    d.glEnable = tEnable;
    d.glDisable = tDisable;
    d.glUseProgram = tUseProgram;
    d.glMaterialfv = tMaterialfv;
    d.glMaterialf = tMaterialf;
    d.glMateriali = tMateriali;
    d.glMaterialiv = tMaterialiv;
    d.glNewList = tNewList;
    d.glEndList = tEndList;
    d.glCallList = tCallList;
    d.glCallLists = tCallLists;
    d.glListBase = tListBase;
    d.glDeleteLists = tDeleteLists;
    d.glBindTexture = tBindTexture;
    d.glTexImage2D = tTexImage2D;
    d.glTexSubImage2D = tTexSubImage2D;
    d.glCopyTexImage2D = tCopyTexImage2D;
    d.glCopyTexSubImage2D = tCopyTexSubImage2D;
    d.glFramebufferTexture2D = tFramebufferTexture2D;
    d.glTexStorage2D = tTexStorage2D;
    d.glTexEnvi = tTexEnvi;
    d.glTexGeni = tTexGen<GLint>;
    d.glTexGenf = tTexGen<GLfloat>;
    d.glTexGend = tTexGen<GLdouble>;
    d.glTexGeniv = tTexGenv<GLint>;
    d.glTexGenfv = tTexGenv<GLfloat>;
    d.glTexGendv = tTexGenv<GLdouble>;
    d.glTexEnvf = tTexEnvf;
    d.glTexEnviv = tTexEnviv;
    d.glTexEnvfv = tTexEnvfv;
    d.glActiveTexture = tActiveTexture;
    d.glEnableClientState = tEnableClientState;
    d.glDisableClientState = tDisableClientState;
    d.glClientActiveTexture = tClientActiveTexture;
    d.glVertexPointer = tVertexPointer;
    d.glNormalPointer = tNormalPointer;
    d.glColorPointer = tColorPointer;
    d.glTexCoordPointer = tTexCoordPointer;
    d.glBindBuffer = tBindBuffer;
    d.glBufferData = tBufferData;
    d.glBufferSubData = tBufferSubData;
    d.glDrawArrays = tDrawArrays;
    d.glDrawElements = tDrawElements;
    d.glDrawRangeElements = tDrawRangeElements;
    d.glMultiDrawArrays = tMultiDrawArrays;
    d.glArrayElement = tArrayElement;
    d.glRectf = tRectf;
    d.glRectd = tRectd;
    d.glRecti = tRecti;
    d.glRects = tRects;
    d.glLightf = tLightf;
    d.glLighti = tLighti;
    d.glLightfv = tLightfv;
    d.glLightiv = tLightiv;
    d.glLightModelfv = tLightModelfv;
    d.glLightModeliv = tLightModeliv;
    d.glLightModelf = tLightModelf;
    d.glLightModeli = tLightModeli;
    d.glShadeModel = tShadeModel;
    d.glPolygonMode = tPolygonMode;
    d.glColorMask = tColorMask;
    d.glColorMaterial = tColorMaterial;
    d.glBlendFunc = tBlendFunc;
    d.glBlendFuncSeparate = tBlendFuncSeparate;
    d.glDepthMask = tDepthMask;
    d.glDepthFunc = tDepthFunc;
    d.glAlphaFunc = tAlphaFunc;
    d.glPolygonOffset = tPolygonOffset;
    d.glCullFace = tCullFace;
    d.glFrontFace = tFrontFace;
    d.glFogf = tFogf;
    d.glFogi = tFogi;
    d.glFogfv = tFogfv;
    d.glFogiv = tFogiv;
    d.glViewport = tViewport;
    d.glDepthRange = tDepthRange;
    d.glDepthRangef = tDepthRangef;
    d.glScissor = tScissor;
    d.glPushAttrib = tPushAttrib;
    d.glPopAttrib = tPopAttrib;
    d.glPushClientAttrib = tPushClientAttrib;
    d.glPopClientAttrib = tPopClientAttrib;
    d.glBitmap = tBitmap;
    d.glDrawPixels = tDrawPixels;
    d.glCopyPixels = tCopyPixels;
    // While a list compiles, these only mark it as drawing something that is not held.
    compileOnly.glBitmap = tBitmap;
    compileOnly.glDrawPixels = tDrawPixels;
    compileOnly.glCopyPixels = tCopyPixels;
    compileOnly.glCallList = tCallListCompiled;
    compileOnly.glMaterialfv = tMaterialfvCompiled;
    compileOnly.glCallLists = tCallListsCompiled;
}

} // namespace nprgl
