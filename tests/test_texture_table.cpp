// TextureTable: one record per texture, as its uploads make it, without a GL context.
#include "frame/TextureTable.h"

#include <gtest/gtest.h>

#include <vector>

using namespace nprgl;

namespace {

// w x h RGBA bytes of one colour.
std::vector<unsigned char> rgba(int w, int h, unsigned char r, unsigned char g, unsigned char b,
                                unsigned char a)
{
    std::vector<unsigned char> p;
    for (int i = 0; i < w * h; ++i) p.insert(p.end(), {r, g, b, a});
    return p;
}

} // namespace

TEST(TextureTable, AnUploadMakesOneRecordOfWhatItsPixelsSay)
{
    TextureTable t;
    const auto solid = rgba(8, 8, 255, 0, 0, 255);
    t.image2D(3, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    ASSERT_NE(t.find(3), nullptr);
    EXPECT_TRUE(t.opaque(3));
    EXPECT_NE(t.hash(3), 0u);
    ASSERT_NE(t.mean(3), nullptr);
    EXPECT_NEAR(t.mean(3)->r, 1.0f, 1e-3f);
    EXPECT_NEAR(t.mean(3)->g, 0.0f, 1e-3f);
    // Another texture is untouched, and one never made has no record.
    EXPECT_EQ(t.find(4), nullptr);
    EXPECT_FALSE(t.opaque(4));
    EXPECT_EQ(t.hash(4), 0u);

    // A second upload replaces the first record whole: half-transparent alpha-only pixels.
    const std::vector<unsigned char> alpha(64, 128);
    t.image2D(3, GL_ALPHA, 8, 8, GL_ALPHA, GL_UNSIGNED_BYTE, alpha.data(), alpha.size());
    EXPECT_FALSE(t.opaque(3));
    EXPECT_TRUE(t.alphaOnly(3));
    // Same size, other content: another name across runs.
    EXPECT_NE(t.hash(3), 0u);
    t.image2D(5, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    EXPECT_NE(t.hash(3), t.hash(5));
}

TEST(TextureTable, AnRgbFormatIsOpaqueWhateverAlphaItsBytesCarry)
{
    TextureTable t;
    const auto clear = rgba(4, 4, 10, 20, 30, 0);
    t.image2D(1, GL_RGB, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, clear.data(), clear.size());
    EXPECT_TRUE(t.opaque(1));
    t.image2D(2, GL_RGBA, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, clear.data(), clear.size());
    EXPECT_FALSE(t.opaque(2));
}

TEST(TextureTable, StorageFilledInPartsIsOpaqueWhileEveryPartIs)
{
    TextureTable t;
    // Made without pixels, then filled by parts (SFML's way).
    t.image2D(7, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, nullptr, 0);
    EXPECT_FALSE(t.opaque(7));
    EXPECT_EQ(t.hash(7), 0u);
    const auto solid = rgba(8, 4, 0, 255, 0, 255);
    t.subImage2D(7, 0, 0, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    EXPECT_TRUE(t.opaque(7));
    const auto clear = rgba(8, 4, 0, 255, 0, 0);
    t.subImage2D(7, 0, 4, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, clear.data(), clear.size());
    EXPECT_FALSE(t.opaque(7));
    // A transparent part is not undone by an opaque one over another part.
    t.subImage2D(7, 0, 0, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    EXPECT_FALSE(t.opaque(7));
}

TEST(TextureTable, APartChangesWhatTheUploadWasKnownBy)
{
    TextureTable t;
    const auto solid = rgba(8, 8, 200, 200, 200, 255);
    t.image2D(2, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    ASSERT_NE(t.hash(2), 0u);
    const auto part = rgba(2, 2, 0, 0, 0, 255);
    const uint64_t uploaded = t.hash(2);
    t.subImage2D(2, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, part.data(), part.size());
    const uint64_t afterPart = t.hash(2);
    EXPECT_NE(afterPart, 0u);       // known: the upload and the part
    EXPECT_NE(afterPart, uploaded); // no longer the hashed upload
    EXPECT_EQ(t.mean(2), nullptr);  // nor its mean
    EXPECT_TRUE(t.opaque(2));       // an opaque part over an opaque image
    // The same part elsewhere is other content; the same sequence is the same content.
    TextureTable other;
    other.image2D(2, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    other.subImage2D(2, 4, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, part.data(), part.size());
    EXPECT_NE(other.hash(2), afterPart);
    TextureTable same;
    same.image2D(2, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    same.subImage2D(2, 1, 1, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, part.data(), part.size());
    EXPECT_EQ(same.hash(2), afterPart);
    // Into a texture never made here nothing is recorded.
    t.subImage2D(9, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, part.data(), part.size());
    EXPECT_EQ(t.find(9), nullptr);
}

TEST(TextureTable, StorageFilledInPartsIsKnownByItsParts)
{
    TextureTable t;
    t.image2D(7, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, nullptr, 0);
    const auto solid = rgba(8, 8, 0, 255, 0, 255);
    t.subImage2D(7, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    EXPECT_NE(t.hash(7), 0u);
    // Pixels from a buffer object (none here) leave it unknown, and it stays so.
    t.subImage2D(7, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, nullptr, 0);
    EXPECT_EQ(t.hash(7), 0u);
    t.subImage2D(7, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    EXPECT_EQ(t.hash(7), 0u);
}

TEST(TextureTable, WrittenByGlItsContentIsNotKnown)
{
    TextureTable t;
    const auto solid = rgba(8, 8, 200, 200, 200, 255);
    t.image2D(3, GL_RGBA, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    ASSERT_NE(t.hash(3), 0u);
    t.overwritten(3); // glCopyTexSubImage2D, or rendered into
    EXPECT_EQ(t.hash(3), 0u);
    t.subImage2D(3, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    EXPECT_EQ(t.hash(3), 0u);
    // Copied storage (glCopyTexImage2D) is not known either.
    t.storage2D(4, GL_RGBA8, false);
    t.subImage2D(4, 0, 0, 8, 8, GL_RGBA, GL_UNSIGNED_BYTE, solid.data(), solid.size());
    EXPECT_EQ(t.hash(4), 0u);
}

TEST(TextureTable, StorageOfADepthFormatIsAShadowMap)
{
    TextureTable t;
    t.storage2D(4, GL_DEPTH_COMPONENT24, false);
    EXPECT_TRUE(t.depth(4));
    EXPECT_TRUE(t.opaque(4));
    t.storage2D(4, GL_ALPHA8, true);
    EXPECT_FALSE(t.depth(4));
    EXPECT_TRUE(t.alphaOnly(4));
    EXPECT_FALSE(t.opaque(4));
}

TEST(TextureTable, ACubeMapsMeanIsItsKnownFacesMean)
{
    TextureTable t;
    glm::vec3 mean;
    EXPECT_FALSE(t.cubeMean(6, mean));
    const auto red = rgba(4, 4, 255, 0, 0, 255), blue = rgba(4, 4, 0, 0, 255, 255);
    t.cubeFace(6, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, red.data(), red.size());
    t.cubeFace(6, 3, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, blue.data(), blue.size());
    t.cubeFace(6, 9, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, blue.data(), blue.size()); // no face 9
    ASSERT_TRUE(t.cubeMean(6, mean));
    EXPECT_NEAR(mean.r, 0.5f, 1e-3f);
    EXPECT_NEAR(mean.b, 0.5f, 1e-3f);
    // Texture object 0 is the default texture only once it has an image.
    EXPECT_FALSE(t.defaultImage());
    t.image2D(0, GL_RGBA, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, red.data(), red.size());
    EXPECT_TRUE(t.defaultImage());
}
