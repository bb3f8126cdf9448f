// The hold policy (frame/TrackerHold.cpp): which draws the styles take and why the others are
// left, as queries over GL state set through the tracker's entry points, without GL or captures.
#include "frame/StateTracker.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <string>

using namespace nprgl;

namespace {

// A tracker holding draws, under a perspective projection and the modelview.
class HoldPolicy : public ::testing::Test {
protected:
    void SetUp() override
    {
        tracker.setHolding(true);
        tracker.matrixMode(GL_PROJECTION);
        tracker.topMatrix() = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 1.0f, 100.0f);
        tracker.matrixMode(GL_MODELVIEW);
    }

    // Why a 3D triangle draw issued now is left ("" when it is held).
    std::string why() const
    {
        const char* reason = tracker.unstylableState();
        EXPECT_EQ(tracker.wouldHold(GL_TRIANGLES), reason == nullptr) << (reason ? reason : "");
        return reason ? reason : "";
    }

    StateTracker tracker;
};

} // namespace

TEST_F(HoldPolicy, APlainFilledDrawIsHeldAndOnlyPolygons)
{
    EXPECT_EQ(why(), "");
    EXPECT_TRUE(tracker.wouldHold(GL_QUAD_STRIP));
    EXPECT_FALSE(tracker.wouldHold(GL_LINES));
    EXPECT_FALSE(tracker.wouldHold(GL_POINTS));
    tracker.setHolding(false);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES)) << "nothing is held while holding is off";
}

// 2D drawing (orthographic, depth writes off or no depth test) is the program's own overlay.
TEST_F(HoldPolicy, OrthographicDrawingIsHeldOnlyWhenItWritesTestedDepth)
{
    tracker.matrixMode(GL_PROJECTION);
    tracker.topMatrix() = glm::ortho(0.0f, 640.0f, 0.0f, 480.0f, -1.0f, 1.0f);
    tracker.matrixMode(GL_MODELVIEW);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    tracker.setEnabled(GL_DEPTH_TEST, true);
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES)) << "a depth-tested orthographic scene is 3D";
    tracker.depthMask(false);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
}

TEST_F(HoldPolicy, BlendingOnlyByAlphaIsHeld)
{
    tracker.setEnabled(GL_BLEND, true);
    tracker.blendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    EXPECT_EQ(why(), "") << "a translucent surface is styled";
    tracker.blendFunc(GL_ONE, GL_ZERO);
    EXPECT_EQ(why(), "") << "GL_ONE, GL_ZERO replaces: no blending";
    tracker.blendFunc(GL_ONE, GL_ONE);
    EXPECT_NE(why().find("blending other than"), std::string::npos);
    EXPECT_TRUE(tracker.mayLayer(GL_TRIANGLES)) << "an additive pass may be a layer";
}

TEST_F(HoldPolicy, EachPipelineStateTheStylesCannotDrawIsNamed)
{
    tracker.setEnabled(GL_STENCIL_TEST, true);
    EXPECT_EQ(why(), "the stencil test");
    tracker.setEnabled(GL_STENCIL_TEST, false);

    tracker.polygonMode(GL_FRONT_AND_BACK, GL_LINE);
    EXPECT_EQ(why(), "glPolygonMode lines or points");
    // Lines on the back only, with the back culled: the filled front is all GL draws.
    tracker.polygonMode(GL_FRONT, GL_FILL);
    tracker.setEnabled(GL_CULL_FACE, true);
    tracker.cullMode(GL_BACK);
    EXPECT_EQ(why(), "");
    tracker.cullMode(GL_FRONT);
    EXPECT_EQ(why(), "glPolygonMode lines or points");
    tracker.polygonMode(GL_FRONT_AND_BACK, GL_FILL);

    tracker.colorMask(true, false, true, true);
    EXPECT_EQ(why(), "a partial colour mask");
    tracker.colorMask(false, false, false, false);
    EXPECT_EQ(why(), "") << "a depth-only pass supplies the styles' depth";
    tracker.colorMask(true, true, true, false);
    EXPECT_EQ(why(), "") << "alpha masked alone: the picture is all the program's";
    tracker.colorMask(true, true, true, true);

    tracker.useProgram(5);
    EXPECT_EQ(why(), "the program's own shaders");
    tracker.useProgram(0);
    EXPECT_EQ(why(), "");
}

// The styles draw inside one more glPushAttrib: a stack with no room left leaves the scene.
TEST_F(HoldPolicy, AFullAttributeStackLeavesTheDraw)
{
    tracker.setStackLimits(2, 16);
    tracker.pushAttrib(GL_ENABLE_BIT);
    EXPECT_EQ(why(), "");
    tracker.pushAttrib(GL_ENABLE_BIT);
    EXPECT_EQ(why(), "a full attribute stack");
    tracker.popAttrib();
    EXPECT_EQ(why(), "");
}

// A list being compiled draws nothing now; one compiled and executed draws now what it keeps.
TEST_F(HoldPolicy, ListsBeingCompiledAreNotHeld)
{
    tracker.newList(1, GL_COMPILE);
    EXPECT_FALSE(tracker.wouldHold(GL_TRIANGLES));
    tracker.endList();
    EXPECT_TRUE(tracker.wouldHold(GL_TRIANGLES));
    tracker.newList(2, GL_COMPILE_AND_EXECUTE);
    EXPECT_STREQ(tracker.unstylableState(), "glNewList(GL_COMPILE_AND_EXECUTE)");
    tracker.endList();
    EXPECT_EQ(why(), "");
}
