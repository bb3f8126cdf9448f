#include "cli/StylesCommand.h"

#include "styles/StyleRegistry.h"

#include <cstdio>

namespace nprgl::cli {

int listStyles()
{
    const StyleRegistry& registry = StyleRegistry::instance();
    for (const StyleInfo& style : registry.styles()) {
        std::printf("%s%s\n    %s\n", style.name.c_str(),
                    style.name == registry.defaultStyle() ? " (default)" : "",
                    style.summary.c_str());
        for (const ParamInfo& p : style.params) {
            std::printf("    %s.%s = %g  [%g, %g]  %s\n", style.name.c_str(), p.name.c_str(),
                        p.defaultValue, p.minValue, p.maxValue, p.help.c_str());
        }
        if (style.params.empty()) std::printf("    (no parameters)\n");
    }
    std::printf("\nChain styles with '+', e.g. --style toon+edges; set parameters with "
                "--set style.param=value.\n");
    return 0;
}

} // namespace nprgl::cli
