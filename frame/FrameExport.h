#pragma once

#include "frame/StateTracker.h"
#include "reconstruct/Reconstructor.h"

#include <string>
#include <vector>

namespace nprgl {

// The space exported meshes are written in: as the program's camera saw them (eye), or as
// the program sent them (object: each object in its own coordinates).
enum class ExportSpace { Eye, Object };

// The frame's stylisable batches (polygonal and 3D) as reconstruction input.
std::vector<reconstruct::Batch> reconstructionBatches(const std::vector<TrackedBatch>& batches);

// Reconstructs a frame's meshes and writes them to path (.obj with one group per object,
// .ply or .off). Returns false with a message; objectCount says how many were written.
bool exportFrame(reconstruct::Reconstructor& reconstructor,
                 const std::vector<TrackedBatch>& batches, ExportSpace space,
                 const std::string& path, std::string& error, size_t* objectCount = nullptr);

} // namespace nprgl
