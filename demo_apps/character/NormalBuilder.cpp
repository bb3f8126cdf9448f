#include "NormalBuilder.h"

#include <cmath>

namespace character {

void buildNormals(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices)
{
    for (Vertex& v : vertices) v.normal[0] = v.normal[1] = v.normal[2] = 0.0f;
    for (size_t i = 0; i + 2 < indices.size(); i += 3) {
        const float* a = vertices[indices[i]].position;
        const float* b = vertices[indices[i + 1]].position;
        const float* c = vertices[indices[i + 2]].position;
        float u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        float w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        float n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                      u[0] * w[1] - u[1] * w[0]};
        for (int k = 0; k < 3; ++k) {
            float* dst = vertices[indices[i + k]].normal;
            dst[0] += n[0];
            dst[1] += n[1];
            dst[2] += n[2];
        }
    }
    for (Vertex& v : vertices) {
        float length = std::sqrt(v.normal[0] * v.normal[0] + v.normal[1] * v.normal[1] +
                                 v.normal[2] * v.normal[2]);
        if (length > 0.0f) {
            for (float& n : v.normal) n /= length;
        } else {
            v.normal[1] = 1.0f;
        }
    }
}

} // namespace character
