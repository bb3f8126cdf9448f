// InfoCommand: `nprgl info`: a capture's metadata, frames, calls and what was not captured.
#pragma once

#include <string>

namespace nprgl::cli {

// Prints what the capture holds, as text or (json) one JSON object on stdout. Exit status 1
// when the file cannot be read or is damaged (what could be read is still printed).
int infoCommand(const std::string& file, bool json);

} // namespace nprgl::cli
