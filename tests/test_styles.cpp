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
