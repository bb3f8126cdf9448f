#include "Options.h"

#include <charconv>
#include <cstdio>
#include <string_view>

namespace demo {

namespace {

bool parseInt(std::string_view text, int minValue, int maxValue, int& value)
{
    if (text.empty()) {
        return false;
    }
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && end == text.data() + text.size() && value >= minValue
           && value <= maxValue;
}

bool parseSize(std::string_view text, int& width, int& height)
{
    size_t x = text.find('x');
    if (x == std::string_view::npos) {
        return false;
    }
    // 16384 is the largest viewport llvmpipe supports.
    return parseInt(text.substr(0, x), 1, 16384, width)
           && parseInt(text.substr(x + 1), 1, 16384, height);
}

void printHelp(const Options& options, const std::vector<ExtraOption>& extraOptions)
{
    std::printf("usage: %s [options]\n"
                "  --frames N         frames to render (default: until closed; offscreen 10)\n"
                "  --size WxH         surface size (default 512x512)\n"
                "  --offscreen        render with OSMesa into memory instead of a GLX window\n"
                "  --save-dir DIR     write DIR/%s_<frame>.png (every frame unless --save-frames)\n"
                "  --save-frames LIST frames to save, 1-based, e.g. 1,5,10 or 1-3,7\n"
                "  --report           print 'frames=N seconds=S fps=F' at exit\n"
                "  --exit-undestroyed end by exit() without destroying the GL context\n"
                "  --flush-frames     end each frame by glFlush, never swapping\n"
                "  --grow-at N        window: resize it to twice --size before frame N\n"
                "  --press N KEYS     window: hold KEYS (e.g. Shift_R+F11) down during frame N\n"
                "  --help             show this help\n",
                options.appName.c_str(), options.shortName.c_str());
    for (const ExtraOption& extra : extraOptions) {
        std::string left = "--" + extra.name;
        if (extra.kind == ExtraOption::Kind::Int) {
            left += " N";
        } else if (extra.kind == ExtraOption::Kind::Text) {
            left += " VALUE";
        }
        std::printf("  %-18s %s\n", left.c_str(), extra.help.c_str());
    }
}

int usageError(const Options& options, const std::string& message)
{
    std::fprintf(stderr, "%s: %s (see --help)\n", options.appName.c_str(), message.c_str());
    return 2;
}

} // namespace

bool Options::shouldSave(int frame) const
{
    if (saveDir.empty()) {
        return false;
    }
    return !saveFramesGiven || saveFrames.contains(frame);
}

int Options::intValue(const std::string& name, int fallback) const
{
    auto it = extras.find(name);
    int value = fallback;
    if (it != extras.end()) {
        parseInt(it->second, INT_MIN, INT_MAX, value);
    }
    return value;
}

std::string Options::textValue(const std::string& name, const std::string& fallback) const
{
    auto it = extras.find(name);
    return it == extras.end() ? fallback : it->second;
}

int parseOptions(int argc, char** argv, const std::string& shortName,
                 const std::vector<ExtraOption>& extraOptions, Options& options)
{
    options.shortName = shortName;
    options.appName = "demo_" + shortName;
    bool framesGiven = false;

    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        std::string value;
        bool hasInlineValue = false;
        if (size_t eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
            value = arg.substr(eq + 1);
            arg.resize(eq);
            hasInlineValue = true;
        }
        // Fetches the option's value from "--opt=value" or the next argument.
        auto takeValue = [&]() -> bool {
            if (hasInlineValue) {
                return true;
            }
            if (i + 1 >= argc) {
                return false;
            }
            value = argv[++i];
            return true;
        };
        auto isFlag = [&](const char* name) { return arg == name && !hasInlineValue; };

        if (hasInlineValue && (arg == "--help" || arg == "--offscreen" || arg == "--report" ||
                               arg == "--exit-undestroyed" || arg == "--flush-frames")) {
            return usageError(options, arg + " takes no value");
        }
        if (isFlag("--help") || isFlag("-h")) {
            printHelp(options, extraOptions);
            return 0;
        } else if (isFlag("--offscreen")) {
            options.offscreen = true;
        } else if (isFlag("--report")) {
            options.report = true;
        } else if (isFlag("--flush-frames")) {
            options.flushFrames = true;
        } else if (isFlag("--exit-undestroyed")) {
            options.exitUndestroyed = true;
        } else if (arg == "--frames") {
            if (!takeValue() || !parseInt(value, 0, INT_MAX, options.frames)) {
                return usageError(options, "--frames needs a non-negative integer");
            }
            framesGiven = true;
        } else if (arg == "--grow-at") {
            if (!takeValue() || !parseInt(value, 1, INT_MAX, options.growAt)) {
                return usageError(options, "--grow-at needs a frame number from 1");
            }
        } else if (arg == "--press") {
            if (!takeValue() || !parseInt(value, 1, INT_MAX, options.pressAt) || i + 1 >= argc) {
                return usageError(options, "--press needs a frame number from 1 and keys");
            }
            options.pressKeys = argv[++i];
        } else if (arg == "--size") {
            if (!takeValue() || !parseSize(value, options.width, options.height)) {
                return usageError(options, "--size needs WxH, e.g. 640x480");
            }
        } else if (arg == "--save-dir") {
            if (!takeValue() || value.empty()) {
                return usageError(options, "--save-dir needs a directory");
            }
            options.saveDir = value;
        } else if (arg == "--save-frames") {
            std::string error;
            if (!takeValue()) {
                return usageError(options, "--save-frames needs a list such as 1-3,7");
            }
            if (!options.saveFrames.parse(value, error)) {
                return usageError(options, "--save-frames: " + error);
            }
            options.saveFramesGiven = true;
        } else {
            const ExtraOption* extra = nullptr;
            for (const ExtraOption& candidate : extraOptions) {
                if (arg == "--" + candidate.name) {
                    extra = &candidate;
                }
            }
            if (extra == nullptr) {
                return usageError(options, "unknown option '" + arg + "'");
            }
            if (extra->kind == ExtraOption::Kind::Flag) {
                if (hasInlineValue) {
                    return usageError(options, arg + " takes no value");
                }
                options.extras[extra->name] = "";
                continue;
            }
            if (!takeValue()) {
                return usageError(options, arg + " needs a value");
            }
            int number = 0;
            if (extra->kind == ExtraOption::Kind::Int
                && !parseInt(value, extra->minValue, extra->maxValue, number)) {
                std::string range =
                    std::to_string(extra->minValue) + ".." + std::to_string(extra->maxValue);
                return usageError(options, arg + " needs an integer in " + range);
            }
            options.extras[extra->name] = value;
        }
    }

    if (options.saveFramesGiven && options.saveDir.empty()) {
        return usageError(options, "--save-frames needs --save-dir");
    }
    if (!framesGiven && options.offscreen) {
        options.frames = 10;
    }
    return -1;
}

} // namespace demo
