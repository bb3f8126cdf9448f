#pragma once

// CompareCommand: `nprgl compare`: a capture replayed natively and in a style, measured.

#include <string>
#include <vector>

namespace nprgl::cli {

struct CompareOptions {
    std::string file;
    std::string style;
    std::string preset;
    std::vector<std::string> settings;
    std::string frames;
    std::string json;   // JSON per frame and per object (empty: none)
    std::string outDir; // diff pictures per frame (empty: none)
    unsigned context = 0;
};

// Replays the capture three times in child processes of this command (a replay's style is
// fixed for its process): style none (the program's own frames), the style, and the `ids`
// style (which object covers each pixel). Then per frame FrameFidelity; one line per frame
// and a summary on stdout. 1 when the capture cannot be replayed, 2 on bad options, else 0.
int compareCommand(const CompareOptions& options);

} // namespace nprgl::cli
