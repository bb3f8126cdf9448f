#pragma once

// ProbeCube: the lit, turning cube the configuration and hotkey probes draw in immediate mode.

#include <GL/gl.h>

namespace nprgl::probes {

// One frame: clear, a perspective view of a lit orange cube turned by `frame` degrees.
inline void drawCube(int frame)
{
    glClearColor(0.3f, 0.3f, 0.35f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1, 1, -1, 1, 1.5, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const float light[4] = {0.4f, 0.6f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glTranslatef(0, 0, -4);
    glRotatef(30.0f + float(frame), 1, 1, 0);
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}};
    glColor3f(0.8f, 0.5f, 0.2f);
    glBegin(GL_QUADS);
    for (const auto& f : n) {
        // Two axes across the face, so the corners go round it.
        const float u[3] = {f[1] != 0 || f[2] != 0 ? 1.0f : 0.0f, f[0] != 0 ? 1.0f : 0.0f, 0};
        const float v[3] = {f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2],
                            f[0] * u[1] - f[1] * u[0]};
        glNormal3fv(f);
        const float s[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : s) {
            glVertex3f(f[0] + c[0] * u[0] + c[1] * v[0], f[1] + c[0] * u[1] + c[1] * v[1],
                       f[2] + c[0] * u[2] + c[1] * v[2]);
        }
    }
    glEnd();
}

} // namespace nprgl::probes
