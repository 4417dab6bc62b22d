#pragma once
// Leaves out spheres that are certainly hidden behind nearer ones, before OpenGL sees them.
// Writing per-fragment depth turns off llvmpipe's early depth test, so every sphere drawn is
// fully shaded even when hidden; in a dense 3D block most are. The test is conservative: a
// sphere is dropped only when every pixel its quad could touch is already covered by a nearer
// sphere's solid core, so the image is the same as drawing everything.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/camera.hpp"
#include "render/sphere_impostor_pass.hpp"

namespace washout::render {

class OcclusionCuller {
 public:
  // Keeps, in place, the spheres that may be visible in a width x height pixel view, ordered
  // front to back. Returns how many were dropped. Work buffers are kept for the next frame.
  std::size_t cull(std::vector<SphereInstance>& spheres, const Camera& camera, double radius,
                   int width, int height);

  // Where a sphere lands on a grid of one cell per pixel, and the depths it spans.
  struct Footprint {
    float x = 0, y = 0;     // centre, in pixels
    float reach = 0;        // radius of the disc the shader's quad may draw into, in pixels
    float core = 0;         // radius of a disc surely covered by the sphere, in pixels
    float depth = 0;        // distance of the centre in front of the camera
    bool in_front = false;  // wholly in front of the camera plane (else never culled)
  };

 private:
  std::vector<Footprint> prints_;
  std::vector<std::uint32_t> bucket_starts_;
  std::vector<std::uint32_t> order_;
  std::vector<float> covered_;
  std::vector<SphereInstance> kept_;
};

}  // namespace washout::render
