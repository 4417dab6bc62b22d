#pragma once
// What a user can choose about a frame: size, colour field and range, camera, smoothing.
// The same options come from `washout render` flags and from the scene key washout.frames{}.
#include <string>

namespace washout::render {

struct CameraSpec {
  // "auto" (2D: the x-y plane; 3D: "perspective"), "side", "top" or "perspective".
  // 2D scenes are always drawn as the flat x-y plane, whatever the preset.
  std::string preset = "auto";
  // When true, position/target/up/fov_deg define a perspective camera (3D only).
  bool explicit_pose = false;
  double position[3] = {0.0, 0.0, 0.0};
  double target[3] = {0.0, 0.0, 0.0};
  double up[3] = {0.0, 0.0, 1.0};
  double fov_deg = 35.0;  // vertical field of view of perspective cameras
  // A region to frame instead of every particle of the first frame: a zoom (on the pier, say,
  // where the whole flume would be a thin strip): the view is fitted to this box, and what lies
  // outside it may be cut off at the border of the drawing. region_components is 0 (no region) or
  // the scene's dim: x, y (2D) or x, y, z (3D) of region_min and region_max. An explicit pose
  // ignores it.
  int region_components = 0;
  double region_min[3] = {0.0, 0.0, 0.0};
  double region_max[3] = {0.0, 0.0, 0.0};
};

struct RenderOptions {
  int width = 1280;
  int height = 720;
  std::string color_field = "speed";  // "speed", "pressure" or "vertical_velocity"
  // Without a fixed range, the range is taken from the first frame whose fluid shows any spread
  // of the field, then kept for every later frame.
  bool fixed_range = false;
  double range_min = 0.0;
  double range_max = 1.0;
  CameraSpec camera;
  int supersample = 2;  // render at this multiple of the size, then average down (1 to 4)
  // 3D: leave out the walls between the camera and the water (render/wall_cutaway.hpp).
  bool cutaway_walls = true;
  // Leave out spheres hidden behind nearer ones (same image, faster for dense 3D blocks).
  bool occlusion_culling = true;
};

}  // namespace washout::render
