// The interposer's own code, linked into this test: real-function resolution, contexts,
// GetProcAddress answers and the screenshot's state hygiene, on an OSMesa context.

#include "frame/FrameGrabber.h"
#include "shim/Api.h"
#include "shim/Context.h"
#include "shim/ProcAddress.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

#include "common/PngImage.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

#include <dlfcn.h>
#include <thread>
#include <vector>

using namespace nprgl;

namespace {

constexpr int kSize = 32;

// Copies, not references: GCC's sanitizers mishandle references into initial-exec TLS.
const GlDispatch* currentDispatch() { return tThread.dispatch; }
Context* currentContext() { return tThread.context; }

// An OSMesa context made current through our hooks (the symbols of this executable).
class OSMesaFixture : public ::testing::Test {
protected:
    void SetUp() override
    {
        mContext = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
        ASSERT_NE(mContext, nullptr);
        mBuffer.assign(kSize * kSize * 4, 0);
        ASSERT_TRUE(OSMesaMakeCurrent(mContext, mBuffer.data(), GL_UNSIGNED_BYTE, kSize, kSize));
    }
    void TearDown() override
    {
        OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(mContext);
    }

    static void drawGreen()
    {
        glClearColor(1, 0, 0, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        glBegin(GL_TRIANGLES);
        glColor3f(0, 1, 0);
        glVertex2f(-1, -1); // the lower-left half; the rest stays red
        glVertex2f(1, -1);
        glVertex2f(-1, 1);
        glEnd();
    }

    OSMesaContext mContext = nullptr;
    std::vector<uint8_t> mBuffer;
};

} // namespace

namespace {

struct Slot {
    const char* name;
    void* real;
};

// Every slot of the real tables, as data: one loop of checks instead of a thousand macros.
std::vector<Slot> glSlots()
{
    return {
#define NPRGL_GL(ret, name, params, args) {#name, reinterpret_cast<void*>(gRealGl.name)},
#include "nprgl_api.inc"
    };
}

std::vector<Slot> wsSlots()
{
    return {
#define NPRGL_WS(api, hooked, ret, name, params, args)                                         \
    {#name, reinterpret_cast<void*>(gRealWs.name)},
#include "nprgl_api.inc"
    };
}

} // namespace

TEST(RealGl, EverySlotResolvesToTheDriverNotToUs)
{
    resolveReal();
    std::vector<Slot> gl = glSlots(), ws = wsSlots();
    ASSERT_EQ(gl.size(), kGlEntryCount);
    ASSERT_EQ(ws.size(), kWsEntryCount);
    // Every command of gl.xml a desktop context can reach (core and extensions), aliases
    // apart: about 2,500.
    EXPECT_GE(kGlEntryCount, 2400u);
    for (size_t i = 0; i < gl.size(); ++i) {
        EXPECT_TRUE(realGlFound(i)) << gl[i].name;
        EXPECT_FALSE(isOwnAddress(gl[i].real)) << gl[i].name;
    }
    for (size_t i = 0; i < ws.size(); ++i) {
        EXPECT_TRUE(realWsFound(i)) << ws[i].name;
        EXPECT_FALSE(isOwnAddress(ws[i].real)) << ws[i].name;
    }
}

TEST(RealGl, OwnThunksAreRecognised)
{
    EXPECT_TRUE(isOwnAddress(reinterpret_cast<void*>(&::glVertex3f)));
    EXPECT_TRUE(isOwnAddress(reinterpret_cast<void*>(&::glXSwapBuffers)));
    void* real = dlsym(RTLD_NEXT, "glVertex3f");
    ASSERT_NE(real, nullptr);
    EXPECT_FALSE(isOwnAddress(real));
}

TEST_F(OSMesaFixture, MakeCurrentInstallsTheContextAndRelease)
{
    ASSERT_NE(currentContext(), nullptr);
    EXPECT_EQ(currentContext()->windowSystem(), WindowSystem::OSMesa);
    EXPECT_EQ(currentDispatch(), &currentContext()->dispatch());
    EXPECT_GE(currentContext()->caps().major, 2);
    drawGreen();
    glFinish();
    EXPECT_EQ(currentContext()->frame(), 1u); // glFinish ends an OSMesa frame
    uint8_t px[4] = {};
    glReadPixels(5, 5, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    EXPECT_EQ(px[0], 0);
    EXPECT_EQ(px[1], 255);
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    EXPECT_EQ(currentContext(), nullptr);
    EXPECT_EQ(currentDispatch(), &gRealGl);
    ASSERT_TRUE(OSMesaMakeCurrent(mContext, mBuffer.data(), GL_UNSIGNED_BYTE, kSize, kSize));
}

TEST_F(OSMesaFixture, GetProcAddressAnswersOurThunkOnlyForKnownRealCommands)
{
    EXPECT_EQ(OSMesaGetProcAddress("glVertex3f"), reinterpret_cast<OSMESAproc>(&::glVertex3f));
    EXPECT_EQ(OSMesaGetProcAddress("glUseProgram"),
              reinterpret_cast<OSMESAproc>(&::glUseProgram));
    // Beyond GL 2.1, and by extension names: ours too (a call nprgl does not see is state
    // it cannot follow and data a capture silently lacks).
    EXPECT_EQ(OSMesaGetProcAddress("glGenFramebuffers"),
              reinterpret_cast<OSMESAproc>(&::glGenFramebuffers));
    EXPECT_EQ(OSMesaGetProcAddress("glGenFramebuffersEXT"),
              reinterpret_cast<OSMESAproc>(&::glGenFramebuffersEXT));
    EXPECT_EQ(OSMesaGetProcAddress("glBindFramebufferEXT"),
              reinterpret_cast<OSMESAproc>(&::glBindFramebufferEXT));
    EXPECT_EQ(OSMesaGetProcAddress("glDebugMessageInsert"),
              reinterpret_cast<OSMESAproc>(&::glDebugMessageInsert));
    EXPECT_EQ(ourProcAddress("glNoSuchCommand"), nullptr);
    EXPECT_EQ(ourProcAddress(nullptr), nullptr);
}

TEST_F(OSMesaFixture, ScreenshotLeavesStateAndErrorsAsTheProgramSetThem)
{
    drawGreen();
    GLuint pbo = 0;
    glGenBuffers(1, &pbo);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, pbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ROW_LENGTH, 7);
    glPixelStorei(GL_PACK_SKIP_PIXELS, 2);
    glReadBuffer(GL_FRONT_LEFT); // not the GL_FRONT that the grabber selects
    glEnable(0x1234);           // a deliberate error the program still owns
    std::string path = test::freshDir("grab") + "/shot.png";
    ASSERT_TRUE(FrameGrabber::writeFrame(currentContext()->caps(), kSize, kSize, path));

    EXPECT_EQ(glGetError(), GLenum(GL_INVALID_ENUM));
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    GLint value = 0;
    glGetIntegerv(GL_PACK_ALIGNMENT, &value);
    EXPECT_EQ(value, 1);
    glGetIntegerv(GL_PACK_ROW_LENGTH, &value);
    EXPECT_EQ(value, 7);
    glGetIntegerv(GL_PACK_SKIP_PIXELS, &value);
    EXPECT_EQ(value, 2);
    glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &value);
    EXPECT_EQ(GLuint(value), pbo);
    glGetIntegerv(GL_READ_BUFFER, &value);
    EXPECT_EQ(value, GL_FRONT_LEFT);

