#pragma once

#include "CharacterPose.h"
#include "SkinImage.h"

namespace character {

// Sends a pose to GL every frame in one of three legacy ways.
class MeshDrawer {
public:
    enum class Mode { ClientArrays, Immediate, BufferObjects };

    explicit MeshDrawer(Mode mode) : mode_(mode) {}

    // GL state for the mode, and the texture when there is one; the context must be current.
    void init(const SkinImage* skin);
    void draw(const CharacterPose& pose);
    void shutdown();

private:
    void drawImmediate(const CharacterPose& pose, const Part& part);

    Mode mode_;
    unsigned buffers_[2] = {0, 0};
    unsigned texture_ = 0;
};

} // namespace character
