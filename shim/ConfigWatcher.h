#pragma once

// ConfigWatcher: notices when a configuration file is written, created, replaced or removed.

#include <mutex>
#include <string>
#include <vector>

namespace nprgl {

// inotify on the folders of the configuration files (editors replace a file by renaming a new
// one over it, which a watch on the file itself would lose), polled without blocking at frame
// ends: no thread in the host program, one read per frame. A folder that does not exist (yet,
// or any more) is waited for on its nearest existing ancestor, and watched once it appears.
class ConfigWatcher {
public:
    static ConfigWatcher& instance();

    // Watches `paths` from now on (again: the watches follow the list). Quietly nothing when
    // inotify is not available (reloading is then by the reload key only).
    void watch(const std::vector<std::string>& paths);
    // Whether one of the files changed since the last call (or may have: a folder of theirs
    // appeared, went or moved).
    bool changed();

private:
    // One inotify watch: on a folder of the files, or on the nearest existing ancestor of a
    // missing one, waiting for `child` (the next folder down) to appear.
    struct Watch {
        int wd = -1;
        std::string path;
        std::vector<std::string> children; // missing folders it waits for
        bool files = false;                // a folder of the files
    };

    ConfigWatcher() = default;
    void close();
    // Drops the watches and sets them again for the folders as they are now.
    void arm();
    // False when `path` went since the look (look again); another refusal is warned of.
    bool addWatch(const std::string& path, const std::string& child);

    std::mutex mMutex;
    int mFd = -1;
    std::vector<std::string> mDirs;  // the files' folders
    std::vector<std::string> mNames; // the files' names, as the events give them
    std::vector<Watch> mWatches;
};

} // namespace nprgl
