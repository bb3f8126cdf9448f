#include "common/Log.h"

#include "common/TextFile.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace nprgl {

namespace {

std::atomic<int> gLevel{static_cast<int>(LogLevel::Info)};
std::atomic<int> gFd{STDERR_FILENO};

const char* levelName(LogLevel level)
{
    switch (level) {
    case LogLevel::Error: return "error";
    case LogLevel::Warn: return "warning";
    case LogLevel::Info: return "info";
    case LogLevel::Debug: return "debug";
    }
    return "";
}

} // namespace

bool parseLogLevel(const char* name, LogLevel& out)
{
    static constexpr struct {
        const char* name;
        LogLevel level;
    } kNames[] = {{"error", LogLevel::Error}, {"warn", LogLevel::Warn},
                  {"warning", LogLevel::Warn}, {"info", LogLevel::Info},
                  {"debug", LogLevel::Debug}};
    for (const auto& n : kNames) {
        if (std::strcmp(name, n.name) == 0) {
            out = n.level;
            return true;
        }
    }
    return false;
}

void setLogLevel(LogLevel level) { gLevel.store(static_cast<int>(level)); }

bool logEnabled(LogLevel level) { return static_cast<int>(level) <= gLevel.load(); }

namespace {

// Only a regular file (made when missing) takes the log: a FIFO would hold the program at
// start (no reader) or at any line (a reader that stops reading), a device is not a log.
// Looked at before the open (which does not wait either) and again after it.
void openLogFile(const char* file)
{
    struct stat st {};
    if (::stat(file, &st) == 0 && !S_ISREG(st.st_mode)) {
        logMessage(LogLevel::Warn, "NPRGL_LOG_FILE=%s: not a regular file (%s); logging to stderr",
                   file, TextFile::typeName(st.st_mode));
        return;
    }
    // O_APPEND so that a forked child and its parent interleave whole lines.
    const int fd =
        ::open(file, O_WRONLY | O_CREAT | O_APPEND | O_NONBLOCK | O_NOCTTY | O_CLOEXEC, 0644);
    if (fd < 0) {
        logMessage(LogLevel::Warn, "cannot open NPRGL_LOG_FILE=%s (%s); logging to stderr", file,
                   std::strerror(errno));
        return;
    }
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        logMessage(LogLevel::Warn, "NPRGL_LOG_FILE=%s: not a regular file (%s); logging to stderr",
                   file, TextFile::typeName(st.st_mode));
        return;
    }
    ::fcntl(fd, F_SETFL, O_APPEND);
    gFd.store(fd);
}

} // namespace

void initLog()
{
    if (const char* file = std::getenv("NPRGL_LOG_FILE"); file && *file) openLogFile(file);
    if (const char* level = std::getenv("NPRGL_LOG_LEVEL"); level && *level) {
        LogLevel parsed;
        if (parseLogLevel(level, parsed)) {
            setLogLevel(parsed);
        } else {
            logMessage(LogLevel::Warn,
                       "unknown NPRGL_LOG_LEVEL=%s (use error, warn, info or debug); using warn",
                       level);
        }
    }
}

void logMessage(LogLevel level, const char* fmt, ...)
{
    // One write() per line, so lines from several threads or processes do not interleave.
    char buf[1024];
    int n = std::snprintf(buf, sizeof buf, "nprgl: %s%s",
                          level == LogLevel::Info ? "" : levelName(level),
                          level == LogLevel::Info ? "" : ": ");
    va_list ap;
    va_start(ap, fmt);
    int m = std::vsnprintf(buf + n, sizeof buf - n - 1, fmt, ap);
    va_end(ap);
    size_t len = static_cast<size_t>(n) + std::min<size_t>(m < 0 ? 0 : m, sizeof buf - n - 2);
    buf[len++] = '\n';
    ssize_t ignored = ::write(gFd.load(), buf, len);
    (void)ignored;
}

} // namespace nprgl
