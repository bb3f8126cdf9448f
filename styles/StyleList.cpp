#include "styles/StyleList.h"

namespace nprgl::styles {

// Each module defines its StyleInfo factory in its own file.
StyleInfo toonStyleInfo();
StyleInfo strokesStyleInfo();
StyleInfo wireframeStyleInfo();
StyleInfo perpixelStyleInfo();
StyleInfo edgesStyleInfo();
StyleInfo texturedStyleInfo();
StyleInfo halftoneStyleInfo();
StyleInfo paperStyleInfo();
StyleInfo goochStyleInfo();
StyleInfo depthcueStyleInfo();
StyleInfo blueprintStyleInfo();
StyleInfo pencilStyleInfo();
StyleInfo motionStyleInfo();
StyleInfo coverageStyleInfo();
StyleInfo xtoonStyleInfo();
StyleInfo replicaStyleInfo();
StyleInfo idsStyleInfo();

const char* const kDefaultChain = "toon+paper+edges";

void registerStyles(std::vector<StyleInfo>& out)
{
    out.push_back(toonStyleInfo());
    out.push_back(strokesStyleInfo());
    out.push_back(wireframeStyleInfo());
    out.push_back(perpixelStyleInfo());
    out.push_back(edgesStyleInfo());
    out.push_back(texturedStyleInfo());
    out.push_back(halftoneStyleInfo());
    out.push_back(paperStyleInfo());
    out.push_back(goochStyleInfo());
    out.push_back(xtoonStyleInfo());
    out.push_back(depthcueStyleInfo());
    out.push_back(blueprintStyleInfo());
    out.push_back(pencilStyleInfo());
    out.push_back(motionStyleInfo());
    out.push_back(coverageStyleInfo());
    out.push_back(replicaStyleInfo());
    out.push_back(idsStyleInfo());
}

} // namespace nprgl::styles
