#pragma once

#include <map>
#include <string>
#include <vector>

namespace nprgl::test {

struct ProcessResult {
    int exitCode = -1; // -1: did not start; 128+N: killed by signal N
    std::string out;
    std::string err;
};

// Runs argv with extra environment variables (an empty value removes the variable) and waits,
// capturing stdout and stderr. timeoutSeconds > 0 sends SIGTERM when it runs out.
ProcessResult runProcess(const std::vector<std::string>& argv,
                         const std::map<std::string, std::string>& env = {},
                         int timeoutSeconds = 120);

// Paths of the build tree, passed in by CMake.
std::string binDir();
std::string libPath();
// A fresh empty directory under the test's temporary area.
std::string freshDir(const std::string& name);

} // namespace nprgl::test
