#include "styles/outlines/OutlineParams.h"

#include <string>

namespace nprgl::styles {

void addInkParams(std::vector<ParamInfo>& params)
{
    params.push_back(ParamInfo::number("ink_red", "red of the line colour (ink)", 0.0, 0.0, 1.0));
    params.push_back(
        ParamInfo::number("ink_green", "green of the line colour (ink)", 0.0, 0.0, 1.0));
    params.push_back(
        ParamInfo::number("ink_blue", "blue of the line colour (ink)", 0.0, 0.0, 1.0));
}

void addLightnessParam(std::vector<ParamInfo>& params, const char* lineClass, double def)
{
    params.push_back(ParamInfo::number(
        std::string(lineClass) + "_lightness",
        std::string(lineClass) + " lines: 0 draws them in the ink colour, 1 in white, between: "
                                 "a lighter grey of the ink",
        def, 0.0, 1.0));
}

glm::vec3 inkColour(const StyleContext& ctx, const char* style)
{
    return {float(ctx.param(style, "ink_red")), float(ctx.param(style, "ink_green")),
            float(ctx.param(style, "ink_blue"))};
}

InkClass inkClass(const StyleContext& ctx, const char* style, const char* lightnessParam)
{
    return {inkColour(ctx, style), float(ctx.param(style, lightnessParam))};
}

} // namespace nprgl::styles
