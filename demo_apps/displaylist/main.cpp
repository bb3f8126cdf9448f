// demo_displaylist: three gears compiled once into display lists (like glxgears); each frame
// only sets transforms and calls the lists.

#include "Demo.h"

#include <GL/gl.h>

#include <cmath>
#include <numbers>

namespace {

constexpr float pi = std::numbers::pi_v<float>;

// Offsets from the base returned by glGenLists.
enum ListOffset : GLubyte {
    stateList,
    plateList,
    axleList,
    gear1List,
    gear2List,
    gear3List,
    listCount
};

void setMaterial(float r, float g, float b)
{
    const float colour[] = {r, g, b, 1.0f};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
}

// A gear in the z = 0 plane centred on the origin, flat shaded. clockwiseFront: its front
// faces wound clockwise seen from outside, drawn under glFrontFace(GL_CW), as xscreensaver's
// involute gears set the front face per ring and face (the same picture).
void drawGear(float innerRadius, float outerRadius, float width, int teeth, float toothDepth,
              bool clockwiseFront)
{
    float r0 = innerRadius;
    float r1 = outerRadius - toothDepth / 2.0f;
    float r2 = outerRadius + toothDepth / 2.0f;
    float da = 2.0f * pi / teeth / 4.0f;
    float hw = width / 2.0f;

    glShadeModel(GL_FLAT);
    for (float side : {1.0f, -1.0f}) {
        const bool clockwise = clockwiseFront && side > 0;
        const bool reversed = (side < 0) != clockwise;
        const float z = side * hw;
        if (clockwise) glFrontFace(GL_CW);
        glNormal3f(0.0f, 0.0f, side);
        // Face between the hole and the tooth roots; the back face is wound the other way.
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= teeth; ++i) {
            float a = i * 2.0f * pi / teeth;
            if (!reversed) {
                glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
                glVertex3f(r1 * std::cos(a), r1 * std::sin(a), z);
                if (i < teeth) {
                    glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
                    glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), z);
                }
            } else {
                glVertex3f(r1 * std::cos(a), r1 * std::sin(a), z);
                glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
                if (i < teeth) {
                    glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), z);
                    glVertex3f(r0 * std::cos(a), r0 * std::sin(a), z);
                }
            }
        }
        glEnd();
        // Faces of the teeth.
        glBegin(GL_QUADS);
        for (int i = 0; i < teeth; ++i) {
            float a = i * 2.0f * pi / teeth;
            float p[4][2] = {{r1 * std::cos(a), r1 * std::sin(a)},
                             {r2 * std::cos(a + da), r2 * std::sin(a + da)},
                             {r2 * std::cos(a + 2 * da), r2 * std::sin(a + 2 * da)},
                             {r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da)}};
            for (int k = 0; k < 4; ++k) {
                int j = reversed ? 3 - k : k;
                glVertex3f(p[j][0], p[j][1], z);
            }
        }
        glEnd();
        if (clockwise) glFrontFace(GL_CCW);
    }

    // Outward faces of the teeth.
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i < teeth; ++i) {
        float a = i * 2.0f * pi / teeth;
        glVertex3f(r1 * std::cos(a), r1 * std::sin(a), hw);
        glVertex3f(r1 * std::cos(a), r1 * std::sin(a), -hw);
        float u = r2 * std::cos(a + da) - r1 * std::cos(a);
        float v = r2 * std::sin(a + da) - r1 * std::sin(a);
        float length = std::sqrt(u * u + v * v);
        glNormal3f(v / length, -u / length, 0.0f);
        glVertex3f(r2 * std::cos(a + da), r2 * std::sin(a + da), hw);
        glVertex3f(r2 * std::cos(a + da), r2 * std::sin(a + da), -hw);
        glNormal3f(std::cos(a), std::sin(a), 0.0f);
        glVertex3f(r2 * std::cos(a + 2 * da), r2 * std::sin(a + 2 * da), hw);
        glVertex3f(r2 * std::cos(a + 2 * da), r2 * std::sin(a + 2 * da), -hw);
        u = r1 * std::cos(a + 3 * da) - r2 * std::cos(a + 2 * da);
        v = r1 * std::sin(a + 3 * da) - r2 * std::sin(a + 2 * da);
        glNormal3f(v, -u, 0.0f);
        glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), hw);
        glVertex3f(r1 * std::cos(a + 3 * da), r1 * std::sin(a + 3 * da), -hw);
        glNormal3f(std::cos(a), std::sin(a), 0.0f);
    }
    glVertex3f(r1, 0.0f, hw);
    glVertex3f(r1, 0.0f, -hw);
    glEnd();
}

