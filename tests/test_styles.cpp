#include "styles/PageTone.h"
#include "styles/StyleRegistry.h"
#include "styles/StyleSettings.h"

#include <gtest/gtest.h>

using namespace nprgl;

TEST(StyleRegistry, KnowsNoneAndTheDefault)
{
    const StyleRegistry& registry = StyleRegistry::instance();
    ASSERT_NE(registry.find("none"), nullptr);
    // The default is a chain of known styles with one shading style.
    std::vector<const StyleInfo*> chain;
    std::string error;
    EXPECT_TRUE(registry.parseChain(registry.defaultStyle(), chain, error)) << error;
    EXPECT_GE(chain.size(), 2u);
    EXPECT_EQ(registry.find("nonesuch"), nullptr);
}

TEST(StyleRegistry, ParsesChainsAndNamesTheUnknownStyle)
{
    const StyleRegistry& registry = StyleRegistry::instance();
    std::vector<const StyleInfo*> chain;
    std::string error;
    ASSERT_TRUE(registry.parseChain("toon", chain, error)) << error;
    EXPECT_EQ(chain.size(), 1u);
    EXPECT_FALSE(registry.parseChain("none+toon", chain, error));
    EXPECT_NE(error.find("'none'"), std::string::npos) << error;
    EXPECT_FALSE(registry.parseChain("toon+toon", chain, error));
    EXPECT_NE(error.find("twice"), std::string::npos) << error;
    EXPECT_FALSE(registry.parseChain("toon+sparkles", chain, error));
    EXPECT_NE(error.find("'sparkles'"), std::string::npos) << error;
    EXPECT_FALSE(registry.parseChain("", chain, error));
    EXPECT_FALSE(registry.parseChain("none+", chain, error));
}

// A style that draws on a background (pencil on paper) brings it when the chain names no
// background, and only then.
TEST(StyleRegistry, AStyleBringsItsBackgroundWhenTheChainHasNone)
{
    const StyleRegistry& registry = StyleRegistry::instance();
    std::vector<const StyleInfo*> chain;
    std::string error;
    auto names = [&]() {
        std::string s;
        for (const StyleInfo* info : chain) s += (s.empty() ? "" : "+") + info->name;
        return s;
    };
    ASSERT_TRUE(registry.parseChain("pencil", chain, error)) << error;
    EXPECT_EQ(names(), "pencil+paper");
    ASSERT_TRUE(registry.parseChain("toon+pencil", chain, error)) << error;
    EXPECT_EQ(names(), "toon+pencil+paper");
    ASSERT_TRUE(registry.parseChain("paper+pencil", chain, error)) << error;
    EXPECT_EQ(names(), "paper+pencil");
    ASSERT_TRUE(registry.parseChain("toon+edges", chain, error)) << error;
    EXPECT_EQ(names(), "toon+edges");
}

TEST(StyleSettings, EmptyStyleMeansTheDefault)
{
    StyleSettings settings;
    std::string error;
    ASSERT_TRUE(StyleSettings::parse("", "", settings, error)) << error;
    EXPECT_EQ(settings.chainName(), StyleRegistry::instance().defaultStyle());
}

TEST(StyleSettings, RefusesUnknownParametersNamingThem)
{
    StyleSettings settings;
    std::string error;
    EXPECT_FALSE(StyleSettings::parse("none", "none.width=3", settings, error));
    EXPECT_NE(error.find("none.width"), std::string::npos) << error;
    EXPECT_FALSE(StyleSettings::parse("none", "width", settings, error));
    EXPECT_FALSE(StyleSettings::parse("bogus", "", settings, error));
    EXPECT_NE(error.find("bogus"), std::string::npos) << error;
}

TEST(StyleSettings, ChecksRangesAndNamesTheRange)
{
    StyleSettings settings;
    std::string error;
    ASSERT_TRUE(StyleSettings::parse("toon", "toon.diffuse_threshold=-0.2", settings, error))
        << error;
    EXPECT_DOUBLE_EQ(settings.value("toon", "diffuse_threshold"), -0.2);
    EXPECT_DOUBLE_EQ(settings.value("toon", "tones"), 3.0); // the default
    EXPECT_FALSE(StyleSettings::parse("toon", "toon.diffuse_threshold=1.5", settings, error));
    EXPECT_NE(error.find("[-1, 1]"), std::string::npos) << error;
    EXPECT_FALSE(StyleSettings::parse("toon", "toon.tones=many", settings, error));
    EXPECT_NE(error.find("not a number"), std::string::npos) << error;
}

