#pragma once

#include "styles/StyleRegistry.h"

#include <map>
#include <string>
#include <vector>

namespace nprgl {

// A checked style chain plus its parameter values: what NPRGL_STYLE and NPRGL_CONFIG say.
class StyleSettings {
public:
    // Checks the chain and every "style.param=value" against the registry: unknown names,
    // values that are not numbers and values out of range are refused with a message that
    // names the parameter.
    static bool parse(const std::string& chain, const std::string& config,
                      StyleSettings& out, std::string& error);

    // Checks one "style.param" = text: the parameter exists and the text is a valid value
    // of it (a number in range, one of its choices, a colour). `value` is the number or
    // choice index (unset for text and colours).
    static bool check(const std::string& key, const std::string& text, const ParamInfo*& param,
                      double& value, std::string& error);

    const std::vector<const StyleInfo*>& chain() const { return mChain; }
    std::string chainName() const;
    // The value of style.param: the configured one, else the registry default.
    double value(const std::string& style, const std::string& param) const;
    // A text parameter (a file name): the configured one, else the default.
    std::string text(const std::string& style, const std::string& param) const;
    // The configured values as parse() reads them ("toon.tones=3,paper.texture=a.png"):
    // numbers in shortest round-trip form, choices by name. Defaults are not listed.
    std::string configText() const;

private:
    std::vector<const StyleInfo*> mChain;
    std::map<std::string, double> mValues;
    std::map<std::string, std::string> mTexts;
};

} // namespace nprgl
