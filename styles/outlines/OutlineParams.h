#pragma once

#include "styles/Style.h"
#include "styles/StyleRegistry.h"

#include <glm/glm.hpp>

#include <vector>

namespace nprgl::styles {

// Parameters every outline style shares: one ink colour (commas separate NPRGL_CONFIG
// entries, so a colour is three numbers) and, per line class, a lightness that mixes the
// ink towards white for lighter secondary lines.

// Appends ink_red, ink_green, ink_blue (default black).
void addInkParams(std::vector<ParamInfo>& params);
// Appends "<lineClass>_lightness" with help naming the class.
void addLightnessParam(std::vector<ParamInfo>& params, const char* lineClass, double def);
glm::vec3 inkColour(const StyleContext& ctx, const char* style);
// The ink mixed towards white by the class's lightness parameter.
glm::vec3 classColour(const StyleContext& ctx, const char* style, const char* lightnessParam);

} // namespace nprgl::styles