// The page follows the program's background: the first frame's clear colour decides, and
// the page changes only after the other tone lasted kHoldFrames frames (a flash of a light
// clear in a dark program, or a fade through grey, does not flip it back and forth).
TEST(PageTone, FollowsTheClearColourWithoutFlicker)
{
    using styles::PageTone;
    PageTone dark;
    dark.observe(0, glm::vec3(0.0f));
    EXPECT_TRUE(dark.dark());
    PageTone light;
    light.observe(0, glm::vec3(0.9f, 0.9f, 0.85f));
    EXPECT_FALSE(light.dark());

    uint64_t frame = 1;
    // Flashes of white shorter than the hold, and a mid grey between the two thresholds.
    for (int i = 0; i < PageTone::kHoldFrames - 1; ++i) dark.observe(frame++, glm::vec3(1.0f));
    dark.observe(frame++, glm::vec3(0.0f));
    for (int i = 0; i < 3 * PageTone::kHoldFrames; ++i) dark.observe(frame++, glm::vec3(0.5f));
    EXPECT_TRUE(dark.dark()) << "a flash or a grey between the thresholds flipped the page";
    // Only the first flush of a frame counts.
    for (int i = 0; i < 2 * PageTone::kHoldFrames; ++i) dark.observe(frame, glm::vec3(1.0f));
    EXPECT_TRUE(dark.dark());
    // A background that stays light turns the page light.
    for (int i = 0; i < PageTone::kHoldFrames; ++i) dark.observe(frame++, glm::vec3(1.0f));
    EXPECT_FALSE(dark.dark());

    PageTone forced;
    forced.setMode(PageTone::Mode::Dark);
    forced.observe(0, glm::vec3(1.0f));
    EXPECT_TRUE(forced.dark()) << "paper.tone=dark was not kept";
    forced.setMode(PageTone::Mode::Light);
    forced.observe(1, glm::vec3(0.0f));
    EXPECT_FALSE(forced.dark()) << "paper.tone=light was not kept";
}

// On a dark page black ink becomes light ink of the same hue, and the lighter line classes
// move towards the page (black) instead of white; a light page keeps the configured ink.
TEST(PageTone, InkStandsOutOnEitherPage)
{
    using styles::PageTone;
    PageTone light, dark;
    light.observe(0, glm::vec3(1.0f));
    dark.observe(0, glm::vec3(0.0f));
    const glm::vec3 black(0.0f), blue(0.0f, 0.0f, 0.4f);
    EXPECT_EQ(light.ink(black), black);
    EXPECT_EQ(light.line(black, 0.5f), glm::vec3(0.5f));
    EXPECT_GT(PageTone::luminance(dark.ink(black)), 0.6f) << "black ink on a dark page";
    EXPECT_GT(PageTone::luminance(dark.ink(blue)), 0.4f);
    EXPECT_GT(dark.ink(blue).b, dark.ink(blue).r) << "the ink lost its blue";
    EXPECT_LT(PageTone::luminance(dark.line(black, 0.5f)),
              PageTone::luminance(dark.line(black, 0.0f)))
        << "a lighter line class is not nearer the dark page";
    const glm::vec3 chalk(0.9f, 0.9f, 0.8f);
    EXPECT_EQ(dark.ink(chalk), chalk) << "a light ink was changed on a dark page";
}

// A parameter no style declares reads 0 (or empty text) and says so, naming it.
TEST(StyleSettings, AnUndeclaredParameterIsSaid)
{
    StyleSettings settings;
    std::string error;
    ASSERT_TRUE(StyleSettings::parse("toon", "", settings, error)) << error;
    testing::internal::CaptureStderr();
    EXPECT_EQ(settings.value("toon", "tonez"), 0.0);
    EXPECT_EQ(settings.text("toon", "shadow_colour"), "");
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_NE(said.find("toon.tonez"), std::string::npos) << said;
    EXPECT_NE(said.find("toon.shadow_colour"), std::string::npos) << said;
    EXPECT_EQ(settings.value("toon", "tones"), 3.0);
}
