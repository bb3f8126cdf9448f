// The shading styles (thesis chapter 3) rendered in-process through the style harness.

#include "tests/support/StyleHarness.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <set>

using namespace nprgl;
using namespace nprgl::test;

namespace {

glm::mat4 perspective() { return glm::perspective(glm::radians(40.0f), 1.0f, 1.0f, 20.0f); }

} // namespace

TEST(Toon, SphereShowsOnlyItsBandColours)
{
    StyleHarness harness(128, 128);
    ASSERT_TRUE(harness.ok());
    const glm::vec4 red(0.8f, 0.1f, 0.1f, 1.0f);
    auto mv = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6));
    auto scene = harness.makeScene({sphereBatch(mv, 1.5f, 48, 24, red)}, perspective());
    PngImage image;
    std::string error;
    ASSERT_TRUE(harness.render(scene, "toon", "", image, error)) << error;
    image.write(std::string("/tmp/toon_sphere.png"), error);
    // Inside the sphere (well away from its rim) only the three band colours occur.
    std::set<uint32_t> colours;
    for (int y = 40; y < 88; ++y) {
        for (int x = 40; x < 88; ++x) {
            const uint8_t* p = &image.rgba[(size_t(y) * 128 + x) * 4];
            colours.insert(uint32_t(p[0]) << 16 | uint32_t(p[1]) << 8 | p[2]);
        }
    }
    EXPECT_GE(colours.size(), 2u);
    EXPECT_LE(colours.size(), 3u);
}
