// Writes fuzz_replay's seed inputs (the format is in fuzz_replay.cpp): hand-made call
// streams for the calls the replayer must check (client arrays and draws, buffers, display
// lists, images, batch references and blob arrays), and the first frames of capture files
// (the committed fixtures), their blob references turned into the target's tokens.
// Usage: make_replay_seeds DIR [CAPTURE...]

#include "capture/CaptureReader.h"
#include "stream/CallWriter.h"
#include "stream/Opcodes.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <cstdio>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

using namespace nprgl;

namespace {

constexpr size_t kMaxSeedBytes = 60000;
constexpr uint8_t kBlobToken[7] = {0xB1, 0x0B, 0xB1, 0x0B, 0xB1, 0x0B, 0xB1};

// One fuzz input being built.
class Seed {
public:
    explicit Seed(uint8_t size) { mBytes.push_back(size); }
    void section(bool blob, const void* data, size_t size)
    {
        size = std::min<size_t>(size, 0xFFFF);
        mBytes.push_back(blob ? 1 : 0);
        mBytes.push_back(uint8_t(size));
        mBytes.push_back(uint8_t(size >> 8));
        const auto* p = static_cast<const uint8_t*>(data);
        mBytes.insert(mBytes.end(), p, p + size);
    }
    size_t size() const { return mBytes.size(); }
    bool write(const std::string& path) const
    {
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(mBytes.data()), std::streamsize(mBytes.size()));
        return bool(out);
    }

private:
    std::vector<uint8_t> mBytes;
};

// Scalar-only calls: opcode and arguments.
template <typename... A> void call(CallWriter& w, uint16_t opcode, A... args)
{
    w.op(opcode);
    (w.put(args), ...);
}

// Calls with a pointer or an output argument have a payload even when it holds scalars only.
template <typename... A> void payloadCall(CallWriter& w, uint16_t opcode, A... args)
{
    w.op(opcode);
    size_t mark = w.beginPayload();
    (w.put(args), ...);
    w.endPayload(mark);
}

void arrayData(CallWriter& w, uint8_t slot, uint64_t offset, const void* data, size_t size)
{
    w.op(op::kArrayData);
    size_t mark = w.beginPayload();
    w.put(slot);
    w.put(offset);
    w.putBytes(data, size);
    w.endPayload(mark);
}

void blobToken(CallWriter& w, uint8_t index)
{
    for (uint8_t b : kBlobToken)
        w.put(b);
    w.put(index);
}

void frameEnd(CallWriter& w, uint64_t frame) { call(w, op::kFrameEnd, frame); }

const float kTriangle[] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};

void clientArrays(CallWriter& w)
{
    call(w, op::glEnableClientState, GLenum(GL_VERTEX_ARRAY));
    payloadCall(w, op::glVertexPointer, GLint(3), GLenum(GL_FLOAT), GLsizei(0), uint64_t(0x1000));
    arrayData(w, 0, 0, kTriangle, sizeof kTriangle);
    call(w, op::glDrawArrays, GLenum(GL_TRIANGLES), GLint(0), GLsizei(3));
    const uint16_t indices[] = {0, 1, 2};
    for (uint16_t opcode : {op::glDrawElements, op::glDrawRangeElements}) {
        w.op(opcode);
        size_t mark = w.beginPayload();
        w.put(GLenum(GL_TRIANGLES));
        if (opcode == op::glDrawRangeElements) w.put(GLuint(0)), w.put(GLuint(2));
        w.put(GLsizei(3));
        w.put(GLenum(GL_UNSIGNED_SHORT));
        w.put(uint8_t(1));
        w.putBytes(indices, sizeof indices);
        w.endPayload(mark);
    }
    const GLint firsts[] = {0, 1};
    const GLsizei counts[] = {3, 2};
    w.op(op::glMultiDrawArrays);
    size_t mark = w.beginPayload();
    w.put(GLenum(GL_TRIANGLES));
    w.put(GLsizei(2));
    w.putBytes(firsts, sizeof firsts);
    w.putBytes(counts, sizeof counts);
    w.endPayload(mark);
    call(w, op::glBegin, GLenum(GL_TRIANGLES));
    for (GLint i = 0; i < 3; ++i)
        call(w, op::glArrayElement, i);
    call(w, op::glEnd);
    call(w, op::glEnableClientState, GLenum(GL_COLOR_ARRAY));
    payloadCall(w, op::glColorPointer, GLint(4), GLenum(GL_UNSIGNED_BYTE), GLsizei(0), uint64_t(8));
    const uint8_t colours[12] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255};
    arrayData(w, 2, 0, colours, sizeof colours);
    call(w, op::glDrawArrays, GLenum(GL_TRIANGLES), GLint(0), GLsizei(3));
    call(w, op::glDisableClientState, GLenum(GL_COLOR_ARRAY));
}

