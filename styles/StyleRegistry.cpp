#include "styles/StyleRegistry.h"

#include <algorithm>

namespace nprgl {

const ParamInfo* StyleInfo::findParam(std::string_view param) const
{
    auto it = std::find_if(params.begin(), params.end(),
                           [param](const ParamInfo& p) { return p.name == param; });
    return it == params.end() ? nullptr : &*it;
}

StyleRegistry::StyleRegistry()
{
    mStyles.push_back({"none", "passthrough: frames pixel-identical to running without nprgl", {}});
    mDefault = "none";
}

const StyleRegistry& StyleRegistry::instance()
{
    static const StyleRegistry registry;
    return registry;
}

const StyleInfo* StyleRegistry::find(std::string_view name) const
{
    auto it = std::find_if(mStyles.begin(), mStyles.end(),
                           [name](const StyleInfo& s) { return s.name == name; });
    return it == mStyles.end() ? nullptr : &*it;
}

bool StyleRegistry::parseChain(std::string_view chain, std::vector<const StyleInfo*>& out,
                               std::string& error) const
{
    std::vector<const StyleInfo*> result;
    while (true) {
        size_t plus = chain.find('+');
        std::string_view name = chain.substr(0, plus);
        const StyleInfo* style = find(name);
        if (!style) {
            std::string known;
            for (const StyleInfo& s : mStyles) known += (known.empty() ? "" : ", ") + s.name;
            error = "unknown style '" + std::string(name) + "' (known: " + known + ")";
            return false;
        }
        result.push_back(style);
        if (plus == std::string_view::npos) break;
        chain.remove_prefix(plus + 1);
    }
    out = std::move(result);
    return true;
}

} // namespace nprgl
