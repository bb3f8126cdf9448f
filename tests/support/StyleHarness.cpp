#include "tests/support/StyleHarness.h"

#include "styles/ShaderProgram.h"

#include <GL/osmesa.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace nprgl::test {

namespace {

void* getProc(const char* name) { return reinterpret_cast<void*>(OSMesaGetProcAddress(name)); }

const char* kDepthVertex = R"(#version 130
uniform mat4 mvp;
in vec3 position;
void main() { gl_Position = mvp * vec4(position, 1.0); }
)";
const char* kDepthFragment = R"(#version 130
out vec4 fragColor;
void main() { fragColor = vec4(1.0); }
)";

} // namespace

StyleHarness::StyleHarness(int width, int height) : mWidth(width), mHeight(height)
{
    const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24,
                           OSMESA_STENCIL_BITS, 8, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 0, 0};
    OSMesaContext ctx = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!ctx) return;
    mContext = ctx;
    mBuffer.resize(size_t(width) * height * 4);
    if (!OSMesaMakeCurrent(ctx, mBuffer.data(), GL_UNSIGNED_BYTE, width, height)) return;
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    std::string missing;
    mOk = mGl.load(&getProc, missing);
}

StyleHarness::~StyleHarness()
{
    keepChain(false);
    if (mContext) OSMesaDestroyContext(static_cast<OSMesaContext>(mContext));
}

styles::Scene StyleHarness::makeScene(const std::vector<reconstruct::Batch>& batches,
                                      const glm::mat4& projection, glm::vec3 lightDir)
{
    mReconstructor.build(batches, mObjects);
    styles::Scene scene;
    scene.viewport = {0, 0, mWidth, mHeight};
    uint32_t id = 0;
    for (const reconstruct::FrameObject& o : mObjects) {
        styles::SceneObject s;
        s.mesh = o.mesh;
        s.modelview = o.modelview;
        s.projection = projection;
        s.lightDir = glm::normalize(lightDir);
        s.id = ++id;
        scene.objects.push_back(std::move(s));
    }
    return scene;
}

void StyleHarness::keepChain(bool keep)
{
    mKeepChain = keep;
    if (!keep && mKept) {
        mKept->shutdown();
        mKept.reset();
    }
}

const char* StyleHarness::depthVertexShader() { return kDepthVertex; }
const char* StyleHarness::depthFragmentShader() { return kDepthFragment; }

