#include "Md2Animator.h"

#include "NormalBuilder.h"

#include <cmath>
#include <filesystem>
#include <map>
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

    const bool textured = h.numSt > 0 && h.skinWidth > 0 && h.skinHeight > 0 &&
                          fits(h.ofsSt, h.numSt, 4);
    std::map<std::pair<int, int>, uint32_t> corners; // (vertex, st) -> pose vertex
    for (int t = 0; t < h.numTris; ++t) {
        int16_t corner[3], st[3];
        std::memcpy(corner, data.data() + h.ofsTris + 12 * t, sizeof corner);
        std::memcpy(st, data.data() + h.ofsTris + 12 * t + 6, sizeof st);
        for (int k = 0; k < 3; ++k) {
            if (corner[k] < 0 || corner[k] >= h.numVertices ||
                (textured && (st[k] < 0 || st[k] >= h.numSt))) {
                error = path + ": triangle refers to a missing vertex";
                return false;
            }
        }
        // MD2 triangles wind clockwise; GL's front faces wind counter-clockwise.
        for (int k : {0, 2, 1}) {
            triangles_.push_back(uint32_t(corner[k]));
            const int s = textured ? st[k] : 0;
            auto [it, added] = corners.emplace(std::pair{int(corner[k]), s},
                                               uint32_t(cornerVertex_.size()));
            if (added) {
                cornerVertex_.push_back(uint32_t(corner[k]));
                int16_t uv[2] = {0, 0};
                if (textured) std::memcpy(uv, data.data() + h.ofsSt + 4 * s, sizeof uv);
                // MD2 measures t from the top of the skin; GL from its bottom row.
                cornerTexcoord_.insert(cornerTexcoord_.end(),
                                       {float(uv[0]) / h.skinWidth,
                                        1.0f - float(uv[1]) / h.skinHeight});
            }
            cornerTriangles_.push_back(it->second);
        }
    }
    std::vector<std::string> skinNames;
    for (int i = 0; fits(h.ofsSkins, h.numSkins, 64) && i < h.numSkins; ++i) {
        skinNames.emplace_back(data.data() + h.ofsSkins + 64 * i,
                               strnlen(data.data() + h.ofsSkins + 64 * i, 64));
    }
    if (textured && !loadSkin(path, skinNames, error)) return false;

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

    // Blend and light the MD2 vertices, then give each texture corner its vertex: normals are
    // built on the shared vertices so that texture seams are not shading seams.
    size_t count = from.size() / 3;
    shared_.resize(count);
    for (size_t v = 0; v < count; ++v) {
        for (int i = 0; i < 3; ++i) {
            shared_[v].position[i] = from[3 * v + i] + t * (to[3 * v + i] - from[3 * v + i]);
        }
    }
    buildNormals(shared_, triangles_);
    pose.vertices.resize(cornerVertex_.size());
    for (size_t c = 0; c < cornerVertex_.size(); ++c) {
        pose.vertices[c] = shared_[cornerVertex_[c]];
        pose.vertices[c].texcoord[0] = cornerTexcoord_[2 * c];
        pose.vertices[c].texcoord[1] = cornerTexcoord_[2 * c + 1];
    }
    pose.indices = cornerTriangles_;
    pose.parts.assign(1, Part{});
    pose.parts[0].indexCount = static_cast<uint32_t>(pose.indices.size());
}

bool Md2Animator::loadSkin(const std::string& modelPath, const std::vector<std::string>& named,
                           std::string& error)
{
    namespace fs = std::filesystem;
    std::vector<std::string> candidates;
    if (!skinPath_.empty()) {
        candidates.push_back(skinPath_); // asked for: a failure is an error
    } else {
        for (const std::string& name : named) {
            candidates.push_back((fs::path(modelPath).parent_path() / fs::path(name).filename())
                                     .replace_extension(".bmp")
                                     .string());
        }
        candidates.push_back(fs::path(modelPath).replace_extension(".bmp").string());
    }
    for (const std::string& candidate : candidates) {
        if (!skinPath_.empty() || fs::exists(candidate)) {
            return skin_.loadBmp(candidate, error);
        }
    }
    return true; // no skin beside the model: drawn in its material colour
}

std::string Md2Animator::describe() const
{
    return "morph: " + std::to_string(frames_.size()) + " MD2 keyframes, clip " + clipName_ +
           " (" + std::to_string(clipCount_) + " frames), " +
           std::to_string(frames_.empty() ? 0 : frames_[0].positions.size() / 3) +
           " vertices, " + std::to_string(triangles_.size() / 3) + " triangles" +
           (skin_.width ? ", textured" : "");
}

} // namespace character