void buffers(CallWriter& w)
{
    call(w, op::glBindBuffer, GLenum(GL_ARRAY_BUFFER), GLuint(1));
    w.op(op::glBufferData);
    size_t mark = w.beginPayload();
    w.put(GLenum(GL_ARRAY_BUFFER));
    w.put(GLsizeiptr(sizeof kTriangle));
    w.put(GLenum(GL_STATIC_DRAW));
    w.putBytes(kTriangle, sizeof kTriangle);
    w.endPayload(mark);
    call(w, op::glEnableClientState, GLenum(GL_VERTEX_ARRAY));
    payloadCall(w, op::glVertexPointer, GLint(3), GLenum(GL_FLOAT), GLsizei(0), uint64_t(0));
    call(w, op::glDrawArrays, GLenum(GL_TRIANGLES), GLint(0), GLsizei(3));
    const uint32_t indices[] = {0, 1, 2};
    call(w, op::glBindBuffer, GLenum(GL_ELEMENT_ARRAY_BUFFER), GLuint(2));
    w.op(op::glBufferData);
    mark = w.beginPayload();
    w.put(GLenum(GL_ELEMENT_ARRAY_BUFFER));
    w.put(GLsizeiptr(sizeof indices));
    w.put(GLenum(GL_STATIC_DRAW));
    w.putBytes(indices, sizeof indices);
    w.endPayload(mark);
    w.op(op::glDrawElements);
    mark = w.beginPayload();
    w.put(GLenum(GL_TRIANGLES));
    w.put(GLsizei(3));
    w.put(GLenum(GL_UNSIGNED_INT));
    w.put(uint8_t(2));
    w.put(uint64_t(0));
    w.endPayload(mark);
    call(w, op::glBindBuffer, GLenum(GL_ARRAY_BUFFER), GLuint(0));
    call(w, op::glBindBuffer, GLenum(GL_ELEMENT_ARRAY_BUFFER), GLuint(0));
}

void lists(CallWriter& w)
{
    call(w, op::glNewList, GLuint(1), GLenum(GL_COMPILE));
    call(w, op::glBegin, GLenum(GL_TRIANGLES));
    for (int i = 0; i < 3; ++i)
        call(w, op::glVertex3f, kTriangle[3 * i], kTriangle[3 * i + 1], kTriangle[3 * i + 2]);
    call(w, op::glEnd);
    call(w, op::glEndList);
    call(w, op::glNewList, GLuint(2), GLenum(GL_COMPILE_AND_EXECUTE));
    call(w, op::glCallList, GLuint(1));
    call(w, op::glCallList, GLuint(1));
    call(w, op::glEndList);
    call(w, op::glCallList, GLuint(2));
    call(w, op::glListBase, GLuint(1));
    const uint8_t names[] = {0, 1};
    w.op(op::glCallLists);
    size_t mark = w.beginPayload();
    w.put(GLsizei(2));
    w.put(GLenum(GL_UNSIGNED_BYTE));
    w.putBytes(names, sizeof names);
    w.endPayload(mark);
    // A list calling itself twice: 2^64 runs within the nesting limit, bounded by the
    // replayer's budget for the driver and by the compositor's tracker for itself.
    call(w, op::glNewList, GLuint(3), GLenum(GL_COMPILE));
    call(w, op::glCallList, GLuint(3));
    call(w, op::glCallList, GLuint(3));
    call(w, op::glEndList);
    call(w, op::glCallList, GLuint(3));
    call(w, op::glGenLists, GLsizei(2));
    call(w, op::glDeleteLists, GLuint(1), GLsizei(3));
}

void images(CallWriter& w)
{
    uint8_t texels[4 * 4 * 4];
    for (size_t i = 0; i < sizeof texels; ++i)
        texels[i] = uint8_t(i * 13);
    payloadCall(w, op::glGenTextures, GLsizei(1)); // the names are output: not recorded
    call(w, op::glBindTexture, GLenum(GL_TEXTURE_2D), GLuint(1));
    call(w, op::glPixelStorei, GLenum(GL_UNPACK_ALIGNMENT), GLint(1));
    w.op(op::glTexImage2D);
    size_t mark = w.beginPayload();
    for (GLint v : {GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0})
        w.put(v);
    w.put(GLenum(GL_RGBA));
    w.put(GLenum(GL_UNSIGNED_BYTE));
    w.put(uint8_t(1));
    w.putBytes(texels, sizeof texels);
    w.endPayload(mark);
    w.op(op::glDrawPixels);
    mark = w.beginPayload();
    w.put(GLsizei(2));
    w.put(GLsizei(2));
    w.put(GLenum(GL_RGBA));
    w.put(GLenum(GL_UNSIGNED_BYTE));
    w.put(uint8_t(1));
    w.putBytes(texels, 16);
    w.endPayload(mark);
    w.op(op::glBitmap);
    mark = w.beginPayload();
    w.put(GLsizei(8));
    w.put(GLsizei(2));
    for (GLfloat v : {0.0f, 0.0f, 8.0f, 0.0f})
        w.put(v);
    w.put(uint8_t(1));
    w.putBytes(texels, 2);
    w.endPayload(mark);
    call(w, op::glCopyTexImage2D, GLenum(GL_TEXTURE_2D), GLint(0), GLenum(GL_RGBA), GLint(0),
         GLint(0), GLsizei(8), GLsizei(8), GLint(0));
    call(w, op::glMapGrid2f, GLint(4), 0.0f, 1.0f, GLint(4), 0.0f, 1.0f);
    call(w, op::glEvalMesh2, GLenum(GL_FILL), GLint(0), GLint(4), GLint(0), GLint(4));
}

