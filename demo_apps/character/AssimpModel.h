#pragma once

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <string>

namespace character {

// An assimp import kept alive with the animation chosen from it.
struct AssimpModel {
    Assimp::Importer importer;
    const aiScene* scene = nullptr;
    const aiAnimation* animation = nullptr;

    // clip names an animation; empty picks the first one that lasts longer than an instant.
    bool load(const std::string& path, const std::string& clip, std::string& error);
};

} // namespace character
