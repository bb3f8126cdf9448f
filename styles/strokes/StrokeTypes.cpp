#include "styles/strokes/StrokeTypes.h"

namespace nprgl::styles::strokes {

float edgeFraction(const ChainPoint& p, uint32_t e0, uint32_t e1)
{
    (void)e1;
    if (p.va == p.vb) return p.va == e0 ? 0.0f : 1.0f;
    return p.va == e0 ? p.t : 1.0f - p.t;
}

ChainPoint splitPoint(const ChainPoint& a, const ChainPoint& b, float s, uint32_t e0,
                      uint32_t e1)
{
    // tau: the object-space fraction whose projection lands at screen fraction s.
    const float denom = (1.0f - s) * b.w + s * a.w;
    const float tau = denom != 0.0f ? s * a.w / denom : s;
    ChainPoint p;
    p.object = glm::mix(a.object, b.object, tau);
    p.window = glm::mix(a.window, b.window, s);
    p.biasedDepth = a.biasedDepth + (b.biasedDepth - a.biasedDepth) * s;
    p.w = a.w + (b.w - a.w) * tau;
    p.va = e0;
    p.vb = e1;
    const float fa = edgeFraction(a, e0, e1), fb = edgeFraction(b, e0, e1);
    p.t = fa + (fb - fa) * tau;
    return p;
}

} // namespace nprgl::styles::strokes
