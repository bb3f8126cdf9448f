#pragma once

#include "Options.h"

#include <string>
#include <vector>

namespace demo {

// What an app draws. All hooks run with the GL context current.
class Scene {
public:
    virtual ~Scene() = default;

    virtual std::vector<ExtraOption> extraOptions() const { return {}; }
    // Called once before the first frame; returns false and sets error to abort with exit 1.
    virtual bool init(const Options& options, std::string& error) = 0;
    // frame counts from 1; the picture must depend on it only, never on time.
    virtual void draw(int frame) = 0;
    virtual void shutdown() {}
};

} // namespace demo
