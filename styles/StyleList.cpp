#include "styles/StyleList.h"

namespace nprgl::styles {

// Each module defines its StyleInfo factory in its own file.
StyleInfo toonStyleInfo();

const char* const kDefaultChain = "none";

void registerStyles(std::vector<StyleInfo>& out)
{
    out.push_back(toonStyleInfo());
}

} // namespace nprgl::styles
