// Programs that fork, exec or spawn other GL programs, exit inside a frame or leave with _exit,
// on OSMesa.
#include <GL/osmesa.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace {

struct Surface {
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, nullptr);
    std::vector<unsigned char> pixels = std::vector<unsigned char>(32 * 32 * 4);
    bool makeCurrent() { return OSMesaMakeCurrent(ctx, pixels.data(), GL_UNSIGNED_BYTE, 32, 32); }
};

// One frame (OSMesa frames end at glFinish): a triangle over a cleared background.
int drawAndRead(float clearRed = 0, float clearBlue = 1, float triGreen = 1)
{
    glClearColor(clearRed, 0, clearBlue, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(1 - clearRed, triGreen, 0);
    glVertex2f(-1, -1);
    glVertex2f(3, -1);
    glVertex2f(-1, 3);
    glEnd();
    glFinish();
    unsigned char px[4] = {};
    glReadPixels(1, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    return px[0] + px[1] + px[2];
}

// The parent clears to blue under a yellow triangle, a spawned child to red under a green one,
// so a capture shows whose calls it holds.
int drawParentFrame() { return drawAndRead(0, 1, 1); }
int drawChildFrame() { return drawAndRead(1, 0, 1); }

constexpr int kChildFrames = 3;

void sendByte(int fd)
{
    char c = 1;
    while (write(fd, &c, 1) < 0) {
    }
}

bool receiveByte(int fd)
{
    char c = 0;
    return fd < 0 || read(fd, &c, 1) == 1;
}

// The spawned program: its frames alternate with the parent's through two pipes (no fds: it
// runs alone, as under system()).
int runChild(int fromParent, int toParent)
{
    Surface surface;
    if (!surface.makeCurrent()) return 11;
    std::printf("child pid=%d\n", int(getpid()));
    for (int frame = 0; frame < kChildFrames; ++frame) {
        std::printf("child frame px=%d\n", drawChildFrame());
        std::fflush(stdout);
        if (toParent >= 0) sendByte(toParent);
        if (!receiveByte(fromParent)) return 12;
    }
    return 0;
}

int waitChild(pid_t pid)
{
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Draws a frame, starts another GL program (this one in mode "child") the way mode asks, draws
// a frame after each of the child's, waits for it and draws once more: five parent frames.
int runLauncher(const char* self, const std::string& mode)
{
    Surface surface;
    if (!surface.makeCurrent()) return 10;
    std::printf("parent px=%d\n", drawParentFrame());
    std::fflush(stdout);
    int toChild[2], toParent[2];
    if (pipe(toChild) != 0 || pipe(toParent) != 0) return 13;
    std::string readFd = std::to_string(toChild[0]), writeFd = std::to_string(toParent[1]);
    std::vector<char*> argv = {const_cast<char*>(self), const_cast<char*>("child"),
                               readFd.data(), writeFd.data(), nullptr};
    pid_t pid = -1;
    int status = -1;
    if (mode == "exec") {
        pid = fork();
        if (pid == 0) {
            execv("/proc/self/exe", argv.data());
            _exit(127);
        }
    } else if (mode == "spawn") {
        if (posix_spawn(&pid, "/proc/self/exe", nullptr, nullptr, argv.data(), environ) != 0)
            return 14;
    } else {
        // system() blocks: no alternation, the child draws its frames alone.
        std::string cmd = std::string("'") + self + "' child -1 -1";
        int rc = std::system(cmd.c_str());
        status = WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
    }
    close(toChild[0]);
    close(toParent[1]);
    for (int frame = 0; frame < kChildFrames; ++frame) {
        if (pid > 0 && !receiveByte(toParent[0])) return 15;
        drawParentFrame();
        if (pid > 0) sendByte(toChild[1]);
    }
    if (pid > 0) status = waitChild(pid);
    std::printf("child status=%d\n", status);
    std::printf("parent again px=%d\nok\n", drawParentFrame());
    return 0;
}

} // namespace

int main(int argc, char** argv)
{
    const char* mode = argc > 1 ? argv[1] : "fork";
    if (std::strcmp(mode, "child") == 0) {
        return runChild(argc > 2 ? std::atoi(argv[2]) : -1, argc > 3 ? std::atoi(argv[3]) : -1);
    }
    if (std::strcmp(mode, "exec") == 0 || std::strcmp(mode, "spawn") == 0 ||
        std::strcmp(mode, "system") == 0) {
        return runLauncher(argv[0], mode);
    }
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
