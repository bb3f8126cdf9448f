#include "common/ScreenshotSpec.h"

#include "common/KeyValue.h"

namespace nprgl {

bool ScreenshotSpec::parse(std::string_view text, ScreenshotSpec& out, std::string& error)
{
    KeyValueList pairs;
    if (!parseKeyValues(text, ';', pairs, error)) return false;
    ScreenshotSpec spec;
    bool haveFrames = false;
    for (const auto& [key, value] : pairs) {
        if (key == "frames") {
            if (!FrameSet::parse(value, spec.frames, error)) return false;
            haveFrames = true;
        } else if (key == "dir") {
            spec.dir = value.empty() ? "." : value;
        } else {
            error = "unknown key '" + key + "' (use frames=LIST;dir=DIR)";
            return false;
        }
    }
    if (!haveFrames) {
        error = "frames=LIST is missing (e.g. frames=1,10,100;dir=out)";
        return false;
    }
    out = std::move(spec);
    return true;
}

} // namespace nprgl
