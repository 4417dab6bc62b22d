#pragma once
// Draws particles as lit spheres with one camera-facing quad each: the fragment shader casts the
// view ray at the sphere, discards the quad's corners, writes the true depth of the hit (so
// intersecting spheres cut each other correctly) and shades it (render/sphere_shading.hpp).
// Needs a current OpenGL 3.3 core context for its whole life.
#include <cstdint>
#include <vector>

#include "render/camera.hpp"

namespace washout::render {

// 16 bytes, read by the shader as one RGBA32UI texel.
struct SphereInstance {
  float center[3];  // world position minus camera.origin()
  std::uint8_t color[4];
};
static_assert(sizeof(SphereInstance) == 16);

class SphereImpostorPass {
 public:
  SphereImpostorPass();  // compiles the shaders; throws ContextError on failure
  ~SphereImpostorPass();
  SphereImpostorPass(const SphereImpostorPass&) = delete;
  SphereImpostorPass& operator=(const SphereImpostorPass&) = delete;

  void draw(const std::vector<SphereInstance>& spheres, const Camera& camera, double radius);

 private:
  unsigned orthographic_program_ = 0, perspective_program_ = 0;
  unsigned vertex_array_ = 0, instance_buffer_ = 0, instance_texture_ = 0;
  int max_spheres_ = 0;            // texels a buffer texture may hold
  long long buffer_capacity_ = 0;  // bytes allocated in instance_buffer_
};

}  // namespace washout::render
