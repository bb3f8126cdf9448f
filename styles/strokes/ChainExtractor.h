#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/strokes/StrokeTypes.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace nprgl::styles::strokes {

// Thesis §4.4.3: finds the silhouette edges of a mesh for one eye (eq. 4.1, tested in object
// space) and links them into maximal chains while it finds them: from the first unvisited
// silhouette edge in edge order, walk forward through the neighbour lists; if the walk does
// not come back to the start, walk backward from the start too. No randomisation, so the
// same view gives the same chains. At a vertex with several unvisited candidates the walk
// takes the straightest one; the others start chains of their own later, so every selected
// edge lands in exactly one chain. Creases and borders, when asked for, are chained after
// the silhouettes (among themselves), so they never cut a silhouette loop.
class ChainExtractor {
public:
    struct Options {
        bool creases = false;
        bool borders = false;
    };

    // eye: the eye point in object space (reconstruct::eyeInObjectSpace).
    void extract(const reconstruct::ObjectMesh& mesh, const glm::vec3& eye,
                 const Options& options, EdgeChains& out);

    // Number of edges that passed the silhouette test in the last extract().
    uint32_t silhouetteCount() const { return mSilhouettes; }

private:
    // Walks from vertex `from` along unvisited edges of class `pass`, appending to the
    // scratch lists; returns true when it arrives back at `stop`.
    bool walk(const reconstruct::ObjectMesh& mesh, uint32_t from, uint32_t stop,
              glm::vec3 direction, uint8_t pass, std::vector<uint32_t>& vertices,
              std::vector<uint32_t>& edges);

    std::vector<uint8_t> mMark; // per edge: 0 not selected, 1 silhouette, 2 other, 0x80 visited
    std::vector<uint32_t> mSelected;
    std::vector<uint32_t> mForwardVertices, mForwardEdges, mBackVertices, mBackEdges;
    uint32_t mSilhouettes = 0;
};

} // namespace nprgl::styles::strokes
