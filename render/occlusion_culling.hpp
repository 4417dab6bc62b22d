#pragma once
// Leaves out spheres that are certainly hidden behind nearer ones, before OpenGL sees them.
// Writing per-fragment depth turns off llvmpipe's early depth test, so every sphere drawn is
// fully shaded even when hidden; in a dense 3D block most are. The test is conservative: a
// sphere is dropped only when every pixel its quad could touch is already covered by a nearer
// sphere's solid core, so the image is the same as drawing everything.
#include <cstddef>
#include <vector>

#include "render/camera.hpp"
#include "render/sphere_impostor_pass.hpp"

namespace washout::render {

// Keeps, in place, the spheres that may be visible in a width x height pixel view, ordered
// front to back. Returns how many were dropped.
std::size_t cull_hidden_spheres(std::vector<SphereInstance>& spheres, const Camera& camera,
                                double radius, int width, int height);

}  // namespace washout::render
