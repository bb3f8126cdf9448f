#include "reconstruct/MeshExport.h"

#include <cctype>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/System/omstream.hh>

namespace nprgl::reconstruct {

namespace {

struct Transform {
    glm::mat4 position;
    glm::mat3 normal;

    explicit Transform(const glm::mat4& m)
        : position(m), normal(glm::transpose(glm::inverse(glm::mat3(m))))
    {
    }

    glm::vec3 point(const glm::vec3& p) const
    {
        const glm::vec4 q = position * glm::vec4(p, 1.0f);
        return q.w != 0.0f && q.w != 1.0f ? glm::vec3(q) / q.w : glm::vec3(q);
    }

    glm::vec3 direction(const glm::vec3& n) const
    {
        const glm::vec3 d = normal * n;
        const float len = glm::length(d);
        return len > 0.0f ? d / len : d;
    }
};

std::string lowerExtension(const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
    std::string ext = path.substr(dot);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

// Text output through one buffer; shortest round-trip float formatting.
class ObjWriter {
public:
    explicit ObjWriter(std::FILE* file) : mFile(file) { mBuffer.reserve(kFlush + 256); }

    void text(const char* s) { mBuffer.append(s); }
    void number(float v)
    {
        char tmp[32];
        const auto r = std::to_chars(tmp, tmp + sizeof(tmp), v);
        mBuffer.append(tmp, r.ptr);
    }
    void number(uint64_t v)
    {
        char tmp[24];
        const auto r = std::to_chars(tmp, tmp + sizeof(tmp), v);
        mBuffer.append(tmp, r.ptr);
    }
    void line(const char* tag, float a, float b)
    {
        text(tag);
        number(a);
        text(" ");
        number(b);
        endLine();
    }
    void line(const char* tag, const glm::vec3& v)
    {
        text(tag);
        number(v.x);
        text(" ");
        number(v.y);
        text(" ");
        number(v.z);
        endLine();
    }
    void endLine()
    {
        mBuffer.push_back('\n');
        if (mBuffer.size() >= kFlush) flush();
    }
    bool flush()
    {
        if (!mBuffer.empty() && std::fwrite(mBuffer.data(), 1, mBuffer.size(), mFile) !=
                                    mBuffer.size())
            mFailed = true;
        mBuffer.clear();
        return !mFailed;
    }

private:
    static constexpr size_t kFlush = size_t(1) << 16;
    std::FILE* mFile;
    std::string mBuffer;
    bool mFailed = false;
};

bool hasTexcoords(const ObjectMesh& object)
{
    for (uint32_t c : object.faceCorners) {
        if (object.sourceVertices[c].texcoord != glm::vec2(0.0f)) return true;
    }
    return false;
}

bool writeObj(const std::string& path, const std::vector<ExportObject>& objects,
              std::string& error)
{
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) {
        error = "cannot open " + path + ": " + std::strerror(errno);
        return false;
    }
    ObjWriter out(file);
    out.text("# nprgl reconstructed meshes");
    out.endLine();
    // OBJ indices are 1-based and global to the file.
    uint64_t vertexBase = 1, texcoordBase = 1, normalBase = 1;
    for (size_t i = 0; i < objects.size(); ++i) {
        if (!objects[i].mesh) continue;
        const ObjectMesh& object = *objects[i].mesh;
        const Transform transform(objects[i].transform);
        out.text("g object_");
        out.number(uint64_t(i));
        out.endLine();
        for (uint32_t v = 0; v < object.vertexCount(); ++v)
            out.line("v ", transform.point(object.position(v)));
        const bool texcoords = hasTexcoords(object);
        const uint32_t faces = object.faceCount();
        for (uint32_t f = 0; f < faces && texcoords; ++f) {
            for (int k = 0; k < 3; ++k) {
                const glm::vec2& t = object.corner(f, k).texcoord;
                out.line("vt ", t.x, t.y);
            }
        }
        for (uint32_t f = 0; f < faces; ++f) {
            for (int k = 0; k < 3; ++k) {
                const Vertex& corner = object.corner(f, k);
                const glm::vec3 n = corner.hasNormal
                                        ? corner.normal
                                        : object.vertexNormal(object.faceVertices[3 * f + k]);
                out.line("vn ", transform.direction(n));
            }
        }
        for (uint32_t f = 0; f < faces; ++f) {
            out.text("f");
            for (int k = 0; k < 3; ++k) {
                const uint64_t corner = uint64_t(3) * f + k;
                out.text(" ");
                out.number(vertexBase + object.faceVertices[corner]);
                out.text("/");
                if (texcoords) out.number(texcoordBase + corner);
                out.text("/");
                out.number(normalBase + corner);
            }
            out.endLine();
        }
        vertexBase += object.vertexCount();
        texcoordBase += texcoords ? uint64_t(3) * faces : 0;
        normalBase += uint64_t(3) * faces;
    }
    const bool written = out.flush();
    const bool closed = std::fclose(file) == 0;
    if (!written || !closed) {
        error = "cannot write " + path + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

// OpenMesh logs to std::clog/cerr from its writers; the host program's stderr is not ours.
class QuietOpenMesh {
public:
    QuietOpenMesh() : mLog(omlog().is_enabled()), mErr(omerr().is_enabled())
    {
        omlog().disable();
        omerr().disable();
    }
    ~QuietOpenMesh()
    {
        if (mLog) omlog().enable();
        if (mErr) omerr().enable();
    }

private:
    bool mLog;
    bool mErr;
};

bool writeWithOpenMesh(const std::string& path, const std::vector<ExportObject>& objects,
                       std::string& error)
{
    Mesh merged;
    for (const ExportObject& item : objects) {
        if (!item.mesh) continue;
        const ObjectMesh& object = *item.mesh;
        const Transform transform(item.transform);
        const int base = int(merged.n_vertices());
        for (uint32_t v = 0; v < object.vertexCount(); ++v) {
            const glm::vec3 p = transform.point(object.position(v));
            const glm::vec3 n = transform.direction(object.vertexNormal(v));
            const OpenMesh::VertexHandle vh = merged.add_vertex(Mesh::Point(p.x, p.y, p.z));
            merged.set_normal(vh, Mesh::Normal(n.x, n.y, n.z));
        }
        // Same faces in the same order on the same vertices: OpenMesh accepts them again.
        for (uint32_t f = 0; f < object.faceCount(); ++f) {
            const uint32_t* fv = &object.faceVertices[3 * size_t(f)];
            merged.add_face(OpenMesh::VertexHandle(base + int(fv[0])),
                            OpenMesh::VertexHandle(base + int(fv[1])),
                            OpenMesh::VertexHandle(base + int(fv[2])));
        }
    }
    QuietOpenMesh quiet;
    if (!OpenMesh::IO::write_mesh(merged, path, OpenMesh::IO::Options::VertexNormal)) {
        error = "OpenMesh could not write " + path;
        return false;
    }
    return true;
}

} // namespace

bool exportMeshes(const std::string& path, const std::vector<ExportObject>& objects,
                  std::string& error) noexcept
{
    try {
        const std::string ext = lowerExtension(path);
        if (ext == ".obj") return writeObj(path, objects, error);
        if (ext == ".ply" || ext == ".off") return writeWithOpenMesh(path, objects, error);
        error = "unknown mesh format '" + ext + "' of " + path + " (use .obj, .ply or .off)";
        return false;
    } catch (const std::exception& e) {
        error = std::string("mesh export failed: ") + e.what();
    } catch (...) {
        error = "mesh export failed";
    }
    return false;
}

} // namespace nprgl::reconstruct
