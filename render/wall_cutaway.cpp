#include "render/wall_cutaway.hpp"

#include <cmath>

namespace washout::render {
namespace {
// The view must run along an axis at least this much (cosine) for its near walls to go.
constexpr double kMinAlignment = 0.25;
}  // namespace

WallCutaway::WallCutaway(const Camera& camera, const std::optional<SceneBounds>& water,
                         double margin) {
  if (!water) return;
  const Eigen::Vector3d forward = (camera.target() - camera.eye()).normalized();
  for (int axis = 0; axis < 2; ++axis) {
    if (forward[axis] > kMinAlignment) {  // the camera stands on the low side
      below_[axis] = true;
      limit_[axis] = water->lo[axis] - margin;
    } else if (forward[axis] < -kMinAlignment) {
      above_[axis] = true;
      limit_[axis] = water->hi[axis] + margin;
    }
  }
}

}  // namespace washout::render
