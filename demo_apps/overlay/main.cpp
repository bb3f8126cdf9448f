// demo_overlay: a lit 3D scene, then a 2D HUD drawn over it in an orthographic projection:
// a translucent panel, GL_LINES and glBitmap text in the demos' tiny bitmap font.

#include "BitmapFont.h"
#include "Demo.h"

#include <GL/gl.h>

#include <cmath>
#include <cstdio>
#include <string_view>

namespace {

class OverlayScene : public demo::Scene {
public:
    bool init(const demo::Options& options, std::string&) override
    {
        width_ = options.width;
        height_ = options.height;
        glViewport(0, 0, width_, height_);
        glClearColor(0.12f, 0.1f, 0.14f, 1.0f);
        glEnable(GL_NORMALIZE);
        glEnable(GL_LIGHT0);
        const float specular[] = {0.5f, 0.5f, 0.5f, 1.0f};
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
        glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 32.0f);
        return true;
    }

    void draw(int frame) override
    {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        drawScene(frame);
        drawOverlay(frame);
    }

private:
    void drawScene(int frame)
    {
        demo::setPerspective(45.0, static_cast<double>(width_) / height_, 1.0, 50.0);
        glLoadIdentity();
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        const float lightDirection[] = {0.5f, 0.7f, 1.0f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightDirection);
        glTranslatef(0.0f, -0.6f, -7.5f);
        glRotatef(30.0f, 1.0f, 0.0f, 0.0f);

        glPushMatrix();
        glRotatef(frame * 2.0f, 0.0f, 1.0f, 0.0f);
        glRotatef(90.0f, 1.0f, 0.0f, 0.0f);
        setColour(0.85f, 0.75f, 0.3f);
        demo::drawTorus(1.3f, 0.3f, 40, 20);
        glPopMatrix();

        const float colours[6][3] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f}, {0.2f, 0.4f, 0.9f},
                                     {0.9f, 0.5f, 0.1f}, {0.7f, 0.2f, 0.8f}, {0.2f, 0.8f, 0.8f}};
        for (int i = 0; i < 6; ++i) {
            glPushMatrix();
            glRotatef(-frame * 1.0f + i * 60.0f, 0.0f, 1.0f, 0.0f);
            glTranslatef(2.4f, 0.4f * std::sin(frame * 0.1f + i), 0.0f);
            setColour(colours[i][0], colours[i][1], colours[i][2]);
            demo::drawSphere(0.35f, 12, 16);
            glPopMatrix();
        }
    }

    void drawOverlay(int frame)
    {
        // Pixel coordinates with the origin at the bottom left.
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0.0, width_, 0.0, height_, -1.0, 1.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_LIGHTING);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

        const int left = 12;
        const int bottom = 12;
        const int right = width_ - 12;
        const int top = bottom + 64;
        glColor4f(0.0f, 0.0f, 0.0f, 0.55f);
        glBegin(GL_QUADS);
        glVertex2i(left, bottom);
        glVertex2i(right, bottom);
        glVertex2i(right, top);
        glVertex2i(left, top);
        glEnd();
        // Progress bar filling up every 100 frames.
        float progress = (frame % 100) / 100.0f;
        glColor4f(0.2f, 0.9f, 0.3f, 0.7f);
        glBegin(GL_QUADS);
        glVertex2f(left + 10.0f, bottom + 10.0f);
        glVertex2f(left + 10.0f + 170.0f * progress, bottom + 10.0f);
        glVertex2f(left + 10.0f + 170.0f * progress, bottom + 18.0f);
        glVertex2f(left + 10.0f, bottom + 18.0f);
        glEnd();
        glDisable(GL_BLEND);

        // Panel frame and a crosshair at the centre of the view, as GL_LINES.
        glColor3f(0.9f, 0.9f, 0.9f);
        float cx = width_ / 2.0f;
        float cy = height_ / 2.0f;
        const float frameLines[][4] = {
            {left + 0.5f, bottom + 0.5f, right - 0.5f, bottom + 0.5f},
            {right - 0.5f, bottom + 0.5f, right - 0.5f, top - 0.5f},
            {right - 0.5f, top - 0.5f, left + 0.5f, top - 0.5f},
            {left + 0.5f, top - 0.5f, left + 0.5f, bottom + 0.5f},
            {cx - 12.0f, cy + 0.5f, cx - 4.0f, cy + 0.5f},
            {cx + 4.0f, cy + 0.5f, cx + 12.0f, cy + 0.5f},
            {cx + 0.5f, cy - 12.0f, cx + 0.5f, cy - 4.0f},
            {cx + 0.5f, cy + 4.0f, cx + 0.5f, cy + 12.0f},
        };
        glBegin(GL_LINES);
        for (const auto& line : frameLines) {
            glVertex2f(line[0], line[1]);
            glVertex2f(line[2], line[3]);
        }
        glEnd();

        char frameText[32];
        std::snprintf(frameText, sizeof(frameText), "FRAME %04d", frame % 10000);
        glColor3f(1.0f, 1.0f, 0.4f);
        drawText(left + 10, bottom + 28, frameText);
        glColor3f(0.7f, 0.85f, 1.0f);
        drawText(12, height_ - 26, "OVERLAY DEMO");
    }

    void drawText(int x, int y, std::string_view text)
    {
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        // The raster colour is latched here from the current colour.
        glRasterPos2i(x, y);
        font_.draw(text);
    }

    static void setColour(float r, float g, float b)
    {
        const float colour[] = {r, g, b, 1.0f};
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, colour);
    }

    int width_ = 0;
    int height_ = 0;
    demo::BitmapFont font_;
};

} // namespace

int main(int argc, char** argv)
{
    OverlayScene scene;
    return demo::run(argc, argv, "overlay", scene);
}
