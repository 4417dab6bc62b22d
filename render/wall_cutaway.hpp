#pragma once
// Leaves out the walls between the camera and the water, as in a cutaway drawing: a 3D flume
// seen from the side would otherwise show only its near side wall. Decided once, with the
// camera, from the water of the first frame: along each horizontal axis the camera looks
// along (x or y), wall particles lying beyond the water on the camera's side are not drawn.
// Walls under the water (the floor) and on the far sides stay, and so do rigid bodies.
#include <Eigen/Core>
#include <optional>

#include "render/camera.hpp"
#include "render/scene_bounds.hpp"

namespace washout::render {

class WallCutaway {
 public:
  WallCutaway() = default;  // cuts nothing
  // margin: how far beyond the water a wall particle's centre must lie (about d0 / 2).
  WallCutaway(const Camera& camera, const std::optional<SceneBounds>& water, double margin);

  bool hides(const Eigen::Vector3d& wall_position) const {
    for (int axis = 0; axis < 2; ++axis) {
      if (below_[axis] && wall_position[axis] < limit_[axis]) return true;
      if (above_[axis] && wall_position[axis] > limit_[axis]) return true;
    }
    return false;
  }
  bool active() const { return below_[0] || below_[1] || above_[0] || above_[1]; }

 private:
  bool below_[2] = {false, false};  // camera on the low side of the axis: cut lower walls
  bool above_[2] = {false, false};
  double limit_[2] = {0.0, 0.0};
};

}  // namespace washout::render
