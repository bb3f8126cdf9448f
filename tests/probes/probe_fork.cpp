// Programs that fork, exit inside a frame or leave with _exit, on OSMesa.
#include <GL/osmesa.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

struct Surface {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, nullptr);
    std::vector<unsigned char> pixels = std::vector<unsigned char>(32 * 32 * 4);
    bool makeCurrent() { return OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, 32, 32); }
};

int drawAndRead()
{
    glClearColor(0, 0, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 0);
    glVertex2f(-1, -1);
    glVertex2f(3, -1);
    glVertex2f(-1, 3);
    glEnd();
    glFinish();
    unsigned char px[4] = {};
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    return px[0] + px[1] + px[2];
}

} // namespace

int waitChild(pid_t pid)
{
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

int main(int argc, char** argv)
{
    const char* mode = argc > 1 ? argv[1] : "fork";
    if (std::strcmp(mode, "fork") == 0) {
        // A child that does its own GL (llvmpipe's threads do not survive a fork, so GL in a
        // child is only possible when the parent has not started any yet).
        std::fflush(stdout);
        pid_t pid = fork();
        if (pid == 0) {
            Surface child;
            if (!child.makeCurrent()) _exit(11);
            std::printf("child px=%d\n", drawAndRead());
            std::fflush(stdout);
            _exit(7);
        }
        std::printf("gl child status=%d\n", waitChild(pid));
    }
    Surface surface;
    if (!surface.makeCurrent()) return 10;
    std::printf("parent px=%d\n", drawAndRead());
    std::fflush(stdout);
    if (std::strcmp(mode, "fork") == 0) {
        // A child of a GL program that does other work and leaves.
        pid_t pid = fork();
        if (pid == 0) {
            std::printf("plain child\n");
            std::fflush(stdout);
            _exit(6);
        }
        std::printf("plain child status=%d\n", waitChild(pid));
        std::printf("parent again px=%d\nok\n", drawAndRead());
        return 0;
    }
    if (std::strcmp(mode, "exit-mid-frame") == 0) {
        glBegin(GL_TRIANGLES);
        glVertex2f(0, 0);
        std::printf("ok\n");
        std::exit(3);
    }
    std::printf("ok\n");
    std::fflush(stdout);
    _exit(5);
}
