#include "shim/ConfigWatcher.h"

#include "common/Log.h"

#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string_view>

namespace nprgl {

namespace {

// On a folder of the files: the files written, replaced, created, removed or renamed away.
constexpr uint32_t kFileEvents =
    IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_CREATE | IN_DELETE;
// On an ancestor of a missing folder: the next folder down made or moved in.
constexpr uint32_t kChildEvents = IN_CREATE | IN_MOVED_TO;
// On either: the folder itself removed or moved (the watch then follows the wrong folder).
constexpr uint32_t kSelfEvents = IN_DELETE_SELF | IN_MOVE_SELF | IN_ONLYDIR;

bool isDirectory(const std::filesystem::path& path)
{
    std::error_code ec;
    return std::filesystem::is_directory(path, ec);
}

template <class List> bool contains(const List& list, std::string_view name)
{
    return std::find(list.begin(), list.end(), name) != list.end();
}

} // namespace

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
    mDirs.clear();
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
    for (const std::string& path : paths) {
        const std::filesystem::path p(path);
        mNames.push_back(p.filename().string());
        const std::string dir = p.has_parent_path() ? p.parent_path().string() : std::string(".");
        if (!contains(mDirs, dir)) mDirs.push_back(dir);
    }
    arm();
}

void ConfigWatcher::arm()
{
    for (const Watch& w : mWatches)
        inotify_rm_watch(mFd, w.wd);
    mWatches.clear();
    for (const std::string& dir : mDirs) {
        // A folder may come or go between the look and the watch: then it is looked at again.
        for (int tries = 0; tries < 4; ++tries) {
            std::filesystem::path at(dir), child;
            while (!isDirectory(at)) {
                std::filesystem::path up = at.parent_path();
                if (up.empty() && at.is_relative() && at != ".") up = ".";
                if (up.empty() || up == at) {
                    at.clear(); // nothing of it exists: nothing to watch
                    break;
                }
                child = at.filename();
                at = std::move(up);
            }
            if (at.empty()) break;
            if (!child.empty()) {
                NPRGL_DEBUG("%s does not exist; watching %s for it", dir.c_str(), at.c_str());
            }
            if (!addWatch(at.string(), child.string())) continue;
            // The missing folder made since the look: its event was before the watch.
            if (child.empty() || !isDirectory(at / child)) break;
        }
    }
}

bool ConfigWatcher::addWatch(const std::string& path, const std::string& child)
{
    const uint32_t mask = kSelfEvents | (child.empty() ? kFileEvents : kChildEvents);
    // One watch per folder: a second ask for the same folder adds to its mask and wd.
    const int wd = inotify_add_watch(mFd, path.c_str(), mask | IN_MASK_ADD);
    if (wd < 0 && errno == ENOENT) return false; // removed since the look
    if (wd < 0) {
        NPRGL_WARN("cannot watch %s for configuration changes: %s; they apply on the reload key",
                   path.c_str(), std::strerror(errno));
        return true;
    }
    auto it =
        std::find_if(mWatches.begin(), mWatches.end(), [&](const Watch& w) { return w.wd == wd; });
    if (it == mWatches.end()) it = mWatches.insert(mWatches.end(), Watch{wd, path, {}, false});
    if (child.empty()) {
        it->files = true;
    } else if (!contains(it->children, child)) {
        it->children.push_back(child);
    }
    return true;
}

bool ConfigWatcher::changed()
{
    // A frame end of another context may be polling: that one reports the change.
    std::unique_lock lock(mMutex, std::try_to_lock);
    if (!lock.owns_lock() || mFd < 0) return false;
    bool hit = false, rearm = false;
    alignas(inotify_event) char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(mFd, buffer, sizeof buffer);
        if (n <= 0) break;
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            at += ssize_t(sizeof(inotify_event) + event->len);
            if (event->mask & IN_Q_OVERFLOW) {
                rearm = true; // events were lost: look at everything again
                continue;
            }
            const auto w = std::find_if(mWatches.begin(), mWatches.end(),
                                        [&](const Watch& x) { return x.wd == event->wd; });
            if (w == mWatches.end()) continue; // a watch dropped by arm()
            if (event->mask & (IN_DELETE_SELF | IN_MOVE_SELF | IN_IGNORED)) rearm = true;
            if (event->len == 0) continue;
            const std::string_view name(event->name);
            if (w->files && contains(mNames, name)) hit = true;
            if ((event->mask & kChildEvents) && contains(w->children, name)) rearm = true;
        }
    }
    if (!rearm) return hit;
    arm();
    // The files may have come or gone with their folder, unseen: read them again.
    return true;
}

} // namespace nprgl
