#pragma once

#include "FrameList.h"

#include <climits>
#include <map>
#include <string>
#include <vector>

namespace demo {

// An app-specific option such as --detail K or --vbo.
struct ExtraOption {
    enum class Kind { Flag, Int, Text };
    std::string name; // without the leading dashes
    Kind kind = Kind::Flag;
    std::string help;
    int minValue = 1;
    int maxValue = INT_MAX;
};

struct Options {
    std::string appName; // executable name, e.g. "demo_immediate"
    std::string shortName; // used for PNG names, e.g. "immediate"
    int frames = 0; // 0 = unlimited
    int width = 512;
    int height = 512;
    bool offscreen = false;
    std::string saveDir;
    FrameList saveFrames;
    bool saveFramesGiven = false;
    bool report = false;
    bool flushFrames = false; // end frames by glFlush, never swapping (a single-buffered program)
    bool exitUndestroyed = false; // end by exit() with the GL context still alive (most programs)
    int growAt = 0; // GLX: the window doubles its size before this frame (0: never)
    // GLX: keys (X keysym names joined by '+') held down with XTEST during this frame, as a
    // user presses a hotkey (0: never).
    int pressAt = 0;
    std::string pressKeys;
    std::map<std::string, std::string> extras; // flags are stored with an empty value

    bool shouldSave(int frame) const;
    bool has(const std::string& name) const { return extras.count(name) != 0; }
    int intValue(const std::string& name, int fallback) const;
    std::string textValue(const std::string& name, const std::string& fallback) const;
};

// Returns -1 when the app should run, otherwise the exit code (0 after --help, 2 on bad usage).
int parseOptions(int argc, char** argv, const std::string& shortName,
                 const std::vector<ExtraOption>& extraOptions, Options& options);

} // namespace demo
