#include "stream/CallPrinter.h"
#include "stream/CallReader.h"
#include "stream/CallWriter.h"
#include "stream/GlSizes.h"
#include "stream/Opcodes.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace nprgl;

namespace {

// Encodes calls as the generated recorder does (same layout), for the decoder to read;
// boundaries, if given, receives the offset at which each call ends.
std::vector<uint8_t> sampleFrame(std::vector<size_t>* boundaries = nullptr)
{
    CallWriter w;
    auto ended = [&] {
        if (boundaries) boundaries->push_back(w.size());
    };
    w.op(op::glBegin);
    w.put<GLenum>(GL_TRIANGLES);
    ended();
    for (int i = 0; i < 3; ++i) {
        w.op(op::glVertex3f);
        w.put<GLfloat>(float(i));
        w.put<GLfloat>(0.5f);
        w.put<GLfloat>(-1.0f);
        ended();
    }
    w.op(op::glEnd);
    ended();
    w.op(op::glLightfv);
    size_t mark = w.beginPayload();
    w.put<GLenum>(GL_LIGHT0);
    w.put<GLenum>(GL_POSITION);
    const float position[4] = {1, 2, 3, 0};
    w.putBytes(position, sizeof position);
    w.endPayload(mark);
    ended();
    w.op(op::kFrameEnd);
    w.put<uint64_t>(7);
    ended();
    return std::vector<uint8_t>(w.data(), w.data() + w.size());
}

} // namespace

