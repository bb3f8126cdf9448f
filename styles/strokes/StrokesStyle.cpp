#include "styles/strokes/StrokesStyle.h"

#include "common/Log.h"
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
    return mRenderer.init(ctx.gl, error);
}

void StrokesStyle::shutdown(StyleContext& ctx)
{
    mRenderer.destroy(ctx.gl);
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
    mRenderer.setTexture(ctx.gl, mTextureImage);
}

void StrokesStyle::render(const Scene& scene, StyleContext& ctx)
{
    auto param = [&](const char* name) { return ctx.param(kName, name); };
    const int renderer = int(param("renderer"));
    strokes::StrokeRenderer::Options o;
    o.visibility = param("zbuffer") != 0.0 ? strokes::StrokeRenderer::Visibility::ZBuffer
                   : int(param("visibility")) == kDepth
                       ? strokes::StrokeRenderer::Visibility::Depth
                       : strokes::StrokeRenderer::Visibility::Query;
    o.extract.creases = param("creases") != 0.0;
    o.extract.borders = param("borders") != 0.0;
    o.depthTolerance = float(param("depth_tolerance"));
    o.depth.radius = int(param("depth_radius"));
    o.query.visibleThreshold = float(param("visible_threshold"));
    o.query.invisibleThreshold =
        std::min(float(param("invisible_threshold")), o.query.visibleThreshold);
    o.query.iterations = int(param("query_iterations"));
    o.query.lineWidth = float(param("query_width"));
    o.build.maxAngle = float(param("max_angle"));
    o.build.maxSegments = uint32_t(param("max_segments"));
    o.build.maxLength = float(param("max_length"));
    o.build.minLength = float(param("min_length"));
    o.foldLength = float(param("fold_length"));

    strokes::StrokePainter::Options& paint = o.paint;
    paint.widthMode = strokes::StrokePainter::WidthMode(int(param("width_mode")));
    paint.width = float(param("width"));
    paint.minWidth = float(param("min_width"));
    paint.maxWidth = std::max(float(param("max_width")), paint.minWidth);
    paint.widthScale = float(param("width_scale"));
    paint.depthReference = float(param("depth_reference"));
    const int passes = int(param("passes"));
    paint.passes = uint32_t(passes > 0 ? passes : renderer == kSketchy ? 3 : 1);
    paint.jitter = renderer == kSketchy || paint.passes > 1 ? float(param("jitter")) : 0.0f;
    paint.jitterMode = strokes::StrokePainter::JitterMode(int(param("jitter_mode")));
    paint.seed = uint32_t(param("seed"));
    // Passes share the opacity: overlapping passes add up to about `opacity`.
    const float opacity = float(param("opacity"));
    paint.opacity = 1.0f - std::pow(1.0f - std::min(opacity, 0.999f), 1.0f / float(paint.passes));

    strokes::StrokeDrawer::Options& draw = o.draw;
    draw.textured = renderer == kTextured;
    if (draw.textured) updateTexture(ctx);
    const float lightness = float(param("lightness"));
    // Grey on a light page by lightness; on a dark one the page's light ink.
    draw.color = glm::vec4(ctx.page.line(glm::vec3(0.0f), lightness), 1.0f);
    draw.capLength = float(param("cap_length"));
    draw.tileLength = float(param("tile_length"));
    draw.u1 = float(param("texture_u1"));
    draw.u2 = std::max(float(param("texture_u2")), draw.u1);
    mRenderer.render(scene, ctx.gl, o);
}

} // namespace nprgl::styles
