#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"

namespace nprgl::styles {

// Cartoon shading (thesis §3.1): per pixel, L·n below t_d takes the shadow colour, above t_h
// the highlight colour, else the diffuse colour; all three derived from the program's own
// colour or material.
class ToonStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    ShaderProgram mProgram;
};

} // namespace nprgl::styles
