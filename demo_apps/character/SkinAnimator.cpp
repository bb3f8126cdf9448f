#include "SkinAnimator.h"

#include <functional>
#include <unordered_map>

namespace character {

bool SkinAnimator::load(const std::string& path, const std::string& clip, std::string& error)
{
    if (!model_.load(path, clip, error)) return false;
    const aiScene* scene = model_.scene;

    // The node that places each mesh, for meshes without bones.
    std::unordered_map<unsigned, const aiNode*> meshNodes;
    std::function<void(const aiNode*)> findMeshes = [&](const aiNode* node) {
        for (unsigned m = 0; m < node->mNumMeshes; ++m) meshNodes.emplace(node->mMeshes[m], node);
        for (unsigned c = 0; c < node->mNumChildren; ++c) findMeshes(node->mChildren[c]);
    };
    findMeshes(scene->mRootNode);

    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        if (!mesh->HasFaces() || !mesh->HasNormals() || meshNodes.count(m) == 0) continue;
        uint32_t base = static_cast<uint32_t>(bindPositions_.size());
        std::vector<std::vector<Influence>> perVertex(mesh->mNumVertices);
        for (unsigned b = 0; b < mesh->mNumBones; ++b) {
            const aiBone* bone = mesh->mBones[b];
            const aiNode* node = scene->mRootNode->FindNode(bone->mName);
            if (!node) continue;
            uint32_t matrix = static_cast<uint32_t>(bones_.size());
            bones_.push_back({node, bone->mOffsetMatrix});
            for (unsigned w = 0; w < bone->mNumWeights; ++w) {
                const aiVertexWeight& weight = bone->mWeights[w];
                if (weight.mVertexId < mesh->mNumVertices && weight.mWeight > 0.0f) {
                    perVertex[weight.mVertexId].push_back({matrix, weight.mWeight});
                }
            }
        }
        // Vertices no bone moves follow the mesh's own node.
        uint32_t rigid = static_cast<uint32_t>(bones_.size());
        bones_.push_back({meshNodes[m], aiMatrix4x4()});
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            influenceStart_.push_back(static_cast<uint32_t>(influences_.size()));
            float total = 0.0f;
            for (const Influence& i : perVertex[v]) total += i.weight;
            if (total <= 0.0f) {
                influences_.push_back({rigid, 1.0f});
            } else {
                for (const Influence& i : perVertex[v]) {
                    influences_.push_back({i.matrix, i.weight / total});
                }
            }
            bindPositions_.push_back(mesh->mVertices[v]);
            bindNormals_.push_back(mesh->mNormals[v]);
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            for (unsigned k = 0; k < 3; ++k) indices_.push_back(base + face.mIndices[k]);
        }
    }
    influenceStart_.push_back(static_cast<uint32_t>(influences_.size()));
    if (indices_.empty()) {
        error = path + ": has no triangle mesh";
        return false;
    }
    boneMatrices_.resize(bones_.size());
    skeleton_ = std::make_unique<SkeletonPose>(scene, model_.animation);
    return true;
}

void SkinAnimator::pose(double seconds, CharacterPose& pose)
{
    skeleton_->evaluate(seconds, false);
    // Undo the file's own placement of the whole scene, as assimp's skinning convention does.
    aiMatrix4x4 rootInverse = model_.scene->mRootNode->mTransformation;
    rootInverse.Inverse();
    for (size_t b = 0; b < bones_.size(); ++b) {
        boneMatrices_[b] = rootInverse * skeleton_->global(bones_[b].node) * bones_[b].offset;
    }

    pose.vertices.resize(bindPositions_.size());
    for (size_t v = 0; v < bindPositions_.size(); ++v) {
        aiVector3D position(0.0f, 0.0f, 0.0f), normal(0.0f, 0.0f, 0.0f);
        for (uint32_t i = influenceStart_[v]; i < influenceStart_[v + 1]; ++i) {
            const aiMatrix4x4& m = boneMatrices_[influences_[i].matrix];
            float w = influences_[i].weight;
            position += (m * bindPositions_[v]) * w;
            normal += (aiMatrix3x3(m) * bindNormals_[v]) * w;
        }
        normal.NormalizeSafe();
        Vertex& out = pose.vertices[v];
        out.position[0] = position.x;
        out.position[1] = position.y;
        out.position[2] = position.z;
        out.normal[0] = normal.x;
        out.normal[1] = normal.y;
        out.normal[2] = normal.z;
    }
    pose.indices = indices_;
    pose.parts.assign(1, Part{});
    pose.parts[0].indexCount = static_cast<uint32_t>(indices_.size());
}

std::string SkinAnimator::describe() const
{
    return "skin: animation " + std::string(model_.animation->mName.C_Str()) + " (" +
           std::to_string(skeleton_->durationSeconds()) + " s), " +
           std::to_string(bones_.size()) + " bone matrices, " +
           std::to_string(bindPositions_.size()) + " vertices, " +
           std::to_string(indices_.size() / 3) + " triangles";
}

} // namespace character
