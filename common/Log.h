#pragma once

// nprgl's own diagnostics: always stderr (or NPRGL_LOG_FILE), always prefixed "nprgl:", never
// stdout, which belongs to the host program.

namespace nprgl {

enum class LogLevel { Error = 0, Warn = 1, Info = 2, Debug = 3 };

// Reads NPRGL_LOG_LEVEL and NPRGL_LOG_FILE. Safe to call more than once.
void initLog();
// Returns false and leaves the level unchanged for an unknown name.
bool parseLogLevel(const char* name, LogLevel& out);
void setLogLevel(LogLevel level);
bool logEnabled(LogLevel level);

void logMessage(LogLevel level, const char* fmt, ...) __attribute__((format(printf, 2, 3)));

} // namespace nprgl

#define NPRGL_LOG(level, ...)                                                                  \
    do {                                                                                       \
        if (::nprgl::logEnabled(level)) ::nprgl::logMessage(level, __VA_ARGS__);               \
    } while (0)
#define NPRGL_ERROR(...) NPRGL_LOG(::nprgl::LogLevel::Error, __VA_ARGS__)
#define NPRGL_WARN(...) NPRGL_LOG(::nprgl::LogLevel::Warn, __VA_ARGS__)
#define NPRGL_INFO(...) NPRGL_LOG(::nprgl::LogLevel::Info, __VA_ARGS__)
#define NPRGL_DEBUG(...) NPRGL_LOG(::nprgl::LogLevel::Debug, __VA_ARGS__)
