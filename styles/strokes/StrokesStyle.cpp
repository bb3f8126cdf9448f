#include "styles/strokes/StrokesStyle.h"

#include "common/Log.h"
#include "reconstruct/Silhouette.h"
#include "styles/StyleRegistry.h"
#include "styles/strokes/StrokeTexture.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles {

namespace {

constexpr const char* kName = "strokes";

enum Renderer { kSketchy = 0, kTextured = 1 };
enum Visibility { kQuery = 0, kDepth = 1 };

std::unique_ptr<Style> create() { return std::make_unique<StrokesStyle>(); }

} // namespace

StyleInfo strokesStyleInfo()
{
    StyleInfo info;
    info.name = kName;
    info.summary = "geometric strokes: silhouettes chained, visibility-tested and drawn as "
                   "sketchy or textured strokes (thesis 4.4)";
    info.role = StyleRole::Outline;
    info.create = &create;
    info.params = {
        ParamInfo::choice("renderer", "sketchy: overdrawn jittered lines; textured: strokes "
                          "with a pencil/ink/brush/chalk texture", {"sketchy", "textured"},
                          kTextured),
        ParamInfo::choice("visibility", "query: occlusion queries per segment with "
                          "refinement (thesis 4.4.4); depth: one depth read-back, sampled "
                          "along each segment (faster)", {"query", "depth"}, kDepth),
        ParamInfo::flag("zbuffer", "skip the visibility stage and depth-test the strokes "
                        "against the scene instead (crisper, clips wide lines)", false),
        ParamInfo::flag("creases", "also draw crease edges (sharp folds)", true),
        ParamInfo::flag("borders", "also draw border edges (rims of open surfaces)", true),
        ParamInfo::number("depth_tolerance", "a surface this fraction of the line's eye "
                          "distance in front of it does not hide it", 0.01, 0.0, 0.25),
        ParamInfo::number("depth_radius", "depth visibility: pixels around each sample "
                          "searched for the far side of a silhouette", 1, 0, 4),
        ParamInfo::number("visible_threshold", "query visibility t_vis: V_r at or above it "
                          "is visible", 0.4, 0.0, 1.0),
        ParamInfo::number("invisible_threshold", "query visibility t_invis: V_r at or below "
                          "it is hidden", 0.1, 0.0, 1.0),
        ParamInfo::number("query_iterations", "query visibility: times an ambiguous segment "
                          "is split and tested again", 3, 0, 8),
        ParamInfo::number("query_width", "query visibility: width in pixels of the test "
                          "lines", 3, 1, 10),
        ParamInfo::number("max_angle", "a stroke ends where it turns by more than this "
                          "(degrees on screen)", 60, 0, 180),
        ParamInfo::number("max_segments", "a stroke has at most this many segments "
                          "(0: no limit)", 0, 0, 100000),
        ParamInfo::number("max_length", "a stroke is at most this long in pixels "
                          "(0: no limit)", 0, 0, 100000),
        ParamInfo::number("min_length", "strokes shorter than this (pixels) are left out: "
                          "specks where a hidden line peeks out", 4, 0, 100),
        ParamInfo::number("fold_length", "silhouette zig-zags shorter than this (pixels) "
                          "that turn back on themselves are cut out (0: keep)", 6, 0, 50),
        ParamInfo::choice("width_mode", "fixed: width pixels; depth: nearer is wider, "
                          "clamped to min/max_width; stroke: grows from min to max_width "
                          "along a stroke; light: thin where lit, thick in shadow",
                          {"fixed", "depth", "stroke", "light"}, 0),
        ParamInfo::number("width", "line width in pixels", 3, 0.25, 32),
        ParamInfo::number("min_width", "smallest width (depth, stroke and light modes)", 1.2,
                          0.25, 32),
        ParamInfo::number("max_width", "largest width (depth, stroke and light modes)", 3.5,
                          0.25, 32),
        ParamInfo::number("width_scale", "stroke mode: width grows by this factor per "
                          "segment", 1.25, 1.0, 4.0),
        ParamInfo::number("depth_reference", "depth mode: eye distance (clip w) drawn at "
                          "width; 0: the first frame's mean", 0, 0, 1e9),
        ParamInfo::number("passes", "times each stroke is drawn (overdraw); 0: 3 for "
                          "sketchy, 1 for textured", 0, 0, 8),
        ParamInfo::number("jitter", "overdraw wobble in pixels (sketchy, and textured with "
                          "passes > 1)", 0.9, 0, 16),
        ParamInfo::choice("jitter_mode", "random: all three axes; normal: outwards only "
                          "along the edge normal (for zbuffer)", {"random", "normal"}, 0),
        ParamInfo::number("seed", "seed of the precomputed per-vertex jitter", 1, 0, 1e6),
        ParamInfo::number("lightness", "stroke colour: 0 black .. 1 white", 0.08, 0.0, 1.0),
        ParamInfo::number("opacity", "overall stroke opacity (shared by the passes)", 0.9,
                          0.0, 1.0),
        ParamInfo::choice("texture", "procedural stroke texture (textured renderer)",
                          {"pencil", "ink", "brush", "chalk"}, 0),
        ParamInfo::text("texture_file", "a PNG stroke texture instead of the procedural one: "
                        "start cap, tiling middle (u1..u2), end cap along x"),
        ParamInfo::number("texture_u1", "where the texture's tiling middle starts (u)", 0.25,
                          0.0, 1.0),
        ParamInfo::number("texture_u2", "where the texture's tiling middle ends (u)", 0.75,
                          0.0, 1.0),
        ParamInfo::number("cap_length", "pixels over which the texture's start and end caps "
                          "are drawn", 18, 0, 500),
        ParamInfo::number("tile_length", "pixels per repeat of the texture's middle", 96, 4,
                          4000),
    };
    return info;
}

