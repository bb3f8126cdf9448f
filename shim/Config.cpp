#include "shim/Config.h"

#include "common/Log.h"
#include "common/ScreenshotSpec.h"

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
};

ProcessConfig& processConfig()
{
    static ProcessConfig* p = new ProcessConfig; // lives past exit: contexts may outlive statics
    return *p;
}

} // namespace

Config Config::fromEnvironment()
{
    Config s;
    s.programName = program_invocation_short_name;
    std::string style = envOr("NPRGL_STYLE", "");
    std::string config = envOr("NPRGL_CONFIG", "");
    std::string error;
    if (!StyleSettings::parse(style, config, s.style, error)) {
        NPRGL_ERROR("%s; using style none", error.c_str());
        StyleSettings::parse("none", "", s.style, error);
    }
    std::string shot = envOr("NPRGL_SCREENSHOT", "");
    if (!shot.empty()) parseScreenshot(shot, s);
    NPRGL_INFO("%s: style %s%s%s%s%s", s.programName.c_str(), s.style.chainName().c_str(),
               config.empty() ? "" : ", config ", config.c_str(),
               s.screenshots ? ", screenshots to " : "",
               s.screenshots ? s.screenshotDir.c_str() : "");
    return s;
}

const Config& Config::process()
{
    ProcessConfig& p = processConfig();
    std::lock_guard lock(p.mutex);
    if (!p.config) p.config = std::make_unique<Config>(fromEnvironment());
    return *p.config;
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
