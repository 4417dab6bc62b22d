#pragma once
// Fixed colours of a frame. Walls are neutral grey and rigid bodies magenta so that neither
// can be mistaken for a value of the fluid colour map (render/color_map.hpp).
#include "render/image.hpp"

namespace washout::render {

inline constexpr Rgb8 kBackgroundColor = {248, 248, 248};
inline constexpr Rgb8 kTextColor = {25, 25, 25};
inline constexpr Rgb8 kWallColor = {150, 150, 150};      // kinds 1 (fixed) and 2 (moving)
inline constexpr Rgb8 kRigidBodyColor = {200, 60, 190};  // kind 3

}  // namespace washout::render
