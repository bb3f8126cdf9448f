#include "shim/ConfigFile.h"

#include "common/KeyValue.h"
#include "common/Log.h"
#include "common/TextFile.h"
#include "styles/Presets.h"
#include "styles/StyleRegistry.h"
#include "styles/StyleSettings.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace nprgl {

namespace {

// A cycle entry is a chain or "preset:NAME" (a shipped preset or a preset file).
bool checkCycleEntry(const std::string& entry, std::string& error)
{
    if (entry.rfind("preset:", 0) == 0) {
        std::string chain, config;
        return Presets::load(entry.substr(7), chain, config, error);
    }
    std::vector<const StyleInfo*> styles;
    return StyleRegistry::instance().parseChain(entry, styles, error);
}

} // namespace

const std::vector<std::string>& ConfigFile::actions()
{
    static const std::vector<std::string> names = {"toggle", "cycle", "screenshot", "overlay",
                                                   "reload", "video"};
    return names;
}

ConfigFile ConfigFile::read(const std::string& path)
{
    std::string text, why;
    const TextFile::Result result = TextFile::read(path, "configuration file", text, why);
    ConfigFile file;
    if (result == TextFile::Result::Read) file = parse(text, path);
    file.path = path;
    file.found = result == TextFile::Result::Read;
    file.refused = why;
    return file;
}

ConfigFile ConfigFile::parse(const std::string& text, const std::string& origin)
{
    ConfigFile out;
    std::string presetConfig, ownConfig, presetChain;
    std::istringstream in(text);
    std::string raw;
    for (int number = 1; std::getline(in, raw); ++number) {
        if (size_t hash = raw.find('#'); hash != std::string::npos) raw.resize(hash);
        const std::string line(trimBlanks(raw));
        if (line.empty()) continue;
        const std::string where = origin + ":" + std::to_string(number) + ": ";
        auto skip = [&](const std::string& why) {
            if (++out.badLines <= kShownErrors) out.errors.push_back(where + why);
        };
        const size_t eq = line.find('=');
        if (eq == std::string::npos) {
            skip("expected key=value, got '" + line + "'");
            continue;
        }
        const std::string key(trimBlanks(std::string_view(line).substr(0, eq)));
        const std::string value(trimBlanks(std::string_view(line).substr(eq + 1)));
        std::string error;
        if (key == "style") {
            std::vector<const StyleInfo*> styles;
            if (!StyleRegistry::instance().parseChain(value, styles, error)) {
                skip(error);
            } else {
                out.chain = value;
            }
        } else if (key == "preset") {
            std::string chain, config;
            if (!Presets::load(value, chain, config, error)) {
                skip("preset: " + error);
            } else {
                presetChain = chain;
                presetConfig = config;
            }
        } else if (key == "overlay") {
            if (value != "open" && value != "closed") {
                skip("overlay: '" + value + "' is not open or closed");
            } else {
                out.overlay = value;
            }
        } else if (key == "leave_texture") {
            uint64_t hash = 0;
            auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), hash, 16);
            if (ec != std::errc() || end != value.data() + value.size() || hash == 0) {
                skip("leave_texture: '" + value + "' is not a texture hash (16 hex digits)");
            } else {
                out.rules.textures.push_back(hash);
            }
        } else if (key == "leave_state") {
            const uint32_t bit = LeaveRules::stateBit(value);
            if (!bit) {
                skip("leave_state: '" + value +
                     "' is not a state (use translucent, cutout, decal or backdrop)");
            } else {
                out.rules.states |= bit;
            }
        } else if (key == "screenshot_dir") {
            out.screenshotDir = value;
        } else if (key == "log_level") {
            LogLevel level;
            if (!parseLogLevel(value.c_str(), level)) {
                skip("unknown log level '" + value + "' (use error, warn, info or debug)");
            } else {
                out.logLevel = value;
            }
        } else if (key == "cycle") {
            std::vector<std::string> entries;
            std::string_view rest = value;
            bool ok = true;
            while (!rest.empty() && ok) {
                const size_t comma = rest.find(',');
                const std::string entry(trimBlanks(rest.substr(0, comma)));
                rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
                if (entry.empty()) continue;
                ok = checkCycleEntry(entry, error);
                if (ok) entries.push_back(entry);
            }
            if (!ok) {
                skip("cycle: " + error);
            } else {
                out.cycle = std::move(entries);
            }
        } else if (key.size() > 4 && key.compare(key.size() - 4, 4, "_key") == 0) {
            const std::string action = key.substr(0, key.size() - 4);
            bool known = false;
            for (const std::string& a : actions()) known = known || a == action;
            if (!known) {
                skip("unknown key binding '" + key + "'");
            } else if (value.empty()) {
                skip(key + " is empty (to unbind a key, write " + key + "=none)");
            } else {
                out.keys[action] = value;
                out.keyLines[action] = origin + ":" + std::to_string(number);
            }
        } else {
            const ParamInfo* param = nullptr;
            double ignored = 0.0;
            if (!StyleSettings::check(key, value, param, ignored, error)) {
                skip(error);
            } else if (value.find(',') != std::string::npos) {
                skip("a value may not contain ',': '" + value + "'");
            } else {
                ownConfig += (ownConfig.empty() ? "" : ",") + key + "=" + value;
            }
        }
    }
    if (out.chain.empty()) out.chain = presetChain;
    out.config = presetConfig;
    if (!ownConfig.empty()) out.config += (out.config.empty() ? "" : ",") + ownConfig;
    return out;
}