// glClear(mask=0x4100) says nothing to a reader; the bits are named from the parameter's own
// group in the registry (0x4000 is also GL_LIGHT0's value), unknown bits stay in hex.
TEST(CallCodec, NamesTheBitsOfABitfield)
{
    CallWriter w;
    w.op(op::glClear);
    w.put<GLbitfield>(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    w.op(op::glPushAttrib);
    w.put<GLbitfield>(GL_ALL_ATTRIB_BITS);
    w.op(op::glPushAttrib);
    w.put<GLbitfield>(GL_LIGHTING_BIT | 0x40000000u);
    w.op(op::glClear);
    w.put<GLbitfield>(0);
    std::string out, error;
    ASSERT_TRUE(CallPrinter::printFrame(w.data(), w.size(), nullptr, nullptr, "", out, error))
        << error;
    EXPECT_EQ(out, "glClear(mask=GL_DEPTH_BUFFER_BIT|GL_COLOR_BUFFER_BIT)\n"
                   "glPushAttrib(mask=GL_ALL_ATTRIB_BITS)\n"
                   "glPushAttrib(mask=GL_LIGHTING_BIT|0x40000000)\n"
                   "glClear(mask=0x0)\n");
}

// Numbered, each GL call's line carries its place in the stream; the frame's end is nprgl's
// own record and takes no number; a grep keeps the numbers of the calls it keeps.
TEST(CallCodec, NumbersCallsFromTheGivenPlace)
{
    std::vector<uint8_t> frame = sampleFrame();
    std::string out, error;
    uint64_t next = 40;
    ASSERT_TRUE(CallPrinter::printFrame(frame.data(), frame.size(), nullptr, nullptr, "glEnd",
                                        out, error, nullptr, &next))
        << error;
    EXPECT_EQ(out, "44 glEnd()\n");
    EXPECT_EQ(next, 46u);
}

TEST(CallCodec, PrintsWhatWasEncoded)
{
    std::vector<uint8_t> frame = sampleFrame();
    std::string out, error;
    uint64_t calls = 0;
    ASSERT_TRUE(CallPrinter::printFrame(frame.data(), frame.size(), nullptr, nullptr, "", out,
                                        error, &calls))
        << error;
    EXPECT_EQ(out, "glBegin(mode=GL_TRIANGLES)\n"
                   "glVertex3f(x=0, y=0.5, z=-1)\n"
                   "glVertex3f(x=1, y=0.5, z=-1)\n"
                   "glVertex3f(x=2, y=0.5, z=-1)\n"
                   "glEnd()\n"
                   "glLightfv(light=GL_LIGHT0, pname=GL_POSITION, params=[1, 2, 3, 0])\n"
                   "-- end of frame 7 --\n");
    EXPECT_EQ(calls, 7u);
}

// A capture names the command behind each of its opcodes; a build whose numbering differs
// (another gl.xml) decodes it by name, and a command it does not know fails the call that
// uses it, by name, not some other command with the same number.
TEST(CallCodec, DecodesAnotherNumberingByName)
{
    // The file's numbering: glVertex3f and glBegin swapped, and a command unknown here.
    std::vector<std::string> names(op::glVertex3f + 1, "glUnused");
    names[0] = "glNoSuchCommandHere";
    names[op::glBegin] = "glVertex3f";
    names[op::glVertex3f] = "glBegin";
    names[op::glEnd] = "glEnd";
    const OpcodeMap map(names);
    EXPECT_FALSE(map.identity());
    EXPECT_EQ(map.unknownCount(), size_t(op::glVertex3f + 1 - 3));

    CallWriter w;
    w.op(op::glVertex3f); // the file's glBegin
    w.put<GLenum>(GL_POINTS);
    w.op(op::glBegin); // the file's glVertex3f
    for (float v : {1.0f, 2.0f, 3.0f}) w.put<GLfloat>(v);
    w.op(op::glEnd);
    w.op(op::kFrameEnd);
    w.put<uint64_t>(3);
    std::string out, error;
    ASSERT_TRUE(CallPrinter::printFrame(w.data(), w.size(), nullptr, &map, "", out, error))
        << error;
    EXPECT_EQ(out, "glBegin(mode=GL_POINTS)\nglVertex3f(x=1, y=2, z=3)\nglEnd()\n"
                   "-- end of frame 3 --\n");
    // Without the table the same bytes mean something else (what the table is for).
    out.clear();
    CallPrinter::printFrame(w.data(), w.size(), nullptr, nullptr, "", out, error);
    EXPECT_NE(out.rfind("glVertex3f(", 0), std::string::npos) << out;

    CallWriter unknown;
    unknown.op(0);
    out.clear();
    EXPECT_FALSE(CallPrinter::printFrame(unknown.data(), unknown.size(), nullptr, &map, "", out,
                                         error));
    EXPECT_NE(error.find("glNoSuchCommandHere (opcode 0) is not a command this nprgl knows"),
              std::string::npos)
        << error;

    // A file written by this build maps onto itself.
    std::vector<std::string> own(kOpcodeNames, kOpcodeNames + op::kCount);
    EXPECT_TRUE(OpcodeMap(own).identity());
}

TEST(CallCodec, AnArrayOfTheWrongLengthIsRefused)
{
    CallWriter w;
    w.op(op::glLightfv);
    size_t mark = w.beginPayload();
    w.put<GLenum>(GL_LIGHT0);
    w.put<GLenum>(GL_POSITION); // needs 4 floats
    const float two[2] = {1, 2};
    w.putBytes(two, sizeof two);
    w.endPayload(mark);
    std::string out, error;
    EXPECT_FALSE(CallPrinter::printFrame(w.data(), w.size(), nullptr, nullptr, "", out, error));
    EXPECT_NE(error.find("expected"), std::string::npos) << error;
}

TEST(CallCodec, TruncatedAndMutatedFramesNeverCrash)
{
    std::vector<size_t> boundaries = {0};
    std::vector<uint8_t> frame = sampleFrame(&boundaries);
    ASSERT_EQ(boundaries.back(), frame.size());
    std::string out, error;
    for (size_t cut = 0; cut < frame.size(); ++cut) {
        out.clear();
        error.clear();
        bool ok = CallPrinter::printFrame(frame.data(), cut, nullptr, nullptr, "", out, error);
        // A cut on a call boundary is a shorter valid frame; anywhere else an error that
        // says where.
        const bool onBoundary =
            std::find(boundaries.begin(), boundaries.end(), cut) != boundaries.end();
        EXPECT_EQ(ok, onBoundary) << "cut at " << cut << ": " << error;
        if (!ok) {
            EXPECT_NE(error.find("offset"), std::string::npos) << error;
        }
    }
    // Random damage: the decoder must notice most of it and read out of bounds never (the
    // sanitizer build checks the latter).
    std::mt19937 rng(42);
    int refused = 0;
    for (int round = 0; round < 2000; ++round) {
        std::vector<uint8_t> mutated = frame;
        for (int k = 0; k < 3; ++k) mutated[rng() % mutated.size()] = uint8_t(rng());
        out.clear();
        refused += !CallPrinter::printFrame(mutated.data(), mutated.size(), nullptr, nullptr,
                                            "", out, error);
    }
    EXPECT_GT(refused, 1000);
}

TEST(CallCodec, BlobReferencesNeedASource)
{
    CallWriter w;
    std::vector<uint8_t> big(4096, 7);
    w.setBlobSink([](const void*, size_t) { return uint64_t(0x1234); });
    w.op(op::glBufferData);
    size_t mark = w.beginPayload();
    w.put<GLenum>(GL_ARRAY_BUFFER);
    w.put<GLsizeiptr>(GLsizeiptr(big.size()));
    w.put<GLenum>(GL_STATIC_DRAW);
    w.putBytes(big.data(), big.size());
    w.endPayload(mark);
    EXPECT_LT(w.size(), 64u); // the bytes went to the blob sink
    std::string out, error;
    EXPECT_FALSE(CallPrinter::printFrame(w.data(), w.size(), nullptr, nullptr, "", out, error));
    EXPECT_NE(error.find("blob"), std::string::npos) << error;
}

// Facts about commands come from one table in the generator (kOpcodeFacts), for the tracker,
// the recorder and the compositor alike. The tracker's old rule, names beginning "glVertex",
// took glVertexAttrib4f for a vertex: run while a list compiled, and not compiled into it.
TEST(CommandFacts, SayWhatEachCommandIs)
{
    auto is = [](uint16_t opcode, uint8_t fact) { return (kOpcodeFacts[opcode] & fact) != 0; };
    EXPECT_TRUE(is(op::glVertex3f, fact::kVertex));
    EXPECT_TRUE(is(op::glDrawElements, fact::kVertex));
    EXPECT_TRUE(is(op::glRectf, fact::kVertex));
    EXPECT_FALSE(is(op::glVertexAttrib4f, fact::kVertex)) << "a generic attribute is no vertex";
    EXPECT_FALSE(is(op::glVertexPointer, fact::kVertex));
    EXPECT_FALSE(is(op::glColor3f, fact::kVertex));
    // GL runs these at once inside glNewList (OpenGL 2.1 section 5.4); it compiles the others.
    EXPECT_TRUE(is(op::glVertexPointer, fact::kRunsWhileCompiling));
    EXPECT_TRUE(is(op::glBindBuffer, fact::kRunsWhileCompiling));
    EXPECT_TRUE(is(op::glGenLists, fact::kRunsWhileCompiling));
    EXPECT_FALSE(is(op::glColor3f, fact::kRunsWhileCompiling));
    EXPECT_FALSE(is(op::glVertexAttrib4f, fact::kRunsWhileCompiling));
    // Held back by the compositor: every vertex call, evaluators and glCallList; never an
    // attribute, which reaches the driver inside a held glBegin/glEnd.
    for (uint16_t i = 0; i < op::kCount; ++i) {
        if (is(i, fact::kVertex)) {
            EXPECT_TRUE(is(i, fact::kHeld)) << kOpcodeNames[i];
        }
    }
    EXPECT_TRUE(is(op::glCallList, fact::kHeld));
    EXPECT_TRUE(is(op::glEvalCoord2f, fact::kHeld));
    EXPECT_FALSE(is(op::glColor3f, fact::kHeld));
    EXPECT_FALSE(is(op::glNormal3f, fact::kHeld));
    // The compositor has a thunk for every draw the tracker follows outside glBegin/glEnd
    // (a draw it lacked would reach the driver unheld, drawn twice under a shading style),
    // for the list calls, and for no attribute or vertex inside glBegin/glEnd.
    for (uint16_t i = 0; i < op::kCount; ++i) {
        const std::string name = kOpcodeNames[i];
        if (is(i, fact::kVertex) && name.rfind("glVertex", 0) != 0 && name != "glArrayElement") {
            EXPECT_TRUE(is(i, fact::kIntercepted)) << name;
        }
    }
    EXPECT_TRUE(is(op::glCallList, fact::kIntercepted));
    EXPECT_TRUE(is(op::glCallLists, fact::kIntercepted));
    EXPECT_TRUE(is(op::glClear, fact::kIntercepted));
    EXPECT_FALSE(is(op::glVertex3f, fact::kIntercepted));
    EXPECT_FALSE(is(op::glColor3f, fact::kIntercepted));
}

TEST(GlSizes, ImagesFollowTheUnpackState)
{
    UnpackState tight;
    tight.alignment = 1;
    EXPECT_EQ(imageBytes(GL_RGB, GL_UNSIGNED_BYTE, 3, 2, 1, tight), 18u);
    UnpackState aligned; // alignment 4: rows of 9 bytes padded to 12
    EXPECT_EQ(imageBytes(GL_RGB, GL_UNSIGNED_BYTE, 3, 2, 1, aligned), 12u + 9u);
    UnpackState rows;
    rows.alignment = 1;
    rows.rowLength = 10;
    rows.skipRows = 1;
    rows.skipPixels = 2;
    EXPECT_EQ(imageBytes(GL_RGBA, GL_UNSIGNED_BYTE, 4, 2, 1, rows), (1 + 1) * 40u + (2 + 4) * 4u);
    EXPECT_EQ(imageBytes(GL_COLOR_INDEX, GL_BITMAP, 10, 14, 1, tight), 28u);
    EXPECT_EQ(imageBytes(GL_RGBA, GL_UNSIGNED_INT_8_8_8_8_REV, 2, 2, 2, tight), 32u);
    EXPECT_EQ(imageBytes(GL_RGBA, 0x1234, 2, 2, 1, tight), 0u);
    EXPECT_EQ(pnameCount(GL_POSITION), 4u);
    EXPECT_EQ(pnameCount(GL_SPOT_DIRECTION), 3u);
    EXPECT_EQ(pnameCount(GL_SHININESS), 1u);
    EXPECT_EQ(callListsBytes(5, GL_3_BYTES), 15u);
    EXPECT_EQ(callListsBytes(-1, GL_INT), 0u);
}
