#pragma once

namespace nprgl::cli {

// Prints every style with its parameters, defaults and ranges to stdout.
int listStyles();

} // namespace nprgl::cli
