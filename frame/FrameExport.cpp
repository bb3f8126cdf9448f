#include "frame/FrameExport.h"

#include "common/Log.h"
#include "reconstruct/MeshExport.h"

namespace nprgl {

std::vector<reconstruct::Batch> reconstructionBatches(const std::vector<TrackedBatch>& batches)
{
    std::vector<reconstruct::Batch> out;
    out.reserve(batches.size());
    for (const TrackedBatch& tb : batches) {
        if (!tb.is3D) continue; // 2D overlays are the program's own, never stylised
        reconstruct::Batch b;
        assignAssembly(b, tb);
        b.vertices = tb.vertices; // the same vertex type: one copy, no conversion
        b.contentHash = tb.contentHash != 0 ? tb.contentHash : reconstruct::hashBatch(b);
        out.push_back(std::move(b));
    }
    return out;
}

bool exportFrame(reconstruct::Reconstructor& reconstructor,
                 const std::vector<TrackedBatch>& batches, ExportSpace space,
                 const std::string& path, std::string& error, size_t* objectCount)
{
    std::vector<reconstruct::FrameObject> objects =
        reconstructor.build(reconstructionBatches(batches));
    std::vector<reconstruct::ExportObject> out;
    for (const reconstruct::FrameObject& o : objects) {
        out.push_back({o.mesh, space == ExportSpace::Eye ? o.modelview : glm::mat4(1.0f)});
    }
    if (objectCount) *objectCount = out.size();
    const reconstruct::CacheStats stats = reconstructor.cacheStats();
    NPRGL_DEBUG("reconstruction: %zu objects; cache hits %llu, updates %llu, rebuilds %llu",
                out.size(), static_cast<unsigned long long>(stats.hits),
                static_cast<unsigned long long>(stats.updates),
                static_cast<unsigned long long>(stats.rebuilds));
    if (out.empty()) {
        error = "the frame has no 3D polygon geometry to export";
        return false;
    }
    return reconstruct::exportMeshes(path, out, error);
}

} // namespace nprgl
