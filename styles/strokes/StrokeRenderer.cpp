#include "styles/strokes/StrokeRenderer.h"

#include "reconstruct/Silhouette.h"

namespace nprgl::styles::strokes {

bool StrokeRenderer::init(const GlFunctions& gl, std::string& error)
{
    return mDrawer.init(gl, error) && mQueryVisibility.init(gl, error);
}

void StrokeRenderer::destroy(const GlFunctions& gl)
{
    mDrawer.destroy(gl);
    mQueryVisibility.destroy(gl);
}

void StrokeRenderer::setTexture(const GlFunctions& gl, const PngImage& image)
{
    mDrawer.setTexture(gl, image);
}

void StrokeRenderer::render(const Scene& scene, const GlFunctions& gl, Options options)
{
    const glm::ivec4 viewport = scene.viewport;
    if (scene.objects.empty() || viewport.z <= 0 || viewport.w <= 0) return;
    const bool zbuffer = options.visibility == Visibility::ZBuffer;
    options.paint.biasedDepth = zbuffer;
    options.draw.depthTest = zbuffer;

    DepthImage depthImage;
    if (options.visibility == Visibility::Depth) {
        // One read-back for the whole frame, into a buffer kept between frames.
        mDepth.resize(size_t(viewport.z) * size_t(viewport.w));
        gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
        gl.PixelStorei(GL_PACK_ROW_LENGTH, 0);
        gl.PixelStorei(GL_PACK_SKIP_ROWS, 0);
        gl.PixelStorei(GL_PACK_SKIP_PIXELS, 0);
        gl.ReadPixels(viewport.x, viewport.y, viewport.z, viewport.w, GL_DEPTH_COMPONENT, GL_FLOAT,
                      mDepth.data());
        depthImage = {mDepth.data(), viewport.x, viewport.y, viewport.z, viewport.w};
    }

    mVertices.clear();
    // Window depths in the program's depth range, as the depth read back holds them: the
    // projector's z (0.5 ndc + 0.5) becomes near + (far - near) (0.5 ndc + 0.5).
    glm::mat4 toRange(1.0f);
    const float nearZ = scene.depthRange.x, farZ = scene.depthRange.y;
    toRange[2][2] = farZ - nearZ;
    toRange[3][2] = farZ + nearZ - 1.0f;
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        const reconstruct::ObjectMesh& mesh = *object.mesh;
        mExtractor.extract(mesh, reconstruct::eyeInObjectSpace(object.modelview), options.extract,
                           mChains);
        if (mChains.chainCount() == 0) continue;
        mProjector.project(mesh, mChains, object.modelview, toRange * object.projection, viewport,
                           options.depthTolerance, mLines);
        if (zbuffer) {
            for (uint8_t& s : mLines.state)
                if (s == kUnknown) s = kVisible;
        } else if (options.visibility == Visibility::Depth) {
            mDepthVisibility.classify(mesh, depthImage, options.depth, mLines);
        } else {
            mQueryVisibility.classify(gl, mesh, viewport, options.query, mLines);
        }
        mSimplifier.simplify(mLines);
        mSimplifier.removeFolds(mLines, options.foldLength);
        mBuilder.build(mLines, options.build, mStrokes);
        if (mStrokes.points.empty()) continue;

        StrokePainter::Options paint = options.paint;
        if (paint.widthMode == StrokePainter::WidthMode::Depth && paint.depthReference <= 0.0f) {
            if (mAutoReference <= 0.0f) {
                double sum = 0.0;
                for (const ChainPoint& p : mStrokes.points)
                    sum += p.w;
                mAutoReference = float(sum / double(mStrokes.points.size()));
            }
            paint.depthReference = mAutoReference;
        }
        StrokePainter::View view;
        view.modelview = object.modelview;
        view.projection = object.projection;
        view.viewport = viewport;
        view.lightDir = object.lightDir;
        mPainter.paint(mesh, mStrokes, view, paint, mJitter, mVertices);
    }
    mJitter.endFrame();
    if (mVertices.empty()) return;
    gl.Viewport(viewport.x, viewport.y, viewport.z, viewport.w);
    mDrawer.draw(gl, mVertices, options.draw);
}

} // namespace nprgl::styles::strokes
