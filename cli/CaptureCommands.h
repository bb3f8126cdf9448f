#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace nprgl::cli {

struct ReplayCommandOptions {
    std::string file;
    std::string style;
    std::string preset;
    std::vector<std::string> settings;
    std::string frames;
    std::string size;
    std::string outDir;
    unsigned context = 0;
    bool stats = false;
    bool overlays = false; // with stats: each 2D draw's contrast
    std::string rules; // a configuration file whose leave_texture and leave_state rules apply
    std::string video; // a video of the frames (.mp4, .mkv, .mov: H.264; .webm: VP9)
    int fps = 30;
};

int replayCommand(const ReplayCommandOptions& options);
int dumpCommand(const std::string& file, const std::string& frames, const std::string& grep);
int exportCommand(const std::string& file, uint64_t frame, const std::string& output,
                  const std::string& space, unsigned context);

} // namespace nprgl::cli
