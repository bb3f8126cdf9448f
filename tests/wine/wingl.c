/* A Windows legacy-GL program for the Wine tests: WGL context, immediate mode, a display list
 * and a texture, a fixed number of frames. Built with mingw-w64, run under wine. */
#include <windows.h>
#include <GL/gl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static LRESULT CALLBACK windowProc(HWND hwnd, UINT msg, WPARAM wp, LPARAM lp)
{
    if (msg == WM_CLOSE) {
        PostQuitMessage(0);
        return 0;
    }
    return DefWindowProcA(hwnd, msg, wp, lp);
}

/* A checkerboard, so a texture that went missing shows. */
static GLuint makeTexture(void)
{
    static unsigned char pixels[16 * 16 * 3];
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 16; ++x) {
            unsigned char* p = pixels + (y * 16 + x) * 3;
            int on = ((x / 4) + (y / 4)) % 2;
            p[0] = on ? 240 : 40;
            p[1] = on ? 200 : 90;
            p[2] = on ? 60 : 160;
        }
    }
    GLuint tex = 0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, pixels);
    return tex;
}

/* A lit cube, compiled once into a display list. */
static GLuint makeCubeList(void)
{
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0},
                                  {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    static const float v[6][4][3] = {
        {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
        {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}},
        {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
        {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}},
        {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
        {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}}};
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glColor3f(0.2f, 0.6f, 0.9f);
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; ++f) {
        glNormal3fv(n[f]);
        for (int i = 0; i < 4; ++i) glVertex3fv(v[f][i]);
    }
    glEnd();
    glEndList();
    return list;
}

static void drawFrame(GLuint cube, GLuint tex, int frame)
{
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -0.75, 0.75, 1.5, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -6.0f);

    /* The cube from the display list, lit. */
    static const float light[4] = {0.5f, 1.0f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    glPushMatrix();
    glTranslatef(-1.3f, 0.0f, 0.0f);
    glRotatef(25.0f + 7.0f * frame, 1.0f, 0.0f, 0.0f);
    glRotatef(35.0f + 11.0f * frame, 0.0f, 1.0f, 0.0f);
    glCallList(cube);
    glPopMatrix();
    glDisable(GL_LIGHTING);

    /* A textured quad in immediate mode. */
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPushMatrix();
    glTranslatef(1.4f, 0.0f, 0.0f);
    glRotatef(-30.0f + 5.0f * frame, 0.0f, 1.0f, 0.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex3f(-1, -1, 0);
    glTexCoord2f(1, 0); glVertex3f(1, -1, 0);
    glTexCoord2f(1, 1); glVertex3f(1, 1, 0);
    glTexCoord2f(0, 1); glVertex3f(-1, 1, 0);
    glEnd();
    glPopMatrix();
    glDisable(GL_TEXTURE_2D);

    /* A triangle in immediate mode with per-vertex colours. */
    glPushMatrix();
    glTranslatef(0.0f, -1.6f, 0.0f);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex3f(-0.6f, -0.4f, 0);
    glColor3f(0, 1, 0); glVertex3f(0.6f, -0.4f, 0);
    glColor3f(0, 0, 1); glVertex3f(0.0f, 0.5f, 0);
    glEnd();
    glPopMatrix();
}

int main(int argc, char** argv)
{
    int frames = 5;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
            frames = atoi(argv[++i]);
        } else {
            fprintf(stderr, "usage: wingl [--frames N]\n");
            return 2;
        }
    }
    if (frames < 1) frames = 1;

    HINSTANCE inst = GetModuleHandleA(NULL);
    WNDCLASSA wc;
    memset(&wc, 0, sizeof wc);
    wc.style = CS_OWNDC;
    wc.lpfnWndProc = windowProc;
    wc.hInstance = inst;
    wc.lpszClassName = "wingl";
    if (!RegisterClassA(&wc)) {
        fprintf(stderr, "wingl: RegisterClass failed\n");
        return 1;
    }
    /* A 320x240 client area. */
    RECT rect = {0, 0, 320, 240};
    const DWORD style = WS_OVERLAPPEDWINDOW | WS_CLIPSIBLINGS | WS_CLIPCHILDREN;
    AdjustWindowRect(&rect, style, FALSE);
    HWND hwnd = CreateWindowA("wingl", "wingl", style, 0, 0, rect.right - rect.left,
                              rect.bottom - rect.top, NULL, NULL, inst, NULL);
    if (!hwnd) {
        fprintf(stderr, "wingl: CreateWindow failed\n");
        return 1;
    }
    HDC dc = GetDC(hwnd);
    PIXELFORMATDESCRIPTOR pfd;
    memset(&pfd, 0, sizeof pfd);
    pfd.nSize = sizeof pfd;
    pfd.nVersion = 1;
    pfd.dwFlags = PFD_DRAW_TO_WINDOW | PFD_SUPPORT_OPENGL | PFD_DOUBLEBUFFER;
    pfd.iPixelType = PFD_TYPE_RGBA;
    pfd.cColorBits = 24;
    pfd.cDepthBits = 24;
    pfd.iLayerType = PFD_MAIN_PLANE;
    int format = ChoosePixelFormat(dc, &pfd);
    if (!format || !SetPixelFormat(dc, format, &pfd)) {
        fprintf(stderr, "wingl: no pixel format\n");
        return 1;
    }
    HGLRC rc = wglCreateContext(dc);
    if (!rc || !wglMakeCurrent(dc, rc)) {
        fprintf(stderr, "wingl: no OpenGL context\n");
        return 1;
    }
    ShowWindow(hwnd, SW_SHOW);
    UpdateWindow(hwnd);

    GLuint tex = makeTexture();
    GLuint cube = makeCubeList();
    glViewport(0, 0, 320, 240);
    for (int frame = 0; frame < frames; ++frame) {
        MSG msg;
        while (PeekMessageA(&msg, NULL, 0, 0, PM_REMOVE)) {
            TranslateMessage(&msg);
            DispatchMessageA(&msg);
        }
        drawFrame(cube, tex, frame);
        SwapBuffers(dc);
    }
    printf("wingl: drew %d frames (%s)\n", frames, (const char*)glGetString(GL_RENDERER));
    glDeleteLists(cube, 1);
    glDeleteTextures(1, &tex);
    wglMakeCurrent(NULL, NULL);
    wglDeleteContext(rc);
    ReleaseDC(hwnd, dc);
    DestroyWindow(hwnd);
    return 0;
}
