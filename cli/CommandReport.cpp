#include "cli/CommandReport.h"

#include <cstdio>

namespace nprgl::cli {

void say(const std::string& line)
{
    std::fprintf(stderr, "nprgl: %s\n", line.c_str());
}

bool openCapture(const std::string& file, capture::CaptureReader& reader, std::string& error)
{
    if (!reader.open(file, error)) return false;
    for (const std::string& note : reader.notes()) say(note);
    return true;
}

int finish(const capture::ReadReport& report, uint64_t framesRead)
{
    if (!report.damaged()) return 0;
    say(report.summary(framesRead));
    return 1;
}

} // namespace nprgl::cli