std::string ConfigFile::hashText(uint64_t hash)
{
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

bool ConfigFile::writeLook(const std::string& path, const std::string& chain,
                           const std::string& config, const LeaveRules& rules, std::string& error)
{
    // A look the next start would skip is not written.
    if (StyleSettings settings; !StyleSettings::parse(chain, config, settings, error)) {
        error = "not saved: " + error;
        return false;
    }
    // Keep every line that is not the look (comments, keys, screenshot folder...).
    std::string kept, old, why;
    if (TextFile::read(path, "configuration file", old, why) == TextFile::Result::Refused) {
        error = "not saved: " + path + ": " + why;
        return false;
    }
    {
        std::istringstream in(old);
        std::string raw;
        while (std::getline(in, raw)) {
            const std::string line(trimBlanks(raw));
            const size_t eq = line.find('=');
            const std::string_view name =
                eq == std::string::npos ? std::string_view() : std::string_view(line).substr(0, eq);
            const std::string key(trimBlanks(name));
            const bool look = key == "style" || key == "preset" || key == "leave_texture" ||
                              key == "leave_state" ||
                              StyleRegistry::instance().findParam(key) != nullptr;
            if (!look) kept += raw + "\n";
        }
    }
    std::string text = kept + "style=" + chain + "\n";
    KeyValueList pairs;
    if (!parseKeyValues(config, ',', pairs, error)) return false;
    for (const auto& [key, value] : pairs) text += key + "=" + value + "\n";
    for (uint64_t hash : rules.textures)
        text += "leave_texture=" + hashText(hash) + "\n";
    for (uint32_t bit = 1; bit != 0 && bit <= rules.states; bit <<= 1) {
        if (rules.states & bit) {
            text += std::string("leave_state=") + LeaveRules::stateName(bit) + "\n";
        }
    }

    const std::filesystem::path folder = std::filesystem::path(path).parent_path();
    std::error_code ec;
    if (!folder.empty()) std::filesystem::create_directories(folder, ec);
    if (ec) {
        error = "cannot create " + folder.string() + ": " + ec.message();
        return false;
    }
    // Written beside and renamed over: a reader (this process's reload) never sees half a file.
    const std::string temporary = path + ".nprgl-new";
    // Not waiting on whatever may sit at the temporary name (a FIFO would hold the program).
    const int fd =
        ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NONBLOCK | O_CLOEXEC, 0644);
    if (fd < 0) {
        error = "cannot write " + temporary + ": " + std::strerror(errno);
        return false;
    }
    struct stat st {};
    const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    int err = 0;
    for (size_t written = 0; regular && written < text.size();) {
        const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            err = n < 0 ? errno : EIO;
            break;
        }
        written += size_t(n);
    }
    if (::close(fd) != 0 && !err) err = errno;
    if (!regular) {
        error = "cannot write " + temporary + ": not a regular file (" +
                TextFile::typeName(st.st_mode) + ")";
        return false;
    }
    if (err) {
        error = "cannot write " + temporary + ": " + std::strerror(err);
        std::remove(temporary.c_str()); // half written
        return false;
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        error = "cannot replace " + path + ": " + std::strerror(errno);
        std::remove(temporary.c_str());
        return false;
    }
    return true;
}

} // namespace nprgl
