// Declares the GL 1.5 buffer functions; must precede every include that may pull in GL/gl.h.
#define GL_GLEXT_PROTOTYPES

#include "MeshDrawer.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cstddef>

namespace character {

void MeshDrawer::init(const SkinImage* skin)
{
    if (skin) {
        glGenTextures(1, &texture_);
        glBindTexture(GL_TEXTURE_2D, texture_);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, skin->width, skin->height, 0, GL_RGB,
                     GL_UNSIGNED_BYTE, skin->rgb.data());
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE); // lit and textured
        glEnable(GL_TEXTURE_2D);
    }
    if (mode_ == Mode::Immediate) return;
    if (mode_ == Mode::BufferObjects) glGenBuffers(2, buffers_);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    if (texture_) glEnableClientState(GL_TEXTURE_COORD_ARRAY);
}

void MeshDrawer::draw(const CharacterPose& pose)
{
    // With buffer objects the pointers are offsets into the buffers, refilled every frame.
    const char* base = reinterpret_cast<const char*>(pose.vertices.data());
    const char* indexBase = reinterpret_cast<const char*>(pose.indices.data());
    if (mode_ == Mode::BufferObjects) {
        glBindBuffer(GL_ARRAY_BUFFER, buffers_[0]);
        glBufferData(GL_ARRAY_BUFFER, pose.vertices.size() * sizeof(Vertex),
                     pose.vertices.data(), GL_STREAM_DRAW);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers_[1]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, pose.indices.size() * sizeof(uint32_t),
                     pose.indices.data(), GL_STREAM_DRAW);
        base = nullptr;
        indexBase = nullptr;
    }
    if (mode_ != Mode::Immediate) {
        glVertexPointer(3, GL_FLOAT, sizeof(Vertex), base + offsetof(Vertex, position));
        glNormalPointer(GL_FLOAT, sizeof(Vertex), base + offsetof(Vertex, normal));
        if (texture_) {
            glTexCoordPointer(2, GL_FLOAT, sizeof(Vertex), base + offsetof(Vertex, texcoord));
        }
    }
    for (const Part& part : pose.parts) {
        glPushMatrix();
        glMultMatrixf(part.matrix);
        if (mode_ == Mode::Immediate) {
            drawImmediate(pose, part);
        } else {
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(part.indexCount), GL_UNSIGNED_INT,
                           indexBase + part.firstIndex * sizeof(uint32_t));
        }
        glPopMatrix();
    }
}

void MeshDrawer::drawImmediate(const CharacterPose& pose, const Part& part)
{
    glBegin(GL_TRIANGLES);
    for (uint32_t i = part.firstIndex; i < part.firstIndex + part.indexCount; ++i) {
        const Vertex& v = pose.vertices[pose.indices[i]];
        glNormal3fv(v.normal);
        if (texture_) glTexCoord2fv(v.texcoord);
        glVertex3fv(v.position);
    }
    glEnd();
}

void MeshDrawer::shutdown()
{
    if (texture_) glDeleteTextures(1, &texture_);
    if (mode_ != Mode::BufferObjects) return;
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDeleteBuffers(2, buffers_);
}

} // namespace character
