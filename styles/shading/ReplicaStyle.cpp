#include "styles/shading/ReplicaStyle.h"

#include "styles/StyleRegistry.h"

namespace nprgl::styles {

namespace {

std::unique_ptr<Style> create() { return std::make_unique<ReplicaStyle>(); }

} // namespace

StyleInfo replicaStyleInfo()
{
    StyleInfo info;
    info.name = "replica";
    info.summary = "the scene as GL draws it, from what nprgl tracked (no NPR): the oracle "
                   "`nprgl compare` measures against the program's own frames";
    info.role = StyleRole::Shading;
    info.programLighting = true;
    info.create = &create;
    return info;
}

bool ReplicaStyle::init(StyleContext& ctx, std::string& error)
{
    return mPlain.init(ctx.gl, error);
}

void ReplicaStyle::render(const Scene& scene, StyleContext& ctx) { mPlain.render(scene, ctx); }

void ReplicaStyle::shutdown(StyleContext& ctx) { mPlain.shutdown(ctx.gl); }

} // namespace nprgl::styles