bool StrokesStyle::init(StyleContext& ctx, std::string& error)
{
    if (!mDrawer.init(ctx.gl, error)) return false;
    if (!mQueryVisibility.init(ctx.gl, error)) return false;
    return true;
}

void StrokesStyle::shutdown(StyleContext& ctx)
{
    mDrawer.destroy(ctx.gl);
    mQueryVisibility.destroy(ctx.gl);
    mTextureKey.clear();
}

void StrokesStyle::updateTexture(StyleContext& ctx)
{
    const std::string file = ctx.text(kName, "texture_file");
    const int kind = int(ctx.param(kName, "texture"));
    std::string key = file.empty() ? "kind:" + std::to_string(kind) : "file:" + file;
    if (key == mTextureKey) return;
    mTextureKey = key;
    bool loaded = false;
    if (!file.empty()) {
        std::string error;
        loaded = strokes::StrokeTexture::load(file, mTextureImage, error);
        if (!loaded)
            NPRGL_ERROR("strokes.texture_file: %s; using the procedural texture instead",
                        error.c_str());
    }
    if (!loaded)
        strokes::StrokeTexture::generate(strokes::StrokeTexture::Kind(kind), mTextureImage);
    mDrawer.setTexture(ctx.gl, mTextureImage);
}

void StrokesStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    auto param = [&](const char* name) { return ctx.param(kName, name); };
    const int renderer = int(param("renderer"));
    const bool zbuffer = param("zbuffer") != 0.0;
    const int visibility = int(param("visibility"));
    const glm::ivec4 viewport = scene.viewport;
    if (scene.objects.empty() || viewport.z <= 0 || viewport.w <= 0) return;

    strokes::DepthImage depthImage;
    if (!zbuffer && visibility == kDepth) {
        // One read-back for the whole frame, into a buffer kept between frames.
        mDepth.resize(size_t(viewport.z) * size_t(viewport.w));
        gl.BindBuffer(GL_PIXEL_PACK_BUFFER, 0);
        gl.PixelStorei(GL_PACK_ALIGNMENT, 4);
        gl.PixelStorei(GL_PACK_ROW_LENGTH, 0);
        gl.PixelStorei(GL_PACK_SKIP_ROWS, 0);
        gl.PixelStorei(GL_PACK_SKIP_PIXELS, 0);
        gl.ReadPixels(viewport.x, viewport.y, viewport.z, viewport.w, GL_DEPTH_COMPONENT,
                      GL_FLOAT, mDepth.data());
        depthImage = {mDepth.data(), viewport.x, viewport.y, viewport.z, viewport.w};
    }

    strokes::ChainExtractor::Options extract;
    extract.creases = param("creases") != 0.0;
    extract.borders = param("borders") != 0.0;
    const float tolerance = float(param("depth_tolerance"));
    strokes::DepthVisibility::Options depthOptions;
    depthOptions.radius = int(param("depth_radius"));
    strokes::QueryVisibility::Options queryOptions;
    queryOptions.visibleThreshold = float(param("visible_threshold"));
    queryOptions.invisibleThreshold =
        std::min(float(param("invisible_threshold")), queryOptions.visibleThreshold);
    queryOptions.iterations = int(param("query_iterations"));
    queryOptions.lineWidth = float(param("query_width"));
    strokes::StrokeBuilder::Options build;
    build.maxAngle = float(param("max_angle"));
    build.maxSegments = uint32_t(param("max_segments"));
    build.maxLength = float(param("max_length"));
    build.minLength = float(param("min_length"));
    const float foldLength = float(param("fold_length"));

    strokes::StrokePainter::Options paint;
    paint.widthMode = strokes::StrokePainter::WidthMode(int(param("width_mode")));
    paint.width = float(param("width"));
    paint.minWidth = float(param("min_width"));
    paint.maxWidth = std::max(float(param("max_width")), paint.minWidth);
    paint.widthScale = float(param("width_scale"));
    const int passes = int(param("passes"));
    paint.passes = uint32_t(passes > 0 ? passes : renderer == kSketchy ? 3 : 1);
    paint.jitter = renderer == kSketchy || paint.passes > 1 ? float(param("jitter")) : 0.0f;
    paint.jitterMode = strokes::StrokePainter::JitterMode(int(param("jitter_mode")));
    paint.seed = uint32_t(param("seed"));
    // Passes share the opacity: overlapping passes add up to about `opacity`.
    const float opacity = float(param("opacity"));
    paint.opacity = 1.0f - std::pow(1.0f - std::min(opacity, 0.999f), 1.0f / float(paint.passes));
    paint.biasedDepth = zbuffer;

    mVertices.clear();
    for (const SceneObject& object : scene.objects) {
        if (!object.mesh) continue;
        const reconstruct::ObjectMesh& mesh = *object.mesh;
        mExtractor.extract(mesh, reconstruct::eyeInObjectSpace(object.modelview), extract,
                           mChains);
        if (mChains.chainCount() == 0) continue;
        mProjector.project(mesh, mChains, object.modelview, object.projection, viewport,
                           tolerance, mLines);
        if (zbuffer) {
            for (uint8_t& s : mLines.state)
                if (s == strokes::kUnknown) s = strokes::kVisible;
        } else if (visibility == kDepth) {
            mDepthVisibility.classify(mesh, depthImage, depthOptions, mLines);
        } else {
            mQueryVisibility.classify(gl, mesh, viewport, queryOptions, mLines);
        }
        mSimplifier.simplify(mLines);
        mSimplifier.removeFolds(mLines, foldLength);
        mBuilder.build(mLines, build, mStrokes);
        if (mStrokes.points.empty()) continue;

        paint.depthReference = float(param("depth_reference"));
        if (paint.widthMode == strokes::StrokePainter::WidthMode::Depth &&
            paint.depthReference <= 0.0f) {
            if (mAutoReference <= 0.0f) {
                double sum = 0.0;
                for (const strokes::ChainPoint& p : mStrokes.points) sum += p.w;
                mAutoReference = float(sum / double(mStrokes.points.size()));
            }
            paint.depthReference = mAutoReference;
        }
        strokes::StrokePainter::View view;
        view.modelview = object.modelview;
        view.projection = object.projection;
        view.viewport = viewport;
        view.lightDir = object.lightDir;
        mPainter.paint(mesh, mStrokes, view, paint, mJitter, mVertices);
    }
    mJitter.endFrame();
    if (mVertices.empty()) return;

    strokes::StrokeDrawer::Options draw;
    draw.textured = renderer == kTextured;
    if (draw.textured) updateTexture(ctx);
    draw.depthTest = zbuffer;
    const float lightness = float(param("lightness"));
    draw.color = glm::vec4(lightness, lightness, lightness, 1.0f);
    draw.capLength = float(param("cap_length"));
    draw.tileLength = float(param("tile_length"));
    draw.u1 = float(param("texture_u1"));
    draw.u2 = std::max(float(param("texture_u2")), draw.u1);
    gl.Viewport(viewport.x, viewport.y, viewport.z, viewport.w);
    mDrawer.draw(gl, mVertices, draw);
}

} // namespace nprgl::styles
