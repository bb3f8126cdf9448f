#include "shim/Config.h"

#include "common/Log.h"
#include "common/ProcessName.h"
#include "common/ScreenshotSpec.h"
#include "shim/ConfigFile.h"
#include "shim/ConfigWatcher.h"
#include "styles/Presets.h"

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <mutex>

namespace nprgl {

namespace {

std::string envOr(const char* name, const char* fallback)
{
    const char* v = std::getenv(name);
    return v ? v : fallback;
}

void parseScreenshot(const std::string& text, Config& s)
{
    ScreenshotSpec spec;
    std::string error;
    if (!ScreenshotSpec::parse(text, spec, error)) {
        NPRGL_ERROR("NPRGL_SCREENSHOT: %s; no screenshots", error.c_str());
        return;
    }
    std::error_code ec;
    std::filesystem::create_directories(spec.dir, ec);
    if (ec) {
        NPRGL_ERROR("NPRGL_SCREENSHOT: cannot create directory %s: %s; no screenshots",
                    spec.dir.c_str(), ec.message().c_str());
        return;
    }
    s.screenshotFrames = std::move(spec.frames);
    s.screenshotDir = std::move(spec.dir);
    s.screenshots = true;
}

struct ProcessConfig {
    std::mutex mutex;
    std::unique_ptr<Config> config; // set once, never replaced: references stay valid
    std::shared_ptr<const Config> current;
    bool fromEnvironment = false;
};

// The default keys: right Shift with a function key, as MangoHud's Shift_R+F12, on keys no
// common program or desktop binds.
const std::map<std::string, std::string>& defaultKeys()
{
    static const std::map<std::string, std::string> keys = {
        {"toggle", "Shift_R+F9"}, {"cycle", "Shift_R+F10"}, {"screenshot", "Shift_R+F11"},
        {"overlay", "Shift_R+F8"}, {"reload", "Shift_R+F7"}, {"video", "Shift_R+F6"}};
    return keys;
}

std::string joinConfig(const std::string& a, const std::string& b)
{
    if (a.empty()) return b;
    return b.empty() ? a : a + "," + b;
}

ProcessConfig& processConfig()
{
    static ProcessConfig* p = new ProcessConfig; // lives past exit: contexts may outlive statics
    return *p;
}

} // namespace

std::vector<std::string> Config::filePaths(const std::string& program)
{
    if (const char* file = std::getenv("NPRGL_CONFIG_FILE"); file && *file) return {file};
    std::string dir = envOr("XDG_CONFIG_HOME", "");
    if (dir.empty()) {
        const char* home = std::getenv("HOME");
        if (!home || !*home) return {};
        dir = std::string(home) + "/.config";
    }
    dir += "/nprgl/";
    return {dir + "nprgl.conf", dir + program + ".conf"};
}

Config Config::fromEnvironment(const Config* previous)
{
    const LogLevel said = previous ? LogLevel::Debug : LogLevel::Info;
    Config s;
    s.programName = processName();
    s.keys = defaultKeys();
    // Lowest precedence first: the global file, the program's file.
    std::string chain, config, logLevel, missing, refused;
    for (const std::string& path : filePaths(s.programName)) {
        s.tried.push_back(path);
        ConfigFile file = ConfigFile::read(path);
        if (!file.refused.empty()) {
            // Not waited on nor read (TextFile); one swapped in at a reload keeps its last look.
            const ConfigFile* before = nullptr;
            if (previous) {
                const auto it = previous->read.find(path);
                if (it != previous->read.end()) before = &it->second;
            }
            NPRGL_ERROR("%s: %s; %s", path.c_str(), file.refused.c_str(),
                        before ? "ignored, its previous lines stay" : "ignored");
            refused += (refused.empty() ? "" : ", ") + path;
            if (!before) continue;
            file = *before;
            file.errors.clear(); // said when it was read
            file.badLines = 0;
        }
        if (!file.found) {
            missing += (missing.empty() ? "" : ", ") + path;
            continue;
        }
        s.files.push_back(path);
        for (const std::string& e : file.errors) NPRGL_ERROR("%s; line skipped", e.c_str());
        if (file.badLines > file.errors.size()) {
            NPRGL_ERROR("%s: %zu more bad lines skipped", path.c_str(),
                        file.badLines - file.errors.size());
        }
        if (!file.chain.empty()) chain = file.chain;
        config = joinConfig(config, file.config);
        if (!file.screenshotDir.empty()) s.hotkeyScreenshotDir = file.screenshotDir;
        if (!file.logLevel.empty()) logLevel = file.logLevel;
        for (const auto& [action, key] : file.keys) s.keys[action] = key;
        for (const auto& [action, line] : file.keyLines)
            s.keyLines[action] = line;
        if (!file.cycle.empty()) s.cycle = file.cycle;
        if (!file.overlay.empty()) s.overlayOpen = file.overlay == "open";
        s.rules.textures.insert(s.rules.textures.end(), file.rules.textures.begin(),
                                file.rules.textures.end());
        s.rules.states |= file.rules.states;
        s.read.emplace(path, std::move(file));
    }
    if (!s.tried.empty()) {
        std::string read;
        for (const std::string& f : s.files) read += (read.empty() ? "" : ", ") + f;
        std::string others;
        if (!missing.empty()) others += "not found: " + missing;
        if (!refused.empty()) others += (others.empty() ? "" : "; ") + ("refused: " + refused);
        NPRGL_LOG(said, "configuration files: %s%s%s%s",
                  read.empty() ? "none read" : read.c_str(), others.empty() ? "" : " (",
                  others.c_str(), others.empty() ? "" : ")");
    }
    s.rules.normalise();
    if (!s.rules.textures.empty()) {
        NPRGL_LOG(said, "rules: %zu texture(s) left as the program draws them",
                  s.rules.textures.size());
    }
    if (s.rules.states) {
        NPRGL_LOG(said, "rules: draws %s left as the program draws them",
                  LeaveRules::stateNames(s.rules.states, " or ").c_str());
    }
    // The environment (and so the command line) over the files.
    std::string error;
    if (const std::string preset = envOr("NPRGL_PRESET", ""); !preset.empty()) {
        std::string presetChain, presetConfig;
        if (!Presets::load(preset, presetChain, presetConfig, error)) {
            NPRGL_ERROR("NPRGL_PRESET: %s; preset ignored", error.c_str());
        } else {
            if (!presetChain.empty()) chain = presetChain;
            config = joinConfig(config, presetConfig);
        }
    }
    if (const std::string style = envOr("NPRGL_STYLE", ""); !style.empty()) chain = style;
    config = joinConfig(config, envOr("NPRGL_CONFIG", ""));
    if (!logLevel.empty() && !std::getenv("NPRGL_LOG_LEVEL")) {
        LogLevel level;
        if (parseLogLevel(logLevel.c_str(), level)) setLogLevel(level);
    }
    if (!StyleSettings::parse(chain, config, s.style, error)) {
        NPRGL_ERROR("%s; using style none", error.c_str());
        StyleSettings::parse("none", "", s.style, error);
    }
    if (const std::string overlay = envOr("NPRGL_OVERLAY", ""); !overlay.empty()) {
        if (overlay == "open" || overlay == "closed") {
            s.overlayOpen = overlay == "open";
        } else {
            NPRGL_ERROR("NPRGL_OVERLAY: '%s' is not open or closed; ignored", overlay.c_str());
        }
    }
    std::string shot = envOr("NPRGL_SCREENSHOT", "");
    if (!shot.empty()) parseScreenshot(shot, s);
    NPRGL_LOG(said, "%s: style %s%s%s%s%s", s.programName.c_str(), s.style.chainName().c_str(),
               config.empty() ? "" : ", config ", config.c_str(),
               s.screenshots ? ", screenshots to " : "",
               s.screenshots ? s.screenshotDir.c_str() : "");
    return s;
}

const Config& Config::process()
{
    ProcessConfig& p = processConfig();
    std::lock_guard lock(p.mutex);
    if (!p.config) {
        p.config = std::make_unique<Config>(fromEnvironment());
        p.fromEnvironment = true;
        ConfigWatcher::instance().watch(p.config->tried);
    }
    if (!p.current) p.current = std::make_shared<const Config>(*p.config);
    return *p.config;
}

std::shared_ptr<const Config> Config::current()
{
    process();
    ProcessConfig& p = processConfig();
    std::lock_guard lock(p.mutex);
    return p.current;
}

void Config::reload()
{
    process();
    ProcessConfig& p = processConfig();
    std::shared_ptr<const Config> previous;
    {
        std::lock_guard lock(p.mutex);
        if (!p.fromEnvironment) return;
        previous = p.current;
    }
    // Read outside the lock: the files may be slow, other contexts keep the current one.
    auto next = std::make_shared<Config>(fromEnvironment(previous.get()));
    std::lock_guard lock(p.mutex);
    next->generation = p.current->generation + 1;
    p.current = std::move(next);
}

bool Config::use(Config config)
{
    ProcessConfig& p = processConfig();
    std::lock_guard lock(p.mutex);
    if (p.config) return false;
    p.config = std::make_unique<Config>(std::move(config));
    return true;
}

} // namespace nprgl