bool StyleHarness::drawDepth(const styles::Scene& scene, styles::StyleChain& styleChain,
                             std::string& error)
{
    const styles::GlFunctions& gl = mGl;
    styles::ShaderProgram depth;
    if (!depth.build(gl, kDepthVertex, kDepthFragment, error)) return false;
    styleChain.setBaseline(scene);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.DepthFunc(GL_LESS);
    gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    gl.UseProgram(depth.id());
    for (const styles::SceneObject& o : scene.objects) {
        glm::mat4 mvp = o.projection * o.modelview;
        gl.UniformMatrix4fv(depth.uniform(gl, "mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
        styleChain.context().meshes.draw(gl, *o.mesh);
    }
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    depth.destroy(gl);
    return true;
}

bool StyleHarness::render(const styles::Scene& scene, const std::string& chain,
                          const std::string& config, PngImage& out, std::string& error,
                          glm::vec4 background)
{
    if (!mOk) {
        error = "no OSMesa GL 3.0 context";
        return false;
    }
    const std::string key = chain + "\n" + config;
    if (mKept && (!mKeepChain || key != mKeptKey)) {
        mKept->shutdown();
        mKept.reset();
    }
    std::unique_ptr<styles::StyleChain> fresh;
    if (!mKept) {
        StyleSettings settings;
        if (!StyleSettings::parse(chain, config, settings, error)) return false;
        fresh = std::make_unique<styles::StyleChain>();
        if (!fresh->init(settings, &getProc, error)) return false;
    }
    styles::StyleChain& styleChain = mKept ? *mKept : *fresh;
    styleChain.context().textureContent = mTextureContent;
    const styles::GlFunctions& gl = mGl;
    gl.Viewport(0, 0, mWidth, mHeight);
    gl.ClearColor(background.r, background.g, background.b, background.a);
    gl.ClearDepth(1.0);
    // glClear obeys the write masks, and the last chain's styles may have left depth writes
    // off (the compositor restores the program's state after a chain; here nothing would).
    gl.DepthMask(GL_TRUE);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    gl.StencilMask(~0u);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    // What the compositor's held-back draws leave: nothing when the chain has a shading style
    // (it draws the scene's depth), else the program's picture with its depth (here depth only).
    if (!styleChain.hasShading() && !drawDepth(scene, styleChain, error)) return false;
    // The program's glClearColor at the flush, as the compositor reports it.
    styles::Scene cleared = scene;
    cleared.clearColor = background;
    styleChain.render(cleared);
    gl.Finish();
    out.width = mWidth;
    out.height = mHeight;
    out.rgba.resize(size_t(mWidth) * mHeight * 4);
    gl.BindFramebuffer(GL_FRAMEBUFFER, 0);
    gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
    gl.ReadPixels(0, 0, mWidth, mHeight, GL_RGBA, GL_UNSIGNED_BYTE, out.rgba.data());
    out.flipRows();
    if (mKeepChain) {
        if (fresh) mKept = std::move(fresh);
        mKeptKey = key;
    } else {
        styleChain.shutdown();
    }
    return true;
}

reconstruct::Batch sphereBatch(const glm::mat4& modelview, float radius, int slices, int stacks,
                               glm::vec4 color, uint32_t materialId)
{
    reconstruct::Batch b;
    b.mode = GL_TRIANGLES;
    b.modelview = modelview;
    b.materialId = materialId;
    auto point = [&](int i, int j) {
        float theta = glm::pi<float>() * float(j) / float(stacks);
        float phi = 2.0f * glm::pi<float>() * float(i % slices) / float(slices);
        glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                    std::sin(theta) * std::sin(phi));
        reconstruct::Vertex v{};
        v.position = n * radius;
        v.normal = n;
        v.color = color;
        v.hasNormal = true;
        return v;
    };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            reconstruct::Vertex a = point(i, j), c = point(i + 1, j), d = point(i + 1, j + 1),
                                e = point(i, j + 1);
            // Counter-clockwise seen from outside.
            if (j > 0) b.vertices.insert(b.vertices.end(), {a, c, e});
            if (j < stacks - 1) b.vertices.insert(b.vertices.end(), {c, d, e});
        }
    }
    return b;
}

reconstruct::Batch boxBatch(const glm::mat4& modelview, glm::vec3 h, glm::vec4 color,
                            uint32_t materialId)
{
    reconstruct::Batch b;
    b.mode = GL_TRIANGLES;
    b.modelview = modelview;
    b.materialId = materialId;
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 n(0.0f);
            n[axis] = sign;
            glm::vec3 u(0.0f), w(0.0f);
            u[(axis + 1) % 3] = 1.0f;
            w[(axis + 2) % 3] = 1.0f;
            if (sign < 0) std::swap(u, w);
            glm::vec3 corner[4] = {n - u - w, n + u - w, n + u + w, n - u + w};
            reconstruct::Vertex v[4];
            for (int k = 0; k < 4; ++k) {
                v[k] = {};
                v[k].position = corner[k] * h;
                v[k].normal = n;
                v[k].color = color;
                v[k].hasNormal = true;
            }
            b.vertices.insert(b.vertices.end(), {v[0], v[1], v[2], v[0], v[2], v[3]});
        }
    }
    return b;
}

GLuint StyleHarness::nearestTexture(GLint internalFormat, int width, int height, GLenum format,
                                    const uint8_t* texels) const
{
    GLuint id = 0;
    glGenTextures(1, &id);
    mGl.BindTexture(GL_TEXTURE_2D, id);
    mGl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    mGl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    mGl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    mGl.TexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, GL_UNSIGNED_BYTE,
                   texels);
    mGl.PixelStorei(GL_UNPACK_ALIGNMENT, 4);
    mGl.BindTexture(GL_TEXTURE_2D, 0);
    return id;
}

} // namespace nprgl::test
