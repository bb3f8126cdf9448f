#include "styles/StyleSettings.h"

#include "common/KeyValue.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace nprgl {

namespace {

bool parseValue(const std::string& text, double& out)
{
    if (text == "true" || text == "on" || text == "yes") return out = 1.0, true;
    if (text == "false" || text == "off" || text == "no") return out = 0.0, true;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && ptr == text.data() + text.size() && std::isfinite(out);
}

} // namespace

bool StyleSettings::parse(const std::string& chain, const std::string& config,
                          StyleSettings& out, std::string& error)
{
    const StyleRegistry& registry = StyleRegistry::instance();
    StyleSettings settings;
    if (!registry.parseChain(chain.empty() ? registry.defaultStyle() : chain, settings.mChain,
                             error)) {
        return false;
    }
    KeyValueList pairs;
    if (!parseKeyValues(config, ',', pairs, error)) return false;
    for (const auto& [key, text] : pairs) {
        size_t dot = key.find('.');
        const StyleInfo* style = dot == std::string::npos ? nullptr
                                                          : registry.find(key.substr(0, dot));
        const ParamInfo* param = style ? style->findParam(key.substr(dot + 1)) : nullptr;
        if (!param) {
            error = "unknown parameter '" + key + "' (see `nprgl styles`)";
            return false;
        }
        if (param->kind == ParamKind::Colour && !text.empty() && !ParamInfo::isColour(text)) {
            error =
                "parameter " + key + ": '" + text + "' is not a colour (use rrggbb, e.g. 1a2b3c)";
            return false;
        }
        if (param->kind == ParamKind::Text || param->kind == ParamKind::Colour) {
            settings.mTexts[key] = text;
            continue;
        }
        double value;
        if (param->kind == ParamKind::Choice) {
            auto it = std::find(param->choices.begin(), param->choices.end(), text);
            if (it == param->choices.end()) {
                error = "parameter " + key + ": '" + text + "' is not one of " +
                        param->rangeString();
                return false;
            }
            value = double(it - param->choices.begin());
        } else if (!parseValue(text, value)) {
            error = "parameter " + key + ": '" + text + "' is not a number";
            return false;
        } else if (value < param->minValue || value > param->maxValue) {
            error = "parameter " + key + "=" + text + " is out of range " + param->rangeString();
            return false;
        }
        settings.mValues[key] = value;
    }
    out = std::move(settings);
    return true;
}

std::string StyleSettings::chainName() const
{
    std::string name;
    for (const StyleInfo* s : mChain) name += (name.empty() ? "" : "+") + s->name;
    return name;
}

double StyleSettings::value(const std::string& style, const std::string& param) const
{
    if (auto it = mValues.find(style + "." + param); it != mValues.end()) return it->second;
    const StyleInfo* info = StyleRegistry::instance().find(style);
    const ParamInfo* p = info ? info->findParam(param) : nullptr;
    return p ? p->defaultValue : 0.0;
}

} // namespace nprgl

namespace nprgl {

std::string StyleSettings::text(const std::string& style, const std::string& param) const
{
    if (auto it = mTexts.find(style + "." + param); it != mTexts.end()) return it->second;
    const StyleInfo* info = StyleRegistry::instance().find(style);
    const ParamInfo* p = info ? info->findParam(param) : nullptr;
    return p ? p->defaultText : std::string();
}

} // namespace nprgl
