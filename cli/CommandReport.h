// How the commands that read a capture say what they found: notes at open, a summary at the end.
#pragma once

#include "capture/CaptureReader.h"
#include "capture/ReadReport.h"

#include <cstdint>
#include <string>

namespace nprgl::cli {

// One line on stderr with the "nprgl: " prefix.
void say(const std::string& line);

// Opens a capture and says what the reader found at open: damaged stretches (each with its
// offset), an incomplete last chunk, a recording that did not close the file.
bool openCapture(const std::string& file, capture::CaptureReader& reader, std::string& error);

// The exit status of a command that read what it could: 1, with a summary, when anything
// was damaged or lost; 0 otherwise.
int finish(const capture::ReadReport& report,
           uint64_t framesRead = capture::ReadReport::kUnknown);

} // namespace nprgl::cli
