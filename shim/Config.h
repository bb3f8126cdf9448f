#pragma once

// Config: what the contexts of this process are asked to do (style chain and values,
// screenshots, hotkeys), from the command line, the environment and the configuration files.

#include "common/FrameSet.h"
#include "frame/LeaveRules.h"
#include "shim/ConfigFile.h"
#include "styles/StyleSettings.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace nprgl {

struct Config {
    StyleSettings style;
    bool screenshots = false;
    FrameSet screenshotFrames;
    std::string screenshotDir;
    std::string programName;
    // Hotkeys' screenshots (styled and unstyled pairs) go here.
    std::string hotkeyScreenshotDir;
    std::map<std::string, std::string> keys; // action -> key combination ("none": unbound)
    std::map<std::string, std::string> keyLines; // action -> "file:line" it was set at
    std::vector<std::string> cycle;           // chains and "preset:NAME"s the cycle key steps
    LeaveRules rules;         // leave_texture and leave_state rules of the files read
    bool overlayOpen = false; // the overlay shows from the first frame (overlay=open, NPRGL_OVERLAY)
    std::vector<std::string> files;           // configuration files read, lowest first
    std::vector<std::string> tried;           // every path looked at (watched for changes)
    std::map<std::string, ConfigFile> read;   // what each file read said, by path
    uint64_t generation = 0;                  // 0 at start-up, +1 at every reload

    // Builds the configuration from, by precedence: NPRGL_STYLE / NPRGL_CONFIG (which the
    // command line sets), NPRGL_PRESET, the per-program file, the global file, the defaults.
    // The files are $XDG_CONFIG_HOME/nprgl/nprgl.conf (default ~/.config) and
    // <program>.conf beside it, or NPRGL_CONFIG_FILE alone. Bad values and lines are
    // reported (file:line) and skipped or replaced by safe ones; the program runs on.
    // A file that is there but refused (a FIFO, a device, a directory, too big, unreadable,
    // binary) counts as missing, or at a reload as what it said before (`previous`).
    // A reload says only what went wrong (the context says what changed).
    static Config fromEnvironment(const Config* previous = nullptr);
    // The paths of the configuration files for `program`, lowest precedence first.
    static std::vector<std::string> filePaths(const std::string& program);

    // The process's configuration at start-up: the one given to use() or, when nothing was,
    // the environment's, read (and reported) when the first context becomes current (a
    // program that never uses GL never reads it and never hears from us).
    static const Config& process();
    // The latest configuration (process() until a reload).
    static std::shared_ptr<const Config> current();
    // Reads the environment and the files again and makes the result current (with the
    // next generation). Only for a configuration that came from the environment.
    static void reload();
    // In-process callers (the replayer, tests) hand their own before any context exists;
    // false (and nothing changes) once process() has been read.
    static bool use(Config config);
};

} // namespace nprgl