// A grey hexagonal axle through a gear's hole, sticking out on both sides.
void drawAxle(float radius, float length)
{
    setMaterial(0.6f, 0.6f, 0.62f);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 6; ++i) {
        float a = i * 2.0f * pi / 6.0f;
        float mid = a + pi / 6.0f;
        glNormal3f(std::cos(mid), std::sin(mid), 0.0f);
        glVertex3f(radius * std::cos(a), radius * std::sin(a), length / 2);
        glVertex3f(radius * std::cos(a), radius * std::sin(a), -length / 2);
    }
    glEnd();
    glNormal3f(0.0f, 0.0f, 1.0f);
    glBegin(GL_POLYGON);
    for (int i = 0; i < 6; ++i) {
        float a = i * 2.0f * pi / 6.0f;
        glVertex3f(radius * std::cos(a), radius * std::sin(a), length / 2);
    }
    glEnd();
}

// Corners of a quad 2.4 wide at (x, 0, -20) facing the eye, and their colours: red, green,
// white, blue, so the diagonal the driver cuts it along shows at its centre (red and white
// meet on v0-v2, green and blue on v1-v3).
const float kCornerColours[4][3] = {{1, 0, 0}, {0, 1, 0}, {1, 1, 1}, {0, 0, 1}};
void cornerQuad(float x, float corners[4][3])
{
    const float c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int i = 0; i < 4; ++i) {
        corners[i][0] = x + 1.2f * c[i][0];
        corners[i][1] = 1.2f * c[i][1];
        corners[i][2] = -20.0f;
    }
}

// The corner quad at x by glBegin/glEnd (drawn now, or compiled into the list being made).
void beginEndCornerQuad(float x)
{
    float corners[4][3];
    cornerQuad(x, corners);
    glBegin(GL_QUADS);
    for (int i = 0; i < 4; ++i) {
        glColor3fv(kCornerColours[i]);
        glVertex3fv(corners[i]);
    }
    glEnd();
}

class DisplayListScene : public demo::Scene {
public:
    std::vector<demo::ExtraOption> extraOptions() const override
    {
        return {{"shine", demo::ExtraOption::Kind::Flag,
                 "call the red gear's list a second time, adding light (GL_ONE, GL_ONE) over "
                 "the same vertices, as multi-pass programs draw a surface's layers"},
                {"shadow-list", demo::ExtraOption::Kind::Flag,
                 "a list darkens a corner of the plate (white, alpha 0.7, blended GL_ZERO, "
                 "GL_ONE_MINUS_SRC_ALPHA, set inside the list), called while blending by "
                 "alpha is on: a ball's shadow in a pool game"},
                {"glowing-plate", demo::ExtraOption::Kind::Flag,
                 "the plate (called with the state list by one glCallLists) is added to the "
                 "scene (GL_ONE, GL_ONE), as effects drawn from lists of lists are"},
                {"clockwise-fronts", demo::ExtraOption::Kind::Flag,
                 "the gears' front faces are wound clockwise and drawn under "
                 "glFrontFace(GL_CW) inside their lists, the rest counter-clockwise (the "
                 "same picture), as xscreensaver's involute gears turn the front face"},
                {"corner-quads", demo::ExtraOption::Kind::Flag,
                 "instead of the gears, three unlit GL_QUADS with a colour per corner, drawn "
                 "by glBegin/glEnd, glDrawElements and a display list (left to right): where "
                 "the driver cuts each into triangles shows at its centre"}};
    }

    bool init(const demo::Options& options, std::string& error) override
    {
        shine_ = options.has("shine");
        glowingPlate_ = options.has("glowing-plate");
        shadowList_ = options.has("shadow-list");
        clockwiseFronts_ = options.has("clockwise-fronts");
        cornerQuads_ = options.has("corner-quads");
        base_ = glGenLists(listCount);
        if (base_ == 0) {
            error = "glGenLists failed";
            return false;
        }
        glViewport(0, 0, options.width, options.height);
        // Keep the whole unit square in view whichever side is longer.
        double aspect = static_cast<double>(options.width) / options.height;
        double halfWidth = aspect >= 1.0 ? aspect : 1.0;
        double halfHeight = aspect >= 1.0 ? 1.0 : 1.0 / aspect;
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-halfWidth, halfWidth, -halfHeight, halfHeight, 5.0, 60.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();

        // The state list is also executed now, so the context is set up as it is compiled.
        glNewList(base_ + stateList, GL_COMPILE_AND_EXECUTE);
        const float lightPosition[] = {5.0f, 5.0f, 10.0f, 0.0f};
        glLightfv(GL_LIGHT0, GL_POSITION, lightPosition);
        glEnable(GL_CULL_FACE);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_NORMALIZE);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glEndList();

