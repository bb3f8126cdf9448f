// A small program on a windowing toolkit, as people write them: freeglut (PROBE_GLUT), SDL2
// (PROBE_SDL2) or GLFW (PROBE_GLFW) opens a double-buffered window and draws a lit, turning
// cube in immediate mode, then exits on its own.
//   --frames N   frames to draw (default 5)
//   --empty      draws the background only
//   --save FILE  writes the last frame's RGBA bytes (bottom row first), read before the swap
// Prints "toolkit checksum C covered N error E" for the last frame.
#if defined(PROBE_GLUT)
#include <GL/freeglut.h>
#elif defined(PROBE_SDL2)
#include <SDL2/SDL.h>
#elif defined(PROBE_GLFW)
#include <GLFW/glfw3.h>
#else
#error "define PROBE_GLUT, PROBE_SDL2 or PROBE_GLFW"
#endif
#include <GL/gl.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace {

constexpr int kWidth = 200, kHeight = 150;
constexpr uint8_t kClear[3] = {30, 30, 45};

int gFrames = 5;
int gFrame = 0;
bool gEmpty = false;
const char* gSave = nullptr;

void drawCube()
{
    static const float kNormals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0},
                                         {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    glBegin(GL_QUADS);
    for (const auto& n : kNormals) {
        // The face's corners: n plus two perpendicular unit vectors, in counter-clockwise order.
        const float u[3] = {n[1] != 0 || n[2] != 0 ? 1.0f : 0.0f, n[0] != 0 ? 1.0f : 0.0f, 0};
        float v[3] = {n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2],
                      n[0] * u[1] - n[1] * u[0]};
        glNormal3fv(n);
        const float signs[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
        for (const auto& s : signs) {
            glVertex3f(0.5f * (n[0] + s[0] * u[0] + s[1] * v[0]),
                       0.5f * (n[1] + s[0] * u[1] + s[1] * v[1]),
                       0.5f * (n[2] + s[0] * u[2] + s[1] * v[2]));
        }
    }
    glEnd();
}

void drawFrame()
{
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(kClear[0] / 255.0f, kClear[1] / 255.0f, kClear[2] / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.4, 0.4, -0.3, 0.3, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    if (gEmpty) return;
    const GLfloat light[4] = {0.4f, 0.7f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glTranslatef(0, 0, -3.0f);
    glRotatef(30.0f + 15.0f * float(gFrame), 0.5f, 1.0f, 0.2f);
    glColor3f(0.9f, 0.5f, 0.2f);
    drawCube();
    glDisable(GL_LIGHTING);
    glDisable(GL_COLOR_MATERIAL);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
}

// The last frame's checksum and coverage, read from the back buffer before the swap.
void report()
{
    std::vector<uint8_t> pixels(size_t(kWidth) * kHeight * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
    uint64_t sum = 0;
    int covered = 0;
    for (size_t i = 0; i < pixels.size(); i += 4) {
        for (int c = 0; c < 3; ++c) sum = sum * 31 + pixels[i + size_t(c)];
        covered += pixels[i] != kClear[0] || pixels[i + 1] != kClear[1] ||
                   pixels[i + 2] != kClear[2];
    }
    if (gSave) {
        if (FILE* f = std::fopen(gSave, "wb")) {
            std::fwrite(pixels.data(), 1, pixels.size(), f);
            std::fclose(f);
        }
    }
    std::printf("toolkit checksum %016llx covered %d error 0x%x\n",
                static_cast<unsigned long long>(sum), covered, glGetError());
    std::fflush(stdout);
}

// Draws one frame; true when it was the last.
bool frame()
{
    drawFrame();
    const bool last = gFrame + 1 >= gFrames;
    if (last) report();
    return last;
}

#if defined(PROBE_GLUT)
void display()
{
    const bool last = frame();
    glutSwapBuffers();
    ++gFrame;
    if (last) glutLeaveMainLoop();
}
#endif

} // namespace

int main(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--frames") == 0 && i + 1 < argc) gFrames = std::atoi(argv[++i]);
        if (std::strcmp(argv[i], "--empty") == 0) gEmpty = true;
        if (std::strcmp(argv[i], "--save") == 0 && i + 1 < argc) gSave = argv[++i];
    }
#if defined(PROBE_GLUT)
    int glutArgc = 1;
    glutInit(&glutArgc, argv);
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowSize(kWidth, kHeight);
    glutCreateWindow("probe_glut");
    glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
    glutDisplayFunc(display);
    glutIdleFunc(glutPostRedisplay);
    glutMainLoop();
#elif defined(PROBE_SDL2)
    if (SDL_Init(SDL_INIT_VIDEO) != 0) {
        std::fprintf(stderr, "probe_sdl2: %s\n", SDL_GetError());
        return 2;
    }
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    SDL_GL_SetAttribute(SDL_GL_DEPTH_SIZE, 24);
    SDL_Window* window = SDL_CreateWindow("probe_sdl2", SDL_WINDOWPOS_UNDEFINED,
                                          SDL_WINDOWPOS_UNDEFINED, kWidth, kHeight,
                                          SDL_WINDOW_OPENGL);
    SDL_GLContext context = window ? SDL_GL_CreateContext(window) : nullptr;
    if (!context) {
        std::fprintf(stderr, "probe_sdl2: %s\n", SDL_GetError());
        return 2;
    }
    for (bool last = false; !last; ++gFrame) {
        SDL_Event event;
        while (SDL_PollEvent(&event)) {
        }
        last = frame();
        SDL_GL_SwapWindow(window);
    }
    SDL_GL_DeleteContext(context);
    SDL_DestroyWindow(window);
    SDL_Quit();
#else
    if (!glfwInit()) {
        std::fprintf(stderr, "probe_glfw: glfwInit failed\n");
        return 2;
    }
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
    GLFWwindow* window = glfwCreateWindow(kWidth, kHeight, "probe_glfw", nullptr, nullptr);
    if (!window) {
        std::fprintf(stderr, "probe_glfw: no window\n");
        glfwTerminate();
        return 2;
    }
    glfwMakeContextCurrent(window);
    for (bool last = false; !last; ++gFrame) {
        glfwPollEvents();
        last = frame();
        glfwSwapBuffers(window);
    }
    glfwDestroyWindow(window);
    glfwTerminate();
#endif
    return 0;
}
