#pragma once

#include "CharacterPose.h"
#include "SkinImage.h"

#include <string>

namespace character {

// One animation technique applied to one model file.
class Animator {
public:
    virtual ~Animator() = default;

    // clip selects an animation by name (empty: a sensible default); false sets error.
    virtual bool load(const std::string& path, const std::string& clip, std::string& error) = 0;
    // Fills pose for the given animation time; a pure function of seconds.
    virtual void pose(double seconds, CharacterPose& pose) = 0;
    // One line for --report and the log: technique, clip, sizes.
    virtual std::string describe() const = 0;
    // The model's texture, or null when it has none (then the vertices' texcoords are unused).
    virtual const SkinImage* skin() const { return nullptr; }
};

} // namespace character
