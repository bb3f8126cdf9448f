#include "styles/StyleChain.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"

#include <algorithm>

namespace nprgl::styles {

bool StyleChain::init(const StyleSettings& settings, GlFunctions::GetProc getProc,
                      std::string& error)
{
    mSettings = settings;
    mContext.settings = &mSettings;
    std::string missing;
    if (!mContext.gl.load(getProc, missing)) {
        error = "the driver lacks " + missing;
        return false;
    }
    const GlFunctions& gl = mContext.gl;
    gl.GenVertexArrays(1, &mContext.vao);
    // Shading first, then the outline styles in the order named.
    std::vector<const StyleInfo*> order = mSettings.chain();
    std::stable_partition(order.begin(), order.end(), [](const StyleInfo* s) {
        return s->role == StyleRole::Shading;
    });
    for (const StyleInfo* info : order) {
        if (!info->create) continue;
        std::unique_ptr<Style> style = info->create();
        std::string why;
        if (!style || !style->init(mContext, why)) {
            NPRGL_ERROR("style %s cannot run here (%s); it is left out", info->name.c_str(),
                        why.c_str());
            if (style) style->shutdown(mContext);
            continue;
        }
        mHasShading = mHasShading || info->role == StyleRole::Shading;
        mStyles.push_back(std::move(style));
    }
    // Whatever the styles' set-up left in the error flag is theirs, not the program's.
    while (gl.GetError() != GL_NO_ERROR) {
    }
    if (mStyles.empty()) {
        error = "no style of '" + mSettings.chainName() + "' could start";
        return false;
    }
    return true;
}

void StyleChain::setBaseline(const Scene& scene)
{
    const GlFunctions& gl = mContext.gl;
    gl.BindVertexArray(mContext.vao);
    gl.UseProgram(0);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.Viewport(scene.viewport.x, scene.viewport.y, scene.viewport.z, scene.viewport.w);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.DepthMask(GL_TRUE);
    gl.Enable(GL_POLYGON_OFFSET_FILL);
    gl.PolygonOffset(-1.0f, -1.0f);
    for (GLenum cap : {GL_BLEND, GL_CULL_FACE, GL_STENCIL_TEST, GL_SCISSOR_TEST, GL_ALPHA_TEST,
                       GL_LIGHTING, GL_TEXTURE_2D, GL_FOG, GL_LINE_SMOOTH, GL_POLYGON_SMOOTH,
                       GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_COLOR_LOGIC_OP}) {
        gl.Disable(cap);
    }
    gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.LineWidth(1.0f);
    gl.PointSize(1.0f);
}

void StyleChain::render(const Scene& scene)
{
    for (const std::unique_ptr<Style>& style : mStyles) {
        setBaseline(scene);
        style->render(scene, mContext);
    }
    mContext.meshes.endFlush(mContext.gl);
}

void StyleChain::shutdown()
{
    for (const std::unique_ptr<Style>& style : mStyles) style->shutdown(mContext);
    mStyles.clear();
    if (mContext.gl.DeleteVertexArrays) {
        mContext.meshes.destroy(mContext.gl);
        mContext.gl.DeleteVertexArrays(1, &mContext.vao);
    }
    mContext.vao = 0;
}

} // namespace nprgl::styles
