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

} // namespace nprgl::styles
