#pragma once

// ConfigFile: what one configuration file (nprgl.conf, <program>.conf) says, line by line.

#include "frame/LeaveRules.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace nprgl {

// The `key=value` lines of a configuration file, `#` comments, the preset syntax plus the keys
// of the running program's controls:
//   style=CHAIN  preset=NAME|FILE  STYLE.PARAM=VALUE
//   screenshot_dir=DIR  log_level=error|warn|info|debug
//   toggle_key= cycle_key= screenshot_key= overlay_key= reload_key=  (e.g. Shift_R+F9)
//   cycle=CHAIN|preset:NAME, ...   (what cycle_key steps through)
//   overlay=open|closed            (the overlay at start-up)
//   leave_texture=HASH             (a rule: draws with this texture stay the program's; one
//                                   line per texture, as the overlay's pick gives them)
//   leave_state=STATE              (a rule: draws in this state stay the program's: translucent
//                                   (blended by alpha), cutout (alpha test), decal (polygon
//                                   offset), backdrop (3D without the depth test); one a line)
// A bad line is reported as file:line and skipped; the other lines apply.
struct ConfigFile {
    // At most this many bad lines are kept in `errors`; `badLines` counts them all.
    static constexpr size_t kShownErrors = 5;

    std::string path;
    bool found = false;        // the file exists and could be read
    std::string refused;       // why a file that exists was not read (empty: read, or missing)
    std::string chain;         // style=, else the preset's chain (empty: none given)
    std::string config;        // "style.param=value,...": the preset's, then the file's own
    std::string screenshotDir;
    std::string logLevel;
    std::map<std::string, std::string> keys; // "toggle", "cycle", ... -> key combination
    std::map<std::string, std::string> keyLines; // the same actions -> "file:line" of the line
    std::vector<std::string> cycle;
    std::string overlay; // overlay=open|closed: the overlay's state at start-up (empty: closed)
    LeaveRules rules;    // leave_texture=HASH (16 hex digits, in order) and leave_state= lines
    std::vector<std::string> errors; // "file:line: message": the first kShownErrors bad lines
    size_t badLines = 0;             // lines skipped, all of them

    // Reads the file at `path`; a file that does not exist is not an error (found = false).
    // One that is not a regular file, over TextFile::kLimit, unreadable or binary is not read
    // (found = false, `refused` says why): the read never blocks and never runs long.
    static ConfigFile read(const std::string& path);
    // Parses text; `origin` names it in messages.
    static ConfigFile parse(const std::string& text, const std::string& origin);

    // Replaces the look (style=, preset=, every STYLE.PARAM, leave_texture and leave_state
    // line) in the file at `path` with `chain`, `config` ("key=value,...") and the rules,
    // keeping its other lines; creates the file (and its folder) when missing. A path that is
    // there but refused by read() is left alone.
    static bool writeLook(const std::string& path, const std::string& chain,
                          const std::string& config, const LeaveRules& rules, std::string& error);
    // A texture rule's hash as the files write it: 16 hex digits.
    static std::string hashText(uint64_t hash);

    // The actions a key may be bound to, in the order the overlay lists them.
    static const std::vector<std::string>& actions();
};

} // namespace nprgl
