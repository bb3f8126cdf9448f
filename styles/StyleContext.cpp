#include "styles/Style.h"

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

} // namespace nprgl::styles
