#include "cli/StylesCommand.h"

#include "styles/Presets.h"
#include "styles/Style.h"
#include "styles/StyleRegistry.h"

#include <cstdio>

namespace nprgl::cli {

int listStyles()
{
    const StyleRegistry& registry = StyleRegistry::instance();
    std::printf("Styles (default chain: %s)\n\n", registry.defaultStyle().c_str());
    for (const StyleInfo& style : registry.styles()) {
        const char* role = !style.create                                  ? ""
                           : style.role == styles::StyleRole::Shading    ? " [shading]"
                           : style.role == styles::StyleRole::Background ? " [background]"
                                                                         : " [outline]";
        std::printf("%s%s\n    %s\n", style.name.c_str(), role, style.summary.c_str());
        for (const ParamInfo& p : style.params) {
            std::printf("    %-34s %-12s %-22s %s\n", (style.name + "." + p.name).c_str(),
                        p.defaultString().c_str(), p.rangeString().c_str(), p.help.c_str());
        }
        if (style.params.empty()) std::printf("    (no parameters)\n");
        std::printf("\n");
    }
    std::printf("Presets (--preset NAME, or a file of key=value lines with # comments)\n\n");
    for (const Preset& p : Presets::shipped()) std::printf("    %-12s %s\n", p.name, p.summary);
    std::printf("\nA chain is one shading style and any outline styles joined with '+', e.g. "
                "--style toon+edges;\nset parameters with --set style.param=value (columns: "
                "parameter, default, range, meaning).\n");
    return 0;
}

} // namespace nprgl::cli
