#include "shim/Settings.h"

#include "common/KeyValue.h"
#include "common/Log.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace nprgl {

namespace {

std::string envOr(const char* name, const char* fallback)
{
    const char* v = std::getenv(name);
    return v ? v : fallback;
}

void parseScreenshot(const std::string& spec, Settings& s)
{
    KeyValueList pairs;
    std::string error;
    if (!parseKeyValues(spec, ';', pairs, error)) {
        NPRGL_ERROR("NPRGL_SCREENSHOT: %s; no screenshots", error.c_str());
        return;
    }
    s.screenshotDir = ".";
    bool haveFrames = false;
    for (const auto& [key, value] : pairs) {
        if (key == "frames") {
            if (!FrameSet::parse(value, s.screenshotFrames, error)) {
                NPRGL_ERROR("NPRGL_SCREENSHOT: %s; no screenshots", error.c_str());
                return;
            }
            haveFrames = true;
        } else if (key == "dir") {
            s.screenshotDir = value.empty() ? "." : value;
        } else {
            NPRGL_ERROR("NPRGL_SCREENSHOT: unknown key '%s' (use frames=LIST;dir=DIR); no "
                        "screenshots",
                        key.c_str());
            return;
        }
    }
    if (!haveFrames) {
        NPRGL_ERROR("NPRGL_SCREENSHOT needs frames=LIST (e.g. frames=1,10,100;dir=out); no "
                    "screenshots");
        return;
    }
    std::error_code ec;
    std::filesystem::create_directories(s.screenshotDir, ec);
    if (ec) {
        NPRGL_ERROR("NPRGL_SCREENSHOT: cannot create directory %s: %s; no screenshots",
                    s.screenshotDir.c_str(), ec.message().c_str());
        return;
    }
    s.screenshots = true;
}

Settings load()
{
    Settings s;
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

} // namespace

const Settings& Settings::get()
{
    static const Settings settings = load();
    return settings;
}

} // namespace nprgl
