#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/GlFunctions.h"
#include "styles/ShaderProgram.h"
#include "styles/strokes/StrokeTypes.h"

#include <glm/glm.hpp>

#include <string>
#include <vector>

namespace nprgl::styles::strokes {

// The thesis's visibility test (§4.4.4): every unknown segment is drawn as a line twice with
// colour and depth writes off, once without and once with the depth test, each inside an
// occlusion query (GL_SAMPLES_PASSED). V_r = passed with / passed without; V_r <= t_invis is
// hidden, V_r >= t_vis visible, anything between is split in the middle and tested again,
// at most `iterations` times; what is still ambiguous then is decided by the mean threshold.
// Lines use the tolerance-biased depth so that a line lying on its own surface passes.
class QueryVisibility {
public:
    struct Options {
        float invisibleThreshold = 0.1f;
        float visibleThreshold = 0.4f;
        int iterations = 3;
        float lineWidth = 3.0f;
    };

    bool init(const GlFunctions& gl, std::string& error);
    void destroy(const GlFunctions& gl);
    // Classifies (and splits) `lines` of one object; the depth buffer holds the scene.
    void classify(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh,
                  const glm::ivec4& viewport, const Options& options, Polylines& lines);

    // Queries issued by the last classify() (two per tested segment).
    uint32_t queryCount() const { return mQueryCount; }

private:
    void runQueries(const GlFunctions& gl, const glm::ivec4& viewport, const Polylines& lines);

    ShaderProgram mProgram;
    GLuint mBuffer = 0;
    std::vector<GLuint> mQueries;
    std::vector<uint32_t> mPending;   // indices of the unknown segments being tested
    std::vector<float> mVertices;     // 2 NDC points per pending segment
    std::vector<float> mRatio;        // per pending segment; < 0: no pixel at all
    GLsizeiptr mBufferBytes = 0;
    Polylines mOut;
    uint32_t mQueryCount = 0;
};

} // namespace nprgl::styles::strokes
