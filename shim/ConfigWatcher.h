#pragma once

// ConfigWatcher: notices when a configuration file is written, created, replaced or removed.

#include <mutex>
#include <string>
#include <vector>

namespace nprgl {

// inotify on the folders of the configuration files (editors replace a file by renaming a new
// one over it, which a watch on the file itself would lose), polled without blocking at frame
// ends: no thread in the host program, one read per frame.
class ConfigWatcher {
public:
    static ConfigWatcher& instance();

    // Watches `paths` from now on (again: the watches follow the list). Quietly nothing when
    // inotify is not available (reloading is then by the reload key only).
    void watch(const std::vector<std::string>& paths);
    // Whether one of the files changed since the last call.
    bool changed();

private:
    ConfigWatcher() = default;
    void close();

    std::mutex mMutex;
    int mFd = -1;
    std::vector<int> mWatches;
    std::vector<std::string> mNames; // the files' names, as the events give them
};

} // namespace nprgl
