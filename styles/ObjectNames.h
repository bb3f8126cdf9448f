#pragma once

// Names for nprgl's own textures, buffers, framebuffers, renderbuffers and queries.

#include "styles/GlFunctions.h"

namespace nprgl::styles {

// From a range of names programs do not reach, created by binding them (a compatibility
// context allows it). The driver's glGen* would hand out the names a program binds next
// without asking for them (old programs hard-code their texture names; a replay binds the
// names its capture recorded, which the driver gave out before nprgl made anything), and
// the two would share one object. Mesa's glGen* gives the name after the largest in use, so
// the program's own later names stay unique too.
class ObjectNames {
public:
    enum class Kind { Texture, Buffer, Framebuffer, Renderbuffer, Query };
    // n names not in use; the object is made when it is first bound (or begun, a query).
    static void reserve(const GlFunctions& gl, Kind kind, GLsizei n, GLuint* names);
    static constexpr GLuint kFirst = 0x4E500000u; // "NP"
};

} // namespace nprgl::styles
