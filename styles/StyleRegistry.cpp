#include "styles/StyleRegistry.h"

#include "styles/Style.h"
#include "styles/StyleList.h"

#include <algorithm>
#include <cstdio>
#include <string>

namespace nprgl {

namespace {

std::string formatNumber(double v)
{
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

} // namespace

ParamInfo ParamInfo::number(std::string name, std::string help, double def, double lo, double hi)
{
    ParamInfo p;
    p.name = std::move(name);
    p.help = std::move(help);
    p.defaultValue = def;
    p.minValue = lo;
    p.maxValue = hi;
    return p;
}

ParamInfo ParamInfo::keptBelow(std::string other, double gapBelow) const
{
    ParamInfo p = *this;
    p.below = std::move(other);
    p.gap = gapBelow;
    return p;
}

ParamInfo ParamInfo::flag(std::string name, std::string help, bool def)
{
    ParamInfo p = number(std::move(name), std::move(help), def ? 1.0 : 0.0, 0.0, 1.0);
    p.isFlag = true;
    return p;
}

ParamInfo ParamInfo::colour(std::string name, std::string help, std::string def)
{
    ParamInfo p = text(std::move(name), std::move(help), std::move(def));
    p.kind = ParamKind::Colour;
    return p;
}

bool ParamInfo::parseColour(const std::string& text, glm::vec3& out)
{
    const size_t skip = !text.empty() && text[0] == '#' ? 1 : 0;
    if (text.size() != skip + 6 ||
        text.find_first_not_of("0123456789abcdefABCDEF", skip) != std::string::npos) {
        return false;
    }
    const unsigned long value = std::stoul(text.substr(skip), nullptr, 16);
    out = glm::vec3(float(value >> 16 & 0xff), float(value >> 8 & 0xff), float(value & 0xff)) /
          255.0f;
    return true;
}

ParamInfo ParamInfo::choice(std::string name, std::string help, std::vector<std::string> names,
                            int def)
{
    ParamInfo p = number(std::move(name), std::move(help), def, 0.0, double(names.size() - 1));
    p.kind = ParamKind::Choice;
    p.choices = std::move(names);
    return p;
}

ParamInfo ParamInfo::text(std::string name, std::string help, std::string def)
{
    ParamInfo p;
    p.name = std::move(name);
    p.help = std::move(help);
    p.kind = ParamKind::Text;
    p.defaultText = std::move(def);
    return p;
}

std::string ParamInfo::defaultString() const
{
    switch (kind) {
    case ParamKind::Choice: return choices[size_t(defaultValue)];
    case ParamKind::Text: return defaultText.empty() ? "\"\"" : defaultText;
    case ParamKind::Colour: return defaultText.empty() ? "derived" : defaultText;
    case ParamKind::Number: break;
    }
    if (isFlag) return defaultValue != 0.0 ? "on" : "off";
    return formatNumber(defaultValue);
}

std::string ParamInfo::rangeString() const
{
    switch (kind) {
    case ParamKind::Choice: {
        std::string s;
        for (const std::string& c : choices) s += (s.empty() ? "" : "|") + c;
        return s;
    }
    case ParamKind::Text: return "file";
    case ParamKind::Colour: return "rrggbb";
    case ParamKind::Number: break;
    }
    if (isFlag) return "on|off";
    return "[" + formatNumber(minValue) + ", " + formatNumber(maxValue) + "]";
}

const ParamInfo* StyleInfo::findParam(std::string_view param) const
{
    auto it = std::find_if(params.begin(), params.end(),
                           [param](const ParamInfo& p) { return p.name == param; });
    return it == params.end() ? nullptr : &*it;
}

StyleRegistry::StyleRegistry()
{
    StyleInfo none;
    none.name = "none";
    none.summary = "passthrough: frames pixel-identical to running without nprgl";
    mStyles.push_back(std::move(none));
    styles::registerStyles(mStyles);
    mDefault = styles::kDefaultChain;
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

const ParamInfo* StyleRegistry::findParam(std::string_view key) const
{
    const size_t dot = key.find('.');
    const StyleInfo* style = dot == std::string_view::npos ? nullptr : find(key.substr(0, dot));
    return style ? style->findParam(key.substr(dot + 1)) : nullptr;
}

bool StyleRegistry::parseChain(std::string_view chain, std::vector<const StyleInfo*>& out,
                               std::string& error) const
{
    std::vector<const StyleInfo*> result;
    int shading = 0;
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
        if (std::find(result.begin(), result.end(), style) != result.end()) {
            error = "style '" + style->name + "' is named twice in '" + std::string(chain) + "'";
            return false;
        }
        if (style->create && style->role == styles::StyleRole::Shading && ++shading > 1) {
            error = "a chain takes one shading style; '" + style->name + "' is a second";
            return false;
        }
        result.push_back(style);
        if (plus == std::string_view::npos) break;
        chain.remove_prefix(plus + 1);
    }
    if (result.size() > 1 &&
        std::any_of(result.begin(), result.end(), [](auto* s) { return !s->create; })) {
        error = "style 'none' cannot be part of a chain";
        return false;
    }
    const auto isBackground = [](auto* s) { return s->role == styles::StyleRole::Background; };
    if (std::none_of(result.begin(), result.end(), isBackground)) {
        for (size_t i = 0, n = result.size(); i < n; ++i) {
            if (result[i]->background.empty()) continue;
            const StyleInfo* page = find(result[i]->background);
            if (page && std::find(result.begin(), result.end(), page) == result.end())
                result.push_back(page);
        }
    }
    out = std::move(result);
    return true;
}

} // namespace nprgl
