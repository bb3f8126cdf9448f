#pragma once

// The GL entry points the styles call, loaded from the real driver (never nprgl's own
// thunks, which would record or hold back the styles' own draws). GL 1.0-3.0 compatibility.

#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

namespace nprgl::styles {

// X(name): the member `name` holds the driver's `gl##name`.
#define NPRGL_STYLE_GL_FUNCTIONS(X)                                                             \
    X(ActiveTexture) X(AlphaFunc) X(AttachShader) X(BeginQuery) X(BindAttribLocation) X(BindBuffer)          \
    X(BindFragDataLocation) X(BindFramebuffer) X(BindRenderbuffer) X(BindTexture)               \
    X(BindVertexArray) X(BlendEquation) X(BlendFunc) X(BlendFuncSeparate) X(BlitFramebuffer)    \
    X(BufferData) X(BufferSubData) X(CheckFramebufferStatus) X(Clear) X(ClearColor)             \
    X(ClearDepth) X(ClearStencil) X(ColorMask) X(CompileShader) X(CreateProgram)                \
    X(CreateShader) X(CullFace) X(DeleteBuffers) X(DeleteFramebuffers) X(DeleteProgram)         \
    X(DeleteQueries) X(DeleteRenderbuffers) X(DeleteShader) X(DeleteTextures)                   \
    X(DeleteVertexArrays) X(DepthFunc) X(DepthMask) X(DepthRange) X(Disable)                    \
    X(DisableVertexAttribArray) X(DrawArrays) X(DrawBuffer) X(DrawBuffers) X(DrawElements)      \
    X(Enable) X(EnableVertexAttribArray) X(EndQuery) X(Finish) X(Flush)                         \
    X(FramebufferRenderbuffer) X(FramebufferTexture2D) X(FrontFace) X(GenVertexArrays)          \
    X(IsBuffer) X(IsFramebuffer) X(IsQuery) X(IsRenderbuffer) X(IsTexture)                      \
    X(GenerateMipmap) X(GetBooleanv) X(GetError) X(GetFloatv) X(GetIntegerv) X(GetProgramInfoLog) \
    X(GetProgramiv) X(GetQueryObjectuiv) X(GetShaderInfoLog) X(GetShaderiv) X(GetString)        \
    X(GetTexImage) X(GetTexLevelParameteriv) X(GetTexParameteriv) X(GetUniformLocation) X(Hint) \
    X(IsEnabled) X(LineWidth)                                                                   \
    X(LinkProgram) X(PixelStorei) X(PointSize) X(PolygonMode) X(PolygonOffset) X(ReadBuffer)    \
    X(ReadPixels) X(RenderbufferStorage) X(Scissor) X(ShaderSource) X(StencilFunc)              \
    X(StencilMask) X(StencilOp) X(TexImage2D) X(TexParameterf) X(TexParameteri) X(TexParameteriv) \
    X(TexSubImage2D) X(Uniform1f) X(Uniform1fv) X(Uniform1i) X(Uniform2f) X(Uniform3f)         \
    X(Uniform3fv) X(Uniform4f) X(Uniform4fv) X(UniformMatrix3fv) X(UniformMatrix4fv)          \
    X(UseProgram) X(Uniform2i) \
    X(CopyTexSubImage2D) \
    X(ClearBufferuiv) \
    X(Uniform4i) \
    X(VertexAttrib4f) X(VertexAttribPointer) X(Viewport)

struct GlFunctions {
#define NPRGL_STYLE_GL_MEMBER(name) decltype(&::gl##name) name = nullptr;
    NPRGL_STYLE_GL_FUNCTIONS(NPRGL_STYLE_GL_MEMBER)
#undef NPRGL_STYLE_GL_MEMBER

    // Optional (GL 3.3, ARB_blend_func_extended): null where the driver lacks dual-source
    // blending.
    PFNGLBINDFRAGDATALOCATIONINDEXEDPROC BindFragDataLocationIndexed = nullptr;

    using GetProc = void* (*)(const char* name);
    // Resolves every entry; false with the missing names when the driver lacks some.
    bool load(GetProc getProc, std::string& missing);
};

} // namespace nprgl::styles
