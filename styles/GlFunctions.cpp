#include "styles/GlFunctions.h"

#include <string_view>

namespace nprgl::styles {

bool GlFunctions::load(GetProc getProc, std::string& missing)
{
    missing.clear();
#define NPRGL_STYLE_GL_LOAD(name)                                                               \
    name = reinterpret_cast<decltype(name)>(getProc("gl" #name));                               \
    if (!name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
    NPRGL_STYLE_GL_FUNCTIONS(NPRGL_STYLE_GL_LOAD)
#undef NPRGL_STYLE_GL_LOAD
    if (!missing.empty()) return false;
    // A GLX driver answers every name with some pointer: ask for the feature itself.
    GLint count = 0;
    GetIntegerv(GL_NUM_EXTENSIONS, &count);
    auto getStringi = reinterpret_cast<PFNGLGETSTRINGIPROC>(getProc("glGetStringi"));
    for (GLint i = 0; getStringi && i < count; ++i) {
        const auto* name = reinterpret_cast<const char*>(getStringi(GL_EXTENSIONS, GLuint(i)));
        if (name && std::string_view(name) == "GL_ARB_blend_func_extended") {
            BindFragDataLocationIndexed = reinterpret_cast<PFNGLBINDFRAGDATALOCATIONINDEXEDPROC>(
                getProc("glBindFragDataLocationIndexed"));
            break;
        }
    }
    return true;
}

} // namespace nprgl::styles
