// GL calls made with no current context: under nprgl they must behave exactly as natively.
#include <GL/gl.h>
#include <GL/glx.h>
#include <cstdio>

int main()
{
    std::printf("version=%s\n", glGetString(GL_VERSION) ? "set" : "null");
    glBegin(GL_TRIANGLES);
    glVertex3f(0, 0, 0);
    glEnd();
    glClear(GL_COLOR_BUFFER_BIT);
    std::printf("error=0x%x\n", glGetError());
    std::printf("current=%s\n", glXGetCurrentContext() ? "set" : "null");
    auto proc = glXGetProcAddressARB(reinterpret_cast<const GLubyte*>("glVertex3f"));
    std::printf("proc=%s\n", proc ? "set" : "null");
    return 0;
}
