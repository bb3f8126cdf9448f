#include "shim/ConfigWatcher.h"

#include "common/Log.h"

#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

namespace nprgl {

ConfigWatcher& ConfigWatcher::instance()
{
    static ConfigWatcher* watcher = new ConfigWatcher; // lives past exit, as the contexts do
    return *watcher;
}

void ConfigWatcher::close()
{
    if (mFd >= 0) ::close(mFd);
    mFd = -1;
    mWatches.clear();
    mNames.clear();
}

void ConfigWatcher::watch(const std::vector<std::string>& paths)
{
    std::lock_guard lock(mMutex);
    close();
    if (paths.empty()) return;
    // Close-on-exec: a program's children must not inherit our descriptor.
    mFd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (mFd < 0) {
        NPRGL_DEBUG("inotify unavailable; configuration changes apply on the reload key");
        return;
    }
    constexpr uint32_t kEvents = IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE;
    std::vector<std::string> dirs;
    for (const std::string& path : paths) {
        const std::filesystem::path p(path);
        mNames.push_back(p.filename().string());
        const std::string dir = p.has_parent_path() ? p.parent_path().string() : std::string(".");
        if (std::find(dirs.begin(), dirs.end(), dir) != dirs.end()) continue;
        dirs.push_back(dir);
        const int wd = inotify_add_watch(mFd, dir.c_str(), kEvents);
        if (wd < 0) {
            NPRGL_DEBUG("cannot watch %s for configuration changes", dir.c_str());
            continue;
        }
        mWatches.push_back(wd);
    }
}

bool ConfigWatcher::changed()
{
    // A frame end of another context may be polling: that one reports the change.
    std::unique_lock lock(mMutex, std::try_to_lock);
    if (!lock.owns_lock() || mFd < 0) return false;
    bool hit = false;
    alignas(inotify_event) char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(mFd, buffer, sizeof buffer);
        if (n <= 0) break;
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            if (event->len > 0) {
                const std::string name(event->name);
                hit = hit || std::find(mNames.begin(), mNames.end(), name) != mNames.end();
            }
            at += ssize_t(sizeof(inotify_event) + event->len);
        }
    }
    return hit;
}

} // namespace nprgl