        if (shadowList_) {
            shadow_ = glGenLists(1);
            glNewList(shadow_, GL_COMPILE);
            glDisable(GL_LIGHTING);
            glBlendFunc(GL_ZERO, GL_ONE_MINUS_SRC_ALPHA);
            glColor4f(1.0f, 1.0f, 1.0f, 0.7f);
            glBegin(GL_QUADS);
            glVertex3f(2.5f, 3.0f, -1.9f);
            glVertex3f(6.5f, 3.0f, -1.9f);
            glVertex3f(6.5f, 7.0f, -1.9f);
            glVertex3f(2.5f, 7.0f, -1.9f);
            glEnd();
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glEnable(GL_LIGHTING);
            glEndList();
        }
        glNewList(base_ + plateList, GL_COMPILE);
        setMaterial(0.25f, 0.25f, 0.3f);
        glNormal3f(0.0f, 0.0f, 1.0f);
        glBegin(GL_QUADS);
        glVertex3f(-7.5f, -6.5f, -2.0f);
        glVertex3f(7.0f, -6.5f, -2.0f);
        glVertex3f(7.0f, 7.5f, -2.0f);
        glVertex3f(-7.5f, 7.5f, -2.0f);
        glEnd();
        glEndList();

        glNewList(base_ + axleList, GL_COMPILE);
        drawAxle(0.45f, 3.0f);
        glEndList();

        compileGear(gear1List, 0.8f, 0.1f, 0.0f, 1.0f, 4.0f, 1.0f, 20);
        compileGear(gear2List, 0.0f, 0.8f, 0.2f, 0.5f, 2.0f, 2.0f, 10);
        compileGear(gear3List, 0.2f, 0.2f, 1.0f, 1.3f, 2.0f, 0.5f, 10);
        if (cornerQuads_) {
            quadList_ = glGenLists(1);
            glNewList(quadList_, GL_COMPILE);
            beginEndCornerQuad(3.4f);
            glEndList();
        }
        return true;
    }

    void draw(int frame) override
    {
        float angle = frame * 2.0f;
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glLoadIdentity();
        if (cornerQuads_) {
            drawCornerQuads();
            return;
        }
        glTranslatef(0.0f, 0.0f, -40.0f);
        glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
        glRotatef(30.0f + frame * 0.25f, 0.0f, 1.0f, 0.0f);

        const GLubyte sceneLists[] = {stateList, plateList};
        glListBase(base_);
        if (glowingPlate_) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_ONE, GL_ONE);
        }
        glCallLists(2, GL_UNSIGNED_BYTE, sceneLists);
        if (glowingPlate_) glDisable(GL_BLEND);
        glListBase(0);
        if (shadow_) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            glCallList(shadow_);
            glDisable(GL_BLEND);
        }

        drawGearAt(gear1List, -3.0f, -2.0f, angle);
        if (shine_) {
            // Unlit added light, no depth writes, the same list at the same place.
            demo::beginShinePass();
            drawGearAt(gear1List, -3.0f, -2.0f, angle);
            demo::endShinePass();
        }
        drawGearAt(gear2List, 3.1f, -2.0f, -2.0f * angle - 9.0f);
        drawGearAt(gear3List, -3.1f, 4.2f, -2.0f * angle - 25.0f);
    }

    void shutdown() override
    {
        if (quadList_) glDeleteLists(quadList_, 1);
        glDeleteLists(base_, listCount);
        if (shadow_) glDeleteLists(shadow_, 1);
    }

private:
    void drawCornerQuads()
    {
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        beginEndCornerQuad(-3.4f);
        float corners[4][3];
        cornerQuad(0.0f, corners);
        const GLubyte order[4] = {0, 1, 2, 3};
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, corners);
        glColorPointer(3, GL_FLOAT, 0, kCornerColours);
        glDrawElements(GL_QUADS, 4, GL_UNSIGNED_BYTE, order);
        glDisableClientState(GL_COLOR_ARRAY);
        glDisableClientState(GL_VERTEX_ARRAY);
        glCallList(quadList_);
        glEnable(GL_CULL_FACE);
        glEnable(GL_LIGHTING);
    }

    void compileGear(GLuint offset, float r, float g, float b, float inner, float outer,
                     float width, int teeth)
    {
        glNewList(base_ + offset, GL_COMPILE);
        // Nested call: the axle list is shared by all gears.
        glCallList(base_ + axleList);
        setMaterial(r, g, b);
        drawGear(inner, outer, width, teeth, 0.7f, clockwiseFronts_);
        glEndList();
    }

    void drawGearAt(GLuint offset, float x, float y, float angle)
    {
        glPushMatrix();
        glTranslatef(x, y, 0.0f);
        glRotatef(angle, 0.0f, 0.0f, 1.0f);
        glCallList(base_ + offset);
        glPopMatrix();
    }

    GLuint base_ = 0;
    bool shine_ = false;
    bool glowingPlate_ = false;
    bool shadowList_ = false;
    bool clockwiseFronts_ = false;
    bool cornerQuads_ = false;
    GLuint shadow_ = 0;
    GLuint quadList_ = 0;
};

} // namespace

int main(int argc, char** argv)
{
    DisplayListScene scene;
    return demo::run(argc, argv, "displaylist", scene);
}