    PngImage image;
    std::string error;
    ASSERT_TRUE(PngImage::read(path, image, error)) << error;
    ASSERT_EQ(image.width, kSize);
    // Top row first: the top-right corner is red, the bottom-left one green.
    size_t topRight = size_t(kSize - 1) * 4, bottomLeft = size_t(kSize - 1) * kSize * 4;
    EXPECT_EQ(image.rgba[topRight + 0], 255);
    EXPECT_EQ(image.rgba[topRight + 1], 0);
    EXPECT_EQ(image.rgba[bottomLeft + 0], 0);
    EXPECT_EQ(image.rgba[bottomLeft + 1], 255);
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    glDeleteBuffers(1, &pbo);
}

TEST(Contexts, EachThreadHasItsOwnCurrentContext)
{
    auto worker = [](Context** seen) {
        OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, nullptr);
        std::vector<uint8_t> buffer(16 * 16 * 4);
        OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, 16, 16);
        *seen = currentContext();
        glClear(GL_COLOR_BUFFER_BIT);
        glFinish();
        OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
        OSMesaDestroyContext(ctx);
    };
    Context* a = nullptr;
    Context* b = nullptr;
    std::thread ta(worker, &a), tb(worker, &b);
    ta.join();
    tb.join();
    EXPECT_NE(a, nullptr);
    EXPECT_NE(b, nullptr);
    EXPECT_NE(a, b);
    EXPECT_EQ(currentContext(), nullptr); // this thread never made one current
}

TEST(Contexts, NoCurrentContextGoesStraightToTheDriver)
{
    ASSERT_EQ(currentContext(), nullptr);
    EXPECT_EQ(currentDispatch(), &gRealGl);
    EXPECT_EQ(glGetString(GL_VERSION), nullptr); // what the driver says with no context
}
