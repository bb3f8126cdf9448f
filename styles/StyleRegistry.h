#pragma once

#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace nprgl {

namespace styles {
class Style;
enum class StyleRole;
} // namespace styles

// How a parameter's value is written: a number (flags are 0/1, on/off), one name of a list
// (stored as its index), a text such as a PNG file name, or a colour as hex rrggbb.
enum class ParamKind { Number, Choice, Text, Colour };

// One tunable parameter of a style, with its range.
struct ParamInfo {
    std::string name;
    std::string help;
    double defaultValue = 0.0;
    double minValue = 0.0;
    double maxValue = 0.0;
    ParamKind kind = ParamKind::Number;
    std::vector<std::string> choices; // Choice: the names, value = index
    std::string defaultText;          // Text, Colour
    bool isFlag = false;              // a Number that is on (1) or off (0)
    // A Number the style keeps at least `gap` below another of its numbers (the style's own
    // check moves a value that is not): the overlay's sliders keep the pair in order.
    std::string below;
    double gap = 0.0;

    static ParamInfo number(std::string name, std::string help, double def, double lo,
                            double hi);
    static ParamInfo flag(std::string name, std::string help, bool def);
    // This number, kept at least `gap` below the style's number `other`.
    ParamInfo keptBelow(std::string other, double gap) const;
    static ParamInfo choice(std::string name, std::string help, std::vector<std::string> names,
                            int def);
    static ParamInfo text(std::string name, std::string help, std::string def = {});
    // "rrggbb" or "#rrggbb"; empty means "derived" where the style says so.
    static ParamInfo colour(std::string name, std::string help, std::string def = {});
    // "rrggbb" or "#rrggbb" (hex: the configuration separates its items with commas) into
    // a colour; false when empty or malformed.
    static bool parseColour(const std::string& text, glm::vec3& out);
    // The default as it is written in a preset ("0.5", "dots", "on", a file name).
    std::string defaultString() const;
    // The range as `nprgl styles` prints it.
    std::string rangeString() const;
};

struct StyleInfo {
    std::string name;
    std::string summary;
    std::vector<ParamInfo> params;
    styles::StyleRole role{};
    // A background style the style draws on: added to a chain that names no background.
    std::string background;
    // The style draws the colours GL's own lighting and flat shading give each vertex (the
    // tracker computes them: StateTracker::setProgramLighting), not the material's colour.
    bool programLighting = false;
    // The style draws dark marks that need a light page (graphite): paper.tone=auto keeps
    // the page light for a chain with it.
    bool lightPage = false;
    std::unique_ptr<styles::Style> (*create)() = nullptr; // null for "none"

    const ParamInfo* findParam(std::string_view param) const;
};

// Every style nprgl knows, registered once at start-up. A chain such as "toon+edges" names
// several of them, applied left to right.
class StyleRegistry {
public:
    static const StyleRegistry& instance();

    const std::vector<StyleInfo>& styles() const { return mStyles; }
    const StyleInfo* find(std::string_view name) const;
    // The parameter a "style.param" key names, or null.
    const ParamInfo* findParam(std::string_view key) const;
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
