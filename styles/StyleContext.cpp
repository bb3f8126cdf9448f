#include "styles/Style.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/StyleSettings.h"

namespace nprgl::styles {

double StyleContext::param(const char* style, const char* name) const
{
    return settings ? settings->value(style, name) : 0.0;
}

std::string StyleContext::text(const char* style, const char* name) const
{
    return settings ? settings->text(style, name) : std::string();
}

glm::vec3 StyleContext::colour(const char* style, const char* name, const char* fallback) const
{
    glm::vec3 out(0.0f);
    const std::string configured = text(style, name);
    if (ParamInfo::parseColour(configured, out)) return out;
    NPRGL_WARN("%s.%s='%s' is not a hex colour rrggbb; using %s", style, name,
               configured.c_str(), fallback);
    ParamInfo::parseColour(fallback, out);
    return out;
}

void StyleContext::scissorTo(const Scene& scene, glm::ivec4 rect) const
{
    rect = scene.confined(rect);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(rect.x, rect.y, rect.z, rect.w);
}

void StyleContext::endScissor(const Scene& scene) const
{
    if (!scene.scissored) {
        gl.Disable(GL_SCISSOR_TEST);
        return;
    }
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(scene.scissor.x, scene.scissor.y, scene.scissor.z, scene.scissor.w);
}

} // namespace nprgl::styles
