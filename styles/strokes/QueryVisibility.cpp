#include "styles/strokes/QueryVisibility.h"

#include "styles/ObjectNames.h"

#include <algorithm>
#include <utility>

namespace nprgl::styles::strokes {

namespace {

const char* kVertex = R"(#version 130
in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";
const char* kFragment = R"(#version 130
out vec4 fragColor;
void main() { fragColor = vec4(1.0); }
)";

constexpr uint8_t kNoPixels = 3; // internal: the line covered no pixel at all

} // namespace

bool QueryVisibility::init(const GlFunctions& gl, std::string& error)
{
    if (!mProgram.build(gl, kVertex, kFragment, error)) return false;
    ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &mBuffer);
    return true;
}

void QueryVisibility::destroy(const GlFunctions& gl)
{
    mProgram.destroy(gl);
    if (mBuffer) gl.DeleteBuffers(1, &mBuffer);
    mBuffer = 0;
    mBufferBytes = 0;
    if (!mQueries.empty()) gl.DeleteQueries(GLsizei(mQueries.size()), mQueries.data());
    mQueries.clear();
}

void QueryVisibility::runQueries(const GlFunctions& gl, const glm::ivec4& viewport,
                                 const Polylines& lines)
{
    const size_t count = mPending.size();
    mVertices.resize(count * 6);
    const float sx = 2.0f / float(std::max(viewport.z, 1));
    const float sy = 2.0f / float(std::max(viewport.w, 1));
    for (size_t k = 0; k < count; ++k) {
        for (int end = 0; end < 2; ++end) {
            const ChainPoint& p = lines.points[mPending[k] + uint32_t(end)];
            float* v = &mVertices[k * 6 + size_t(end) * 3];
            v[0] = (p.window.x - float(viewport.x)) * sx - 1.0f;
            v[1] = (p.window.y - float(viewport.y)) * sy - 1.0f;
            v[2] = 2.0f * p.biasedDepth - 1.0f;
        }
    }
    if (mQueries.size() < count * 2) {
        const size_t old = mQueries.size();
        mQueries.resize(count * 2);
        ObjectNames::reserve(gl, ObjectNames::Kind::Query, GLsizei(count * 2 - old), mQueries.data() + old);
    }
    const GLsizeiptr bytes = GLsizeiptr(mVertices.size() * sizeof(float));
    gl.BindBuffer(GL_ARRAY_BUFFER, mBuffer);
    if (bytes > mBufferBytes) {
        mBufferBytes = std::max(bytes, mBufferBytes * 2);
        gl.BufferData(GL_ARRAY_BUFFER, mBufferBytes, nullptr, GL_STREAM_DRAW);
    }
    gl.BufferSubData(GL_ARRAY_BUFFER, 0, bytes, mVertices.data());
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.EnableVertexAttribArray(0);
    for (int pass = 0; pass < 2; ++pass) {
        // Pass 0: every pixel the line could cover; pass 1: those not behind the scene.
        if (pass == 0) gl.Disable(GL_DEPTH_TEST);
        else gl.Enable(GL_DEPTH_TEST);
        for (size_t k = 0; k < count; ++k) {
            gl.BeginQuery(GL_SAMPLES_PASSED, mQueries[k * 2 + size_t(pass)]);
            gl.DrawArrays(GL_LINES, GLint(k * 2), 2);
            gl.EndQuery(GL_SAMPLES_PASSED);
        }
    }
    mRatio.resize(count);
    for (size_t k = 0; k < count; ++k) {
        GLuint all = 0, passed = 0;
        gl.GetQueryObjectuiv(mQueries[k * 2], GL_QUERY_RESULT, &all);
        gl.GetQueryObjectuiv(mQueries[k * 2 + 1], GL_QUERY_RESULT, &passed);
        mRatio[k] = all ? float(passed) / float(all) : -1.0f;
    }
    mQueryCount += uint32_t(count * 2);
}

void QueryVisibility::classify(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh,
                               const glm::ivec4& viewport, const Options& options,
                               Polylines& lines)
{
    mQueryCount = 0;
    gl.UseProgram(mProgram.id());
    GLboolean mask[4] = {GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE};
    gl.GetBooleanv(GL_COLOR_WRITEMASK, mask); // the pass's, alpha as the program writes it
    gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.DepthMask(GL_FALSE);
    gl.DepthFunc(GL_LEQUAL);
    gl.Disable(GL_BLEND);
    gl.Disable(GL_LINE_SMOOTH);
    gl.Disable(GL_LINE_STIPPLE);
    gl.LineWidth(options.lineWidth);
    const float mean = 0.5f * (options.invisibleThreshold + options.visibleThreshold);
    for (int iteration = 0;; ++iteration) {
        mPending.clear();
        for (uint32_t p = 0; p < lines.count(); ++p) {
            for (uint32_t i = lines.start[p]; i + 1 < lines.start[p + 1]; ++i)
                if (lines.state[i] == kUnknown) mPending.push_back(i);
        }
        if (mPending.empty()) break;
        runQueries(gl, viewport, lines);
        const bool last = iteration >= options.iterations;
        bool split = false;
        for (size_t k = 0; k < mPending.size(); ++k) {
            const float r = mRatio[k];
            uint8_t& state = lines.state[mPending[k]];
            if (r < 0.0f) state = kNoPixels;
            else if (r <= options.invisibleThreshold) state = kHidden;
            else if (r >= options.visibleThreshold) state = kVisible;
            else if (last) state = r >= mean ? kVisible : kHidden;
            else split = true; // stays unknown: refined below
        }
        if (!split) break;
        // Ambiguous segments become two unknown halves (split in the middle on screen).
        mOut.clear();
        for (uint32_t p = 0; p < lines.count(); ++p) {
            const uint32_t begin = lines.start[p], end = lines.start[p + 1];
            for (uint32_t i = begin; i + 1 < end; ++i) {
                mOut.addPoint(lines.points[i], lines.edge[i], lines.state[i]);
                if (lines.state[i] != kUnknown) continue;
                const reconstruct::EdgeInfo& info = mesh.edges[lines.edge[i]];
                mOut.addPoint(splitPoint(lines.points[i], lines.points[i + 1], 0.5f, info.v0,
                                         info.v1),
                              lines.edge[i], kUnknown);
            }
            mOut.addPoint(lines.points[end - 1], 0, kUnknown);
            mOut.endPolyline(lines.closed[p] != 0);
        }
        std::swap(mOut, lines);
    }
    // Lines too short to cover a pixel take their neighbour's verdict.
    for (uint32_t p = 0; p < lines.count(); ++p) {
        const uint32_t begin = lines.start[p], end = lines.start[p + 1];
        uint8_t previous = kUnknown;
        for (uint32_t i = begin; i + 1 < end; ++i) {
            if (lines.state[i] != kNoPixels) {
                previous = lines.state[i];
                continue;
            }
            uint8_t next = kUnknown;
            for (uint32_t j = i + 1; j + 1 < end && next == kUnknown; ++j)
                if (lines.state[j] != kNoPixels) next = lines.state[j];
            const uint8_t fallback = next != kUnknown ? next : uint8_t(kVisible);
            lines.state[i] = previous != kUnknown ? previous : fallback;
        }
    }
    gl.DisableVertexAttribArray(0);
    gl.ColorMask(mask[0], mask[1], mask[2], mask[3]);
    gl.DepthMask(GL_TRUE);
    gl.Enable(GL_DEPTH_TEST);
    gl.LineWidth(1.0f);
}

} // namespace nprgl::styles::strokes
