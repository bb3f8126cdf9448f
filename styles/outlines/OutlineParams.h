#pragma once

#include "styles/Style.h"
#include "styles/StyleRegistry.h"

#include <glm/glm.hpp>

#include <vector>

namespace nprgl::styles {

// Parameters every outline style shares: one ink colour (commas separate NPRGL_CONFIG
// entries, so a colour is three numbers) and, per line class, a lightness that mixes the
// ink towards white (on a dark page: towards black) for lighter secondary lines.

// Appends ink_red, ink_green, ink_blue (default black).
void addInkParams(std::vector<ParamInfo>& params);
// Appends "<lineClass>_lightness" with help naming the class.
void addLightnessParam(std::vector<ParamInfo>& params, const char* lineClass, double def);
// The configured ink (for a light page: PageTone::ink gives the one for this frame's page).
glm::vec3 inkColour(const StyleContext& ctx, const char* style);

// A line class's configured ink and lightness; its colour depends on the frame's page.
struct InkClass {
    glm::vec3 ink{0.0f};
    float lightness = 0.0f;
    glm::vec3 on(const PageTone& page) const { return page.line(ink, lightness); }
};
InkClass inkClass(const StyleContext& ctx, const char* style, const char* lightnessParam);

} // namespace nprgl::styles
