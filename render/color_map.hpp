#pragma once
// The colour map for fluid fields: blue (low) -> cyan -> green -> yellow -> orange -> red (high).
// Seven anchor colours, linear interpolation in sRGB. Both ends are dark so that the extremes
// stand out against the light background; it contains no grey and no magenta, which are kept
// for walls and rigid bodies. See docs/render.md.
#include "render/image.hpp"

namespace washout::render {

// t is clamped to [0, 1]; NaN maps to the low end.
Rgb8 color_map(double t);

inline Rgb8 color_map_low() { return color_map(0.0); }
inline Rgb8 color_map_high() { return color_map(1.0); }

}  // namespace washout::render
