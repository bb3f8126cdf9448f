#include "AssimpModel.h"

#include <assimp/postprocess.h>

namespace character {

bool AssimpModel::load(const std::string& path, const std::string& clip, std::string& error)
{
    scene = importer.ReadFile(path, aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                        aiProcess_JoinIdenticalVertices |
                                        aiProcess_LimitBoneWeights);
    if (!scene || !scene->mRootNode) {
        error = path + ": " + importer.GetErrorString();
        return false;
    }
    for (unsigned a = 0; a < scene->mNumAnimations && !animation; ++a) {
        const aiAnimation* candidate = scene->mAnimations[a];
        bool wanted = clip.empty() ? candidate->mDuration > 0.0
                                   : clip == candidate->mName.C_Str();
        if (wanted) animation = candidate;
    }
    if (!animation && !clip.empty()) {
        error = path + ": no animation named " + clip;
        return false;
    }
    if (!animation) {
        error = path + ": has no animation";
        return false;
    }
    return true;
}

} // namespace character
