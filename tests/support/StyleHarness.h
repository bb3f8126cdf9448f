#pragma once

#include "common/PngImage.h"
#include "reconstruct/Batch.h"
#include "reconstruct/Reconstructor.h"
#include "styles/Scene.h"
#include "styles/StyleChain.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace nprgl::test {

// Renders scenes through a style chain in an in-process OSMesa context, the way the
// compositor does (with no shading style in the chain, the program's own drawing of the
// held-back geometry comes first: here its depth only), without the shim: for the styles'
// unit tests.
class StyleHarness {
public:
    StyleHarness(int width, int height);
    ~StyleHarness();
    bool ok() const { return mOk; }

    // One object per batch group (the Reconstructor's grouping), lit by a light towards
    // lightDir (eye space), viewed through projection.
    styles::Scene makeScene(const std::vector<reconstruct::Batch>& batches,
                            const glm::mat4& projection,
                            glm::vec3 lightDir = glm::normalize(glm::vec3(0.3f, 0.5f, 1.0f)));
    // Renders with "chain" and "config" (as NPRGL_STYLE / NPRGL_CONFIG); false with a message
    // on a bad chain or a style that cannot start.
    bool render(const styles::Scene& scene, const std::string& chain, const std::string& config,
                PngImage& out, std::string& error, glm::vec4 background = glm::vec4(1.0f));
    // On: successive render()s with the same chain and config go through the same styles,
    // as a program's frames do in one context (styles that remember earlier frames). Off (the
    // default): every render() starts new styles.
    void keepChain(bool keep);
    // The program textures' content hashes as the compositor's state model gives them (none
    // by default: every texture's content is unknown, and no style abstracts it).
    void setTextureContent(std::function<uint64_t(GLuint)> content)
    {
        mTextureContent = std::move(content);
    }
    const styles::GlFunctions& gl() const { return mGl; }
    // A 2D texture of bytes, tightly packed, sampled nearest (one texel a face's part); the
    // unpack alignment and the binding are left at their defaults.
    GLuint nearestTexture(GLint internalFormat, int width, int height, GLenum format,
                          const uint8_t* texels) const;
    // A depth-only program's sources (uniform mat4 mvp; attribute 0 position).
    static const char* depthVertexShader();
    static const char* depthFragmentShader();

private:
    bool drawDepth(const styles::Scene& scene, styles::StyleChain& chain, std::string& error);

    int mWidth, mHeight;
    void* mContext = nullptr;
    std::vector<uint8_t> mBuffer;
    bool mOk = false;
    bool mKeepChain = false;
    std::unique_ptr<styles::StyleChain> mKept; // with mKeepChain: the last render()'s styles
    std::string mKeptKey;                      // its chain and config
    std::function<uint64_t(GLuint)> mTextureContent;
    styles::GlFunctions mGl;
    reconstruct::Reconstructor mReconstructor;
    std::vector<reconstruct::FrameObject> mObjects;
};

// Batches for tests: a UV sphere and a box as GL_TRIANGLES with normals, at a modelview.
reconstruct::Batch sphereBatch(const glm::mat4& modelview, float radius, int slices, int stacks,
                               glm::vec4 color, uint32_t materialId = 1);
reconstruct::Batch boxBatch(const glm::mat4& modelview, glm::vec3 halfSize, glm::vec4 color,
                            uint32_t materialId = 1);

} // namespace nprgl::test
