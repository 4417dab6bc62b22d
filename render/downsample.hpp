#pragma once
// Turns the supersampled OpenGL buffer into the final image: averages factor x factor blocks
// (a box filter, which is what smooths the sphere edges) and flips rows to top-first order.
#include <cstdint>

#include "render/image.hpp"

namespace washout::render {

// rgba: width*factor x height*factor pixels, bottom row first. Alpha is ignored.
Image downsample_rgba(const std::uint8_t* rgba, int width, int height, int factor);

}  // namespace washout::render
