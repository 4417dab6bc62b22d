#include "render/occlusion_culling.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace washout::render {
namespace {

constexpr int kDepthBuckets = 1 << 16;
constexpr double kPixelMargin = 0.5;  // covers float rounding between this code and the GPU

// Where a sphere lands on a grid of one cell per pixel, and the depths it spans.
struct Footprint {
  double x = 0.0, y = 0.0;  // centre, in pixels
  double reach = 0.0;       // half-size of the square the shader's quad may cover, in pixels
  double core = 0.0;        // radius of a disc surely covered by the sphere, in pixels
  double depth = 0.0;       // distance of the centre in front of the camera
  bool in_front = false;    // wholly in front of the camera plane (else never culled)
};

// Mirrors the vertex shader's quad (sphere_impostor_pass.cpp) so that reach bounds it.
Footprint footprint_of(const SphereInstance& s, const Eigen::Matrix4d& view,
                       const Eigen::Matrix4d& projection, bool orthographic, double radius,
                       int width, int height) {
  const Eigen::Vector4d c = view * Eigen::Vector4d(s.center[0], s.center[1], s.center[2], 1.0);
  const Eigen::Vector4d clip = projection * c;
  Footprint f;
  f.depth = -c.z();
  f.in_front = f.depth - radius > 0.0 && clip.w() > 0.0;
  if (!f.in_front) return f;
  f.x = (clip.x() / clip.w() * 0.5 + 0.5) * width;
  f.y = (clip.y() / clip.w() * 0.5 + 0.5) * height;
  const double pixels_per_unit_at_1 = projection(1, 1) * 0.5 * height;  // same along x
  if (orthographic) {
    f.reach = radius * pixels_per_unit_at_1;
    f.core = f.reach;
  } else {
    const double distance = c.head<3>().norm();
    const double grow = 1.05 * distance / f.depth + 2.0 * radius / (f.depth - radius);
    f.reach = radius * grow * pixels_per_unit_at_1 / (f.depth - radius);
    // The silhouette contains the disc of angular radius r / distance around the centre.
    f.core = 0.95 * radius * pixels_per_unit_at_1 / distance;
  }
  f.reach += kPixelMargin;
  f.core -= kPixelMargin + 0.7072;  // a cell counts only if it lies wholly inside
  return f;
}

}  // namespace

std::size_t cull_hidden_spheres(std::vector<SphereInstance>& spheres, const Camera& camera,
                                double radius, int width, int height) {
  const std::size_t n = spheres.size();
  if (n == 0 || width <= 0 || height <= 0) return 0;
  const Eigen::Matrix4d view = camera.view_matrix();
  const Eigen::Matrix4d projection = camera.projection_matrix();
  const bool orthographic = camera.is_orthographic();

  std::vector<Footprint> prints(n);
  const auto count = static_cast<long long>(n);
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < count; ++i) {
    prints[i] = footprint_of(spheres[i], view, projection, orthographic, radius, width, height);
  }

  // Front to back with a counting sort on depth: linear time and stable, so deterministic.
  double nearest = std::numeric_limits<double>::infinity(), farthest = -nearest;
  for (const Footprint& f : prints) {
    nearest = std::min(nearest, f.depth);
    farthest = std::max(farthest, f.depth);
  }
  const double scale = farthest > nearest ? (kDepthBuckets - 1) / (farthest - nearest) : 0.0;
  auto bucket_of = [&](const Footprint& f) {
    return static_cast<std::size_t>((f.depth - nearest) * scale);
  };
  std::vector<std::size_t> starts(kDepthBuckets + 1, 0);
  for (const Footprint& f : prints) ++starts[bucket_of(f) + 1];
  for (int b = 0; b < kDepthBuckets; ++b) starts[b + 1] += starts[b];
  std::vector<std::uint32_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[starts[bucket_of(prints[i])]++] = static_cast<std::uint32_t>(i);

  // Per pixel: the farthest depth of a sphere whose core covers it (nearest such sphere).
  std::vector<float> covered(static_cast<std::size_t>(width) * height,
                             std::numeric_limits<float>::infinity());
  std::vector<SphereInstance> kept;
  kept.reserve(n);
  for (const std::uint32_t i : order) {
    const Footprint& f = prints[i];
    if (!f.in_front) {
      kept.push_back(spheres[i]);
      continue;
    }
    const int x0 = std::max(0, static_cast<int>(std::floor(f.x - f.reach)));
    const int x1 = std::min(width - 1, static_cast<int>(std::floor(f.x + f.reach)));
    const int y0 = std::max(0, static_cast<int>(std::floor(f.y - f.reach)));
    const int y1 = std::min(height - 1, static_cast<int>(std::floor(f.y + f.reach)));
    if (x0 > x1 || y0 > y1) continue;  // wholly outside the view: nothing would be drawn
    const auto near = static_cast<float>(f.depth - radius);
    bool hidden = true;
    for (int y = y0; y <= y1 && hidden; ++y) {
      const float* row = covered.data() + static_cast<std::size_t>(y) * width;
      for (int x = x0; x <= x1; ++x) {
        if (!(row[x] < near)) {
          hidden = false;
          break;
        }
      }
    }
    if (hidden) continue;
    kept.push_back(spheres[i]);
    if (f.core <= 0.0) continue;
    // Behind the covered pixels nothing can show that lies beyond this sphere's far side.
    const auto far = static_cast<float>(f.depth + radius);
    const double core2 = f.core * f.core;
    const int cx0 = std::max(0, static_cast<int>(std::floor(f.x - f.core)));
    const int cx1 = std::min(width - 1, static_cast<int>(std::floor(f.x + f.core)));
    const int cy0 = std::max(0, static_cast<int>(std::floor(f.y - f.core)));
    const int cy1 = std::min(height - 1, static_cast<int>(std::floor(f.y + f.core)));
    for (int y = cy0; y <= cy1; ++y) {
      const double dy = y + 0.5 - f.y;
      float* row = covered.data() + static_cast<std::size_t>(y) * width;
      for (int x = cx0; x <= cx1; ++x) {
        const double dx = x + 0.5 - f.x;
        if (dx * dx + dy * dy <= core2) row[x] = std::min(row[x], far);
      }
    }
  }
  const std::size_t dropped = n - kept.size();
  spheres.swap(kept);
  return dropped;
}

}  // namespace washout::render
