#pragma once

#include "styles/StyleRegistry.h"

#include <vector>

namespace nprgl::styles {

// The chain used when none is named.
extern const char* const kDefaultChain;

// Adds every style module's StyleInfo (name, parameters, role, factory), in the order
// `nprgl styles` lists them.
void registerStyles(std::vector<StyleInfo>& out);

} // namespace nprgl::styles
