#pragma once

// Names for nprgl's own textures, buffers, framebuffers, renderbuffers and queries.

#include "styles/GlFunctions.h"

namespace nprgl::styles {

// Counted down from the top of the name space, and made by binding them (a compatibility
// context allows it). The driver's glGen* would hand out the names a program binds next
// without asking for them (old programs hard-code their texture names; a replay binds the
// names its capture recorded, which the driver gave out before nprgl made anything), and the
// two would share one object. At the top they stay out of the program's way: Mesa's glGen*
// gives the name after the largest in use, or, where that would pass the top, the lowest
// free ones (as a program's names run natively: 1, 2, 3...).
class ObjectNames {
public:
    enum class Kind { Texture, Buffer, Framebuffer, Renderbuffer, Query };
    // n names not in use; the object is made when it is first bound (or begun, a query).
    static void reserve(const GlFunctions& gl, Kind kind, GLsizei n, GLuint* names);
    static constexpr GLuint kFirst = 0xFFFFFFFEu; // counting down
    static constexpr GLuint kLast = 0x80000000u;  // then from kFirst again
};

} // namespace nprgl::styles
