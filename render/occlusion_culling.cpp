#include "render/occlusion_culling.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace washout::render {
namespace {

constexpr int kDepthBuckets = 1 << 16;
constexpr double kPixelMargin = 0.1;  // covers float rounding between this code and the GPU

using Footprint = OcclusionCuller::Footprint;

// Mirrors the vertex shader's quad (sphere_impostor_pass.cpp) so that reach bounds it.
Footprint footprint_of(const SphereInstance& s, const Eigen::Matrix4d& view,
                       const Eigen::Matrix4d& projection, bool orthographic, double radius,
                       int width, int height) {
  const Eigen::Vector4d c = view * Eigen::Vector4d(s.center[0], s.center[1], s.center[2], 1.0);
  const Eigen::Vector4d clip = projection * c;
  Footprint f;
  const double depth = -c.z();
  f.depth = static_cast<float>(depth);
  f.in_front = depth - radius > 0.0 && clip.w() > 0.0;
  if (!f.in_front) return f;
  f.x = static_cast<float>((clip.x() / clip.w() * 0.5 + 0.5) * width);
  f.y = static_cast<float>((clip.y() / clip.w() * 0.5 + 0.5) * height);
  const double pixels_per_unit_at_1 = projection(1, 1) * 0.5 * height;  // same along x
  double reach = 0.0, core = 0.0;
  if (orthographic) {
    reach = core = radius * pixels_per_unit_at_1;
  } else {
    const double distance = c.head<3>().norm();
    const double grow = 1.05 * distance / depth + 2.0 * radius / (depth - radius);
    reach = radius * grow * pixels_per_unit_at_1 / (depth - radius);
    // The silhouette contains the disc of angular radius r / distance around the centre.
    core = 0.95 * radius * pixels_per_unit_at_1 / distance;
  }
  f.reach = static_cast<float>(reach + kPixelMargin);
  f.core = static_cast<float>(core - kPixelMargin - 0.7072);  // cells wholly inside only
  return f;
}

}  // namespace

std::size_t OcclusionCuller::cull(std::vector<SphereInstance>& spheres, const Camera& camera,
                                  double radius, int width, int height) {
  const std::size_t n = spheres.size();
  if (n == 0 || width <= 0 || height <= 0) return 0;
  const Eigen::Matrix4d view = camera.view_matrix();
  const Eigen::Matrix4d projection = camera.projection_matrix();
  const bool orthographic = camera.is_orthographic();

  prints_.resize(n);
  const auto count = static_cast<long long>(n);
#pragma omp parallel for schedule(static)
  for (long long i = 0; i < count; ++i) {
    prints_[i] = footprint_of(spheres[i], view, projection, orthographic, radius, width, height);
  }

  // Front to back with a counting sort on depth: linear time and stable, so deterministic.
  float nearest = std::numeric_limits<float>::infinity(), farthest = -nearest;
  for (const Footprint& f : prints_) {
    nearest = std::min(nearest, f.depth);
    farthest = std::max(farthest, f.depth);
  }
  const double scale =
      farthest > nearest ? (kDepthBuckets - 1) / (double(farthest) - nearest) : 0.0;
  auto bucket_of = [&](const Footprint& f) {
    return static_cast<std::size_t>((double(f.depth) - nearest) * scale);
  };
  bucket_starts_.assign(kDepthBuckets + 1, 0);
  for (const Footprint& f : prints_) ++bucket_starts_[bucket_of(f) + 1];
  for (int b = 0; b < kDepthBuckets; ++b) bucket_starts_[b + 1] += bucket_starts_[b];
  order_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    order_[bucket_starts_[bucket_of(prints_[i])]++] = static_cast<std::uint32_t>(i);
  }

  // Per pixel: the farthest depth of a sphere whose core covers it (nearest such sphere).
  covered_.assign(static_cast<std::size_t>(width) * height, std::numeric_limits<float>::infinity());
  kept_.clear();
  kept_.reserve(n);
  for (const std::uint32_t i : order_) {
    const Footprint& f = prints_[i];
    if (!f.in_front) {
      kept_.push_back(spheres[i]);
      continue;
    }
    const int x0 = std::max(0, static_cast<int>(std::floor(f.x - f.reach)));
    const int x1 = std::min(width - 1, static_cast<int>(std::floor(f.x + f.reach)));
    const int y0 = std::max(0, static_cast<int>(std::floor(f.y - f.reach)));
    const int y1 = std::min(height - 1, static_cast<int>(std::floor(f.y + f.reach)));
    if (x0 > x1 || y0 > y1) continue;  // wholly outside the view: nothing would be drawn
    // Only pixels whose cell meets the disc of radius reach can receive the sphere's
    // fragments (the shader discards the quad's corners).
    const auto near = static_cast<float>(f.depth - radius);
    const double fx = f.x, fy = f.y, reach2 = double(f.reach) * f.reach;
    bool hidden = true;
    for (int y = y0; y <= y1 && hidden; ++y) {
      const double dy = std::max({0.0, y - fy, fy - (y + 1.0)});  // to the nearest point
      const float* row = covered_.data() + static_cast<std::size_t>(y) * width;
      for (int x = x0; x <= x1; ++x) {
        const double dx = std::max({0.0, x - fx, fx - (x + 1.0)});
        if (dx * dx + dy * dy > reach2) continue;
        if (!(row[x] < near)) {
          hidden = false;
          break;
        }
      }
    }
    if (hidden) continue;
    kept_.push_back(spheres[i]);
    if (f.core <= 0.0) continue;
    // Behind the covered pixels nothing can show that lies beyond this sphere's far side.
    const auto far = static_cast<float>(f.depth + radius);
    const double core2 = double(f.core) * f.core;
    const int cx0 = std::max(0, static_cast<int>(std::floor(f.x - f.core)));
    const int cx1 = std::min(width - 1, static_cast<int>(std::floor(f.x + f.core)));
    const int cy0 = std::max(0, static_cast<int>(std::floor(f.y - f.core)));
    const int cy1 = std::min(height - 1, static_cast<int>(std::floor(f.y + f.core)));
    for (int y = cy0; y <= cy1; ++y) {
      const double dy = y + 0.5 - fy;
      float* row = covered_.data() + static_cast<std::size_t>(y) * width;
      for (int x = cx0; x <= cx1; ++x) {
        const double dx = x + 0.5 - fx;
        if (dx * dx + dy * dy <= core2) row[x] = std::min(row[x], far);
      }
    }
  }
  const std::size_t dropped = n - kept_.size();
  spheres.swap(kept_);  // the old vector becomes next frame's work buffer
  return dropped;
}

}  // namespace washout::render
