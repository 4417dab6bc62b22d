#pragma once
// Lighting of the particle spheres: ambient + Lambert diffuse + Blinn-Phong highlight, with one
// white light in camera space coming from the upper left, behind the viewer. The fragment
// shader receives these constants; the C++ mirror lets tests predict a sphere's centre colour.
#include "render/image.hpp"

namespace washout::render {

struct SphereShading {
  double light_direction[3];  // camera space, towards the light (normalised where used)
  double ambient;
  double diffuse;
  double specular;
  double shininess;
};

inline constexpr SphereShading kSphereShading = {{-0.35, 0.55, 0.76}, 0.35, 0.75, 0.25, 32.0};

// Colour of the point of a sphere that faces the viewer (normal along the view direction).
Rgb8 shade_sphere_center(Rgb8 base);

}  // namespace washout::render