// Blob 0 holds a batch (glBegin..glEnd), blob 1 vertex data.
void blobs(CallWriter& w, Seed& seed)
{
    CallWriter batch;
    call(batch, op::glBegin, GLenum(GL_TRIANGLES));
    for (int i = 0; i < 3; ++i)
        call(batch, op::glVertex3f, kTriangle[3 * i], kTriangle[3 * i + 1], kTriangle[3 * i + 2]);
    call(batch, op::glEnd);
    seed.section(true, batch.data(), batch.size());
    seed.section(true, kTriangle, sizeof kTriangle);
    w.op(op::kBatchRef);
    blobToken(w, 0);
    w.put(uint64_t(batch.size()));
    call(w, op::glEnableClientState, GLenum(GL_VERTEX_ARRAY));
    payloadCall(w, op::glVertexPointer, GLint(3), GLenum(GL_FLOAT), GLsizei(0), uint64_t(0x1000));
    w.op(op::kArrayData);
    size_t mark = w.beginPayload();
    w.put(uint8_t(0));
    w.put(uint64_t(0));
    w.put(CallWriter::kBlobArray);
    blobToken(w, 1);
    w.put(uint64_t(sizeof kTriangle));
    w.endPayload(mark);
    call(w, op::glDrawArrays, GLenum(GL_TRIANGLES), GLint(0), GLsizei(3));
}

bool handMade(const std::string& dir)
{
    bool ok = true;
    int n = 0;
    for (auto build : {clientArrays, buffers, lists, images}) {
        Seed seed{uint8_t(n)};
        CallWriter w;
        build(w);
        frameEnd(w, 1);
        seed.section(false, w.data(), w.size());
        ok = seed.write(dir + "/made_" + std::to_string(n++)) && ok;
    }
    Seed seed(5);
    CallWriter w;
    blobs(w, seed);
    frameEnd(w, 1);
    seed.section(false, w.data(), w.size());
    return seed.write(dir + "/made_blobs") && ok;
}

// The first frames of a capture (and the blobs they use) that fit in a seed.
bool fromCapture(const std::string& path, const std::string& out)
{
    capture::CaptureReader reader;
    std::string error;
    if (!reader.open(path, error)) {
        std::fprintf(stderr, "make_replay_seeds: %s\n", error.c_str());
        return false;
    }
    Seed seed{5};
    std::vector<capture::BlobHash> used;
    std::vector<uint8_t> bytes;
    size_t budget = kMaxSeedBytes;
    for (const auto& blob : reader.blobs()) {
        if (blob.rawSize > budget / 2 || used.size() == 256) continue;
        if (!reader.readBlob(blob.hash, bytes, error)) return false;
        seed.section(true, bytes.data(), bytes.size());
        used.push_back(blob.hash);
        budget -= bytes.size();
    }
    for (size_t i = 0; i < reader.frames().size() && seed.size() < kMaxSeedBytes; ++i) {
        if (!reader.readFrame(i, bytes, error)) return false;
        // Blob references become tokens (a hash's 8 bytes elsewhere are vanishingly rare).
        for (size_t k = 0; k < used.size(); ++k) {
            for (size_t at = 0; at + 8 <= bytes.size(); ++at) {
                if (std::memcmp(bytes.data() + at, &used[k], 8) != 0) continue;
                std::memcpy(bytes.data() + at, kBlobToken, 7);
                bytes[at + 7] = uint8_t(k);
            }
        }
        // Cut to fit: the rest is the fuzzer's to make up.
        const size_t room = kMaxSeedBytes - std::min(kMaxSeedBytes, seed.size() + 3);
        if (room == 0) break;
        bytes.resize(std::min({bytes.size(), room, size_t(0xFFFF)}));
        seed.section(false, bytes.data(), bytes.size());
    }
    return seed.write(out);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: make_replay_seeds DIR [CAPTURE...]\n");
        return 2;
    }
    const std::string dir = argv[1];
    bool ok = handMade(dir);
    for (int i = 2; i < argc; ++i) {
        std::string name = argv[i];
        name = name.substr(name.find_last_of('/') + 1);
        ok = fromCapture(argv[i], dir + "/capture_" + name) && ok;
    }
    return ok ? 0 : 1;
}
