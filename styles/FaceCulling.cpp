#include "styles/FaceCulling.h"

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
    return object.culled == GL_CCW ? GL_CW : GL_CCW;
}

} // namespace nprgl::styles
