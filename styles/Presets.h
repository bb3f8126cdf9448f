#pragma once

#include <string>
#include <vector>

namespace nprgl {

// A named look: a style chain and parameter values, written as `key=value` lines with `#`
// comments. The key `style` names the chain; every other key is `style.param`.
struct Preset {
    const char* name;
    const char* summary;
    const char* text;
};

class Presets {
public:
    // The presets nprgl ships, in the order `nprgl styles` lists them.
    static const std::vector<Preset>& shipped();

    // Reads a preset by name or from a file (a name with '/' or '.' is a file). On success
    // `chain` is its style chain (empty when it names none) and `config` its parameters as
    // "key=value,key=value"; on failure a message names the file and line.
    static bool load(const std::string& nameOrFile, std::string& chain, std::string& config,
                     std::string& error);
    // Applies a preset (if named) under what was given explicitly: the explicit chain wins,
    // explicit parameters come after the preset's (the later value wins).
    static bool combine(const std::string& preset, std::string& chain, std::string& config,
                        std::string& error);
    // Parses preset text; `origin` names it in messages.
    static bool parse(const std::string& text, const std::string& origin, std::string& chain,
                      std::string& config, std::string& error);
};

} // namespace nprgl
