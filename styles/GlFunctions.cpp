#include "styles/GlFunctions.h"

namespace nprgl::styles {

bool GlFunctions::load(GetProc getProc, std::string& missing)
{
    missing.clear();
#define NPRGL_STYLE_GL_LOAD(name)                                                               \
    name = reinterpret_cast<decltype(name)>(getProc("gl" #name));                               \
    if (!name) missing += (missing.empty() ? "gl" : ", gl") + std::string(#name);
    NPRGL_STYLE_GL_FUNCTIONS(NPRGL_STYLE_GL_LOAD)
#undef NPRGL_STYLE_GL_LOAD
    return missing.empty();
}

} // namespace nprgl::styles
