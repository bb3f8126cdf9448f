#pragma once

#include <string>
#include <vector>

namespace nprgl::cli {

struct RunOptions {
    std::string style;
    std::string preset; // a shipped preset's name or a preset file
    std::vector<std::string> settings; // key=value
    std::string screenshot;
    std::string logLevel;
    std::string logFile;
    std::vector<std::string> command; // program and its arguments
    bool record = false;
    std::string recordFile;   // default: <program>.nprgl in the current directory
    std::string recordFrames; // A-B
    bool recordForce = false; // replace recordFile if it is a capture
    std::string video;        // encode the program's frames into this file
    int fps = 30;
    bool videoOnKey = false;  // the first recording starts at the video key, not at once
};

// Checks the options, sets up the environment and replaces this process with the program
// (so its exit code, pid and signals are the program's own). Returns only on failure, with
// the exit code to use.
int runProgram(const RunOptions& options);

// The absolute path of libnprgl.so: NPRGL_LIBRARY, else the build tree's or the installed one
// beside this executable.
std::string findLibrary(std::string& error);

// What LD_PRELOAD names for that library: the installed one or the build tree's through the
// loader's $LIB (<prefix>/$LIB/nprgl/libnprgl.so, build/$LIB/nprgl/libnprgl.so), any
// other as it is.
std::string preloadEntry(const std::string& library);

} // namespace nprgl::cli
