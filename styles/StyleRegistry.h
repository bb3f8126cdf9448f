#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace nprgl {

// One tunable parameter of a style, with its range. Values are numbers (bools are 0/1).
struct ParamInfo {
    std::string name;
    std::string help;
    double defaultValue = 0.0;
    double minValue = 0.0;
    double maxValue = 0.0;
};

struct StyleInfo {
    std::string name;
    std::string summary;
    std::vector<ParamInfo> params;

    const ParamInfo* findParam(std::string_view param) const;
};

// Every style nprgl knows, registered once at start-up. A chain such as "toon+edges" names
// several of them, applied left to right.
class StyleRegistry {
public:
    static const StyleRegistry& instance();

    const std::vector<StyleInfo>& styles() const { return mStyles; }
    const StyleInfo* find(std::string_view name) const;
    // The style used when none is named.
    const std::string& defaultStyle() const { return mDefault; }

    // Splits and checks a chain; on failure returns false with a message naming the style.
    bool parseChain(std::string_view chain, std::vector<const StyleInfo*>& out,
                    std::string& error) const;

private:
    StyleRegistry();

    std::vector<StyleInfo> mStyles;
    std::string mDefault;
};

} // namespace nprgl
