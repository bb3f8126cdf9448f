#include "styles/Presets.h"

#include "common/KeyValue.h"
#include "common/TextFile.h"
#include "styles/StyleRegistry.h"
#include "styles/StyleSettings.h"

#include <cerrno>
#include <cstring>
#include <sstream>

namespace nprgl {

namespace {

std::string trim(const std::string& s) { return std::string(trimBlanks(s)); }

} // namespace

const std::vector<Preset>& Presets::shipped()
{
    static const std::vector<Preset> presets = {
        {"cartoon", "cel shading, clean ink outlines, paper (the default look)",
         "style=toon+paper+edges\n"},
        {"comic", "two flat tones, bold outlines and ink between the bands",
         "style=toon+paper+edges\n"
         "toon.tones=2\n"
         "toon.diffuse_threshold=0.15\n"
         "toon.band_lines=on\n"
         "edges.silhouette_width=3\n"},
        {"newspaper", "halftone dots in print black with ink outlines",
         "style=halftone+paper+edges\n"
         "halftone.pattern=dots\n"},
        {"engraving", "cross-hatched pen and ink",
         "style=textured+paper+edges\n"
         "textured.shadow_texture=crosshatching\n"
         "textured.tint=off\n"},
        {"sketch", "pencil strokes over hatching",
         "style=textured+paper+strokes\n"
         "textured.shadow_texture=hatching\n"},
        {"pencil", "a graphite drawing: hatching by the light, overdrawn pencil outlines",
         "style=pencil+paper\n"
         "paper.grain=0.18\n"},
        {"motion", "the cartoon look with speed lines behind moving objects",
         "style=toon+paper+edges+motion\n"},
        {"technical", "technical illustration: cool-to-warm tones, a highlight, ink outlines",
         "style=gooch+edges\n"
         "gooch.highlight=40\n"},
        {"blueprint", "white construction lines, a grid and dimensions on blue paper",
         "style=toon+paper+blueprint\n"
         "toon.tones=2\n"
         "toon.shadow_color=1d4f91\n"
         "toon.diffuse_color=1d4f91\n"
         "toon.detail=off\n"
         "paper.color=1d4f91\n"
         "paper.grain=0.05\n"},
    };
    return presets;
}

bool Presets::parse(const std::string& text, const std::string& origin, std::string& chain,
                    std::string& config, std::string& error)
{
    const StyleRegistry& registry = StyleRegistry::instance();
    std::istringstream in(text);
    std::string line, outChain, outConfig;
    for (int number = 1; std::getline(in, line); ++number) {
        if (size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
        line = trim(line);
        if (line.empty()) continue;
        const std::string where = origin + ":" + std::to_string(number) + ": ";
        const size_t eq = line.find('=');
        if (eq == std::string::npos) {
            error = where + "expected key=value, got '" + line + "'";
            return false;
        }
        const std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
        if (key == "style") {
            std::vector<const StyleInfo*> styles;
            if (!registry.parseChain(value, styles, error)) {
                error = where + error;
                return false;
            }
            outChain = value;
            continue;
        }
        const ParamInfo* param = nullptr;
        double ignored = 0.0;
        if (!StyleSettings::check(key, value, param, ignored, error)) {
            error = where + error;
            return false;
        }
        if (value.find(',') != std::string::npos) {
            error = where + "a value may not contain ',': '" + value + "'";
            return false;
        }
        outConfig += (outConfig.empty() ? "" : ",") + key + "=" + value;
    }
    chain = outChain;
    config = outConfig;
    return true;
}

bool Presets::combine(const std::string& preset, std::string& chain, std::string& config,
                      std::string& error)
{
    if (preset.empty()) return true;
    std::string presetChain, presetConfig;
    if (!load(preset, presetChain, presetConfig, error)) return false;
    if (chain.empty()) chain = presetChain;
    if (!presetConfig.empty()) config = presetConfig + (config.empty() ? "" : "," + config);
    return true;
}

bool Presets::load(const std::string& nameOrFile, std::string& chain, std::string& config,
                   std::string& error)
{
    if (nameOrFile.find_first_of("/.") == std::string::npos) {
        for (const Preset& p : shipped()) {
            if (nameOrFile == p.name) return parse(p.text, p.name, chain, config, error);
        }
        std::string known;
        for (const Preset& p : shipped())
            known += (known.empty() ? "" : ", ") + std::string(p.name);
        error = "unknown preset '" + nameOrFile + "' (shipped: " + known +
                "; or give a file name)";
        return false;
    }
    std::string text, why;
    switch (TextFile::read(nameOrFile, "preset file", text, why)) {
    case TextFile::Result::Missing:
        error = "cannot read preset file " + nameOrFile + ": " + std::strerror(ENOENT);
        return false;
    case TextFile::Result::Refused:
        error = "preset file " + nameOrFile + ": " + why;
        return false;
    case TextFile::Result::Read: break;
    }
    return parse(text, nameOrFile, chain, config, error);
}

} // namespace nprgl
