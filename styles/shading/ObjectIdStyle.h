#pragma once

// ObjectIdStyle: the `ids` debug style: each styled object in a colour encoding its id.

#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"

#include <cstdint>
#include <string>

namespace nprgl::styles {

// What `nprgl compare` reads to tell which object covers a pixel: object id i is drawn in
// exactly FrameFidelity::idColour(i) (no light, no fog, no blending); the program's own drawing (what the
// compositor leaves) stays as it is. Alpha-tested cut-outs keep their cut.
class ObjectIdStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    ShaderProgram mProgram;
    ShadingCommon::ObjectUniforms mU;
    GLint mId = -1;
    GLint mTextured = -1;
};

} // namespace nprgl::styles
