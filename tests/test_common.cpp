#include "common/FrameSet.h"
#include "common/KeyValue.h"
#include "common/PngImage.h"
#include "tests/support/Process.h"

#include <gtest/gtest.h>

using namespace nprgl;

TEST(FrameSet, ParsesListsRangesAndOpenEnds)
{
    FrameSet set;
    std::string error;
    ASSERT_TRUE(FrameSet::parse("1,10,20-22,100-", set, error)) << error;
    EXPECT_TRUE(set.contains(1));
    EXPECT_FALSE(set.contains(2));
    EXPECT_TRUE(set.contains(10));
    EXPECT_TRUE(set.contains(21));
    EXPECT_FALSE(set.contains(23));
    EXPECT_TRUE(set.contains(1000000));
    EXPECT_EQ(set.last(), UINT64_MAX);
}

TEST(FrameSet, RefusesBadItemsWithAMessage)
{
    FrameSet set;
    std::string error;
    for (const char* bad : {"", "0", "x", "5-3", "1,,a", "-4", "1-2-3", "99999999999999999999"}) {
        error.clear();
        EXPECT_FALSE(FrameSet::parse(bad, set, error)) << bad;
        EXPECT_FALSE(error.empty()) << bad;
    }
}

TEST(KeyValue, SplitsAndTrims)
{
    KeyValueList list;
    std::string error;
    ASSERT_TRUE(parseKeyValues(" frames=1,2 ; dir = out ", ';', list, error)) << error;
    ASSERT_EQ(list.size(), 2u);
    EXPECT_EQ(list[0], (std::pair<std::string, std::string>{"frames", "1,2"}));
    EXPECT_EQ(list[1], (std::pair<std::string, std::string>{"dir", "out"}));
    EXPECT_FALSE(parseKeyValues("a=1,novalue", ',', list, error));
    EXPECT_NE(error.find("novalue"), std::string::npos);
    EXPECT_FALSE(parseKeyValues("=3", ',', list, error));
}

TEST(PngImage, RoundTripsAndFlips)
{
    PngImage image;
    image.width = 3;
    image.height = 2;
    for (int i = 0; i < 24; ++i) image.rgba.push_back(uint8_t(i * 10));
    std::string path = test::freshDir("png") + "/a.png", error;
    ASSERT_TRUE(image.write(path, error)) << error;
    PngImage back;
    ASSERT_TRUE(PngImage::read(path, back, error)) << error;
    EXPECT_EQ(back.rgba, image.rgba);
    back.flipRows();
    EXPECT_EQ(back.rgba[0], image.rgba[12]);
    EXPECT_FALSE(PngImage::read(path + ".missing", back, error));
    EXPECT_NE(error.find(".missing"), std::string::npos);
}

#include "common/ScreenshotSpec.h"

TEST(ScreenshotSpec, ParsesFramesAndDirAndRefusesTheRest)
{
    ScreenshotSpec spec;
    std::string error;
    ASSERT_TRUE(ScreenshotSpec::parse("frames=1,10;dir=out", spec, error)) << error;
    EXPECT_TRUE(spec.frames.contains(10));
    EXPECT_EQ(spec.dir, "out");
    ASSERT_TRUE(ScreenshotSpec::parse("frames=3", spec, error)) << error;
    EXPECT_EQ(spec.dir, ".");
    EXPECT_FALSE(ScreenshotSpec::parse("dir=out", spec, error));
    EXPECT_NE(error.find("frames=LIST"), std::string::npos) << error;
    EXPECT_FALSE(ScreenshotSpec::parse("frames=1;size=3", spec, error));
    EXPECT_NE(error.find("'size'"), std::string::npos) << error;
    EXPECT_FALSE(ScreenshotSpec::parse("frames=0", spec, error));
}
