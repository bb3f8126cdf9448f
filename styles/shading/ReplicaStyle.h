#pragma once

// ReplicaStyle: the `replica` style: the held scene redrawn as GL would draw it, no NPR.

#include "styles/Style.h"
#include "styles/shading/PlainShading.h"

#include <string>

namespace nprgl::styles {

// The fidelity oracle. Everything the other styles draw goes through the same tracking,
// reconstruction, welding and chain; here the objects are drawn with the colours GL's own
// lighting and shade model gave their vertices (StyleInfo::programLighting) by PlainShading:
// the program's textures (sphere maps too) and lightmaps modulating, the layers the styles do
// not draw on average, and its fog; the chain applies its alpha test, blending,
// polygon offset and depth state. Where nprgl followed the program, the frame equals the
// program's own up to rasterisation; anywhere else the difference is nprgl's (`nprgl compare`).
class ReplicaStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    PlainShading mPlain; // the fixed pipeline's draw, as for scenes the program reads back
};

} // namespace nprgl::styles
