#include "render/sphere_shading.hpp"

#include <algorithm>
#include <cmath>

namespace washout::render {

Rgb8 shade_sphere_center(Rgb8 base) {
  const SphereShading& s = kSphereShading;
  const double* l = s.light_direction;
  const double length = std::sqrt(l[0] * l[0] + l[1] * l[1] + l[2] * l[2]);
  const double n_dot_l = std::max(l[2] / length, 0.0);
  // Half vector between the light and the viewer (0, 0, 1).
  const double hx = l[0] / length, hy = l[1] / length, hz = l[2] / length + 1.0;
  const double n_dot_h = hz / std::sqrt(hx * hx + hy * hy + hz * hz);
  const double highlight = s.specular * std::pow(n_dot_h, s.shininess);
  const double factor = s.ambient + s.diffuse * n_dot_l;
  auto channel = [&](std::uint8_t c) {
    const double v = std::clamp(c / 255.0 * factor + highlight, 0.0, 1.0);
    return static_cast<std::uint8_t>(std::lround(v * 255.0));
  };
  return {channel(base.r), channel(base.g), channel(base.b)};
}

}  // namespace washout::render
