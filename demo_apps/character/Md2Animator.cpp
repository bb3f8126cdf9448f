#include "Md2Animator.h"

#include "NormalBuilder.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace character {

namespace {

constexpr double framesPerSecond = 10.0; // Quake II's server rate, for which MD2 clips are made

struct Md2Header {
    char ident[4];
    int32_t version;
    int32_t skinWidth, skinHeight, frameSize;
    int32_t numSkins, numVertices, numSt, numTris, numGlCommands, numFrames;
    int32_t ofsSkins, ofsSt, ofsTris, ofsFrames, ofsGlCommands, ofsEnd;
};

// "run01" -> "run": frames of one clip share the name without its number.
std::string clipOf(const std::string& frameName)
{
    size_t end = frameName.find_last_not_of("0123456789");
    return end == std::string::npos ? frameName : frameName.substr(0, end + 1);
}

} // namespace

bool Md2Animator::load(const std::string& path, const std::string& clip, std::string& error)
{
    std::ifstream in(path, std::ios::binary);
    std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    Md2Header h;
    if (data.size() < sizeof h) {
        error = path + ": too short for an MD2 file";
        return false;
    }
    std::memcpy(&h, data.data(), sizeof h);
    auto fits = [&](int64_t offset, int64_t count, int64_t size) {
        return offset >= 0 && count >= 0 && size > 0 &&
               offset + count * size <= static_cast<int64_t>(data.size());
    };
    if (std::memcmp(h.ident, "IDP2", 4) != 0 || h.version != 8 || h.numFrames < 1 ||
        h.numVertices < 3 || h.frameSize < 40 + 4 * h.numVertices ||
        !fits(h.ofsTris, h.numTris, 12) || !fits(h.ofsFrames, h.numFrames, h.frameSize)) {
        error = path + ": not a valid MD2 file";
        return false;
    }

    for (int t = 0; t < h.numTris; ++t) {
        int16_t corner[3];
        std::memcpy(corner, data.data() + h.ofsTris + 12 * t, sizeof corner);
        for (int16_t c : corner) {
            if (c < 0 || c >= h.numVertices) {
                error = path + ": triangle refers to a missing vertex";
                return false;
            }
        }
        // MD2 triangles wind clockwise; GL's front faces wind counter-clockwise.
        triangles_.insert(triangles_.end(), {uint32_t(corner[0]), uint32_t(corner[2]),
                                             uint32_t(corner[1])});
    }

    for (int f = 0; f < h.numFrames; ++f) {
        const char* frame = data.data() + h.ofsFrames + static_cast<int64_t>(f) * h.frameSize;
        float scale[3], translate[3];
        char name[17] = {};
        std::memcpy(scale, frame, sizeof scale);
        std::memcpy(translate, frame + 12, sizeof translate);
        std::memcpy(name, frame + 24, 16);
        Keyframe key;
        key.name = name;
        const auto* packed = reinterpret_cast<const uint8_t*>(frame + 40);
        for (int v = 0; v < h.numVertices; ++v) {
            float p[3];
            for (int i = 0; i < 3; ++i) p[i] = packed[4 * v + i] * scale[i] + translate[i];
            // MD2 is Z-up; turn it Y-up.
            key.positions.insert(key.positions.end(), {p[0], p[2], -p[1]});
        }
        frames_.push_back(std::move(key));
    }

    // The requested clip, else "run" when the model has one, else every frame.
    std::string wanted = clip.empty() ? "run" : clip;
    for (size_t f = 0; f < frames_.size(); ++f) {
        if (clipOf(frames_[f].name) != wanted) continue;
        if (clipCount_ == 0) clipFirst_ = f;
        ++clipCount_;
    }
    if (clipCount_ == 0 && !clip.empty()) {
        error = path + ": no frames named " + clip;
        return false;
    }
    if (clipCount_ == 0) {
        clipFirst_ = 0;
        clipCount_ = frames_.size();
        clipName_ = "all frames";
    } else {
        clipName_ = wanted;
    }
    return true;
}

void Md2Animator::pose(double seconds, CharacterPose& pose)
{
    double position = std::fmod(seconds * framesPerSecond, static_cast<double>(clipCount_));
    size_t a = static_cast<size_t>(position);
    size_t b = (a + 1) % clipCount_;
    float t = static_cast<float>(position - a);
    const std::vector<float>& from = frames_[clipFirst_ + a].positions;
    const std::vector<float>& to = frames_[clipFirst_ + b].positions;

    size_t count = from.size() / 3;
    pose.vertices.resize(count);
    for (size_t v = 0; v < count; ++v) {
        for (int i = 0; i < 3; ++i) {
            pose.vertices[v].position[i] = from[3 * v + i] + t * (to[3 * v + i] - from[3 * v + i]);
        }
    }
    pose.indices = triangles_;
    buildNormals(pose.vertices, pose.indices);
    pose.parts.assign(1, Part{});
    pose.parts[0].indexCount = static_cast<uint32_t>(pose.indices.size());
}

std::string Md2Animator::describe() const
{
    return "morph: " + std::to_string(frames_.size()) + " MD2 keyframes, clip " + clipName_ +
           " (" + std::to_string(clipCount_) + " frames), " +
           std::to_string(frames_.empty() ? 0 : frames_[0].positions.size() / 3) +
           " vertices, " + std::to_string(triangles_.size() / 3) + " triangles";
}

} // namespace character
