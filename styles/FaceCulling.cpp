#include "styles/FaceCulling.h"

#include "styles/shading/ShadingCommon.h"

namespace nprgl::styles {

bool FaceCulling::begin(const GlFunctions& gl, const SceneObject& object)
{
    if (object.culled == 0) return true;
    if (object.culled == GL_FRONT_AND_BACK) return false;
    gl.Enable(GL_CULL_FACE);
    gl.FrontFace(GL_CCW);
    gl.CullFace(object.culled == GL_CW ? GL_BACK : GL_FRONT);
    return true;
}

void FaceCulling::end(const GlFunctions& gl, const SceneObject& object)
{
    if (object.culled == GL_CW || object.culled == GL_CCW) gl.Disable(GL_CULL_FACE);
}

GLenum FaceCulling::shownWinding(const SceneObject& object)
{
    if (object.culled == GL_CCW) return GL_CW;
    if (object.culled == GL_CW || !object.mesh) return GL_CCW;
    // The program culls nothing: its normals say which side is the outside (a mirroring
    // modelview or projection turns the window-space winding around).
    return ShadingCommon::normalsFollowCcw(*object.mesh) != object.mirrored() ? GL_CCW : GL_CW;
}

} // namespace nprgl::styles
