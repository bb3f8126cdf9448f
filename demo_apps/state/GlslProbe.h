// GlslProbe: demo_state's GL 2.0 program of its own, and what GL answers about it.
#pragma once

// Declares the GL 2.0 functions; must precede every include that may pull in GL/gl.h.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES
#endif

#include <GL/gl.h>
#include <GL/glext.h>

#include <string>
#include <vector>

// A GLSL program as a GL 2.x program brings one: a vertex shader on the fixed-function inputs
// (ftransform, gl_Normal, gl_Color) with a generic attribute and uniforms of its own, a
// fragment shader, and a shader that does not compile. Everything GL says about them is what
// an interposer must never change: compile and link results, logs, locations, the active
// uniforms and attributes, uniform values.
class GlslProbe {
public:
    // Compiles and links; false with why when GL 2.0 refuses what it must take.
    bool init(std::string& error);
    // Draws a quad with the program (a draw an interposer leaves as it is) and sets the
    // uniforms to values of this frame.
    void draw(int frame);
    void shutdown();

    // The queries, asked now: each a name and the values GL gives.
    struct Answer {
        std::string name;
        std::vector<double> values;
    };
    std::vector<Answer> ask() const;
    // What they must answer after draw(frame): what they answered at init, and the uniform
    // values that frame set.
    std::vector<Answer> expected() const;
    // "glsl: ..." for the report: the answers at init, to compare with a native run's.
    std::string summary() const;

private:
    GLuint mVertex = 0;
    GLuint mFragment = 0;
    GLuint mBroken = 0;
    GLuint mProgram = 0;
    GLint mTint = -1;
    GLint mScale = -1;
    GLint mWeight = -1;
    int mFrame = 0;
    std::vector<Answer> mAtInit;
};
