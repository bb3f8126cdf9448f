#include "styles/StyleSettings.h"

#include "common/KeyValue.h"
#include "common/Log.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <mutex>
#include <set>

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

bool StyleSettings::check(const std::string& key, const std::string& text,
                          const ParamInfo*& param, double& value, std::string& error)
{
    param = StyleRegistry::instance().findParam(key);
    if (!param) {
        error = "unknown parameter '" + key + "' (see `nprgl styles`)";
        return false;
    }
    switch (param->kind) {
    case ParamKind::Text: return true;
    case ParamKind::Colour:
        if (glm::vec3 c; text.empty() || ParamInfo::parseColour(text, c)) return true;
        error = "parameter " + key + ": '" + text + "' is not a colour (use rrggbb, e.g. 1a2b3c)";
        return false;
    case ParamKind::Choice: {
        auto it = std::find(param->choices.begin(), param->choices.end(), text);
        if (it == param->choices.end()) {
            error = "parameter " + key + ": '" + text + "' is not one of " + param->rangeString();
            return false;
        }
        value = double(it - param->choices.begin());
        return true;
    }
    case ParamKind::Number: break;
    }
    if (!parseValue(text, value)) {
        error = "parameter " + key + ": '" + text + "' is not a number";
        return false;
    }
    if (value < param->minValue || value > param->maxValue) {
        error = "parameter " + key + "=" + text + " is out of range " + param->rangeString();
        return false;
    }
    return true;
}

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
        const ParamInfo* param = nullptr;
        double value = 0.0;
        if (!check(key, text, param, value, error)) return false;
        if (param->kind == ParamKind::Text || param->kind == ParamKind::Colour) {
            settings.mTexts[key] = text;
        } else {
            settings.mValues[key] = value;
        }
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

namespace {

// The registry's parameter `key`; a style reading one it does not declare (a misspelt name in
// nprgl's own code) is said once per name, where it would otherwise read 0 silently.
const ParamInfo* declaredParam(const std::string& key)
{
    const ParamInfo* p = StyleRegistry::instance().findParam(key);
    if (!p) {
        static std::mutex mutex;
        static std::set<std::string> said;
        std::lock_guard lock(mutex);
        if (said.insert(key).second) {
            NPRGL_ERROR("a style reads the parameter %s, which no style declares (a fault in "
                        "nprgl): it gets 0 or empty text",
                        key.c_str());
        }
    }
    return p;
}

} // namespace

double StyleSettings::value(const std::string& style, const std::string& param) const
{
    const std::string key = style + "." + param;
    if (auto it = mValues.find(key); it != mValues.end()) return it->second;
    const ParamInfo* p = declaredParam(key);
    return p ? p->defaultValue : 0.0;
}

} // namespace nprgl

namespace nprgl {

std::string StyleSettings::configText() const
{
    std::map<std::string, std::string> items(mTexts.begin(), mTexts.end());
    for (const auto& [key, value] : mValues) {
        const ParamInfo* p = StyleRegistry::instance().findParam(key);
        if (p && p->kind == ParamKind::Choice) {
            const size_t i = size_t(value);
            items[key] = i < p->choices.size() ? p->choices[i] : p->defaultString();
        } else {
            char text[32]; // enough for any double in shortest form
            items[key] = std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
        }
    }
    std::string out;
    for (const auto& [key, value] : items) out += (out.empty() ? "" : ",") + key + "=" + value;
    return out;
}

std::string StyleSettings::text(const std::string& style, const std::string& param) const
{
    const std::string key = style + "." + param;
    if (auto it = mTexts.find(key); it != mTexts.end()) return it->second;
    const ParamInfo* p = declaredParam(key);
    return p ? p->defaultText : std::string();
}

} // namespace nprgl
