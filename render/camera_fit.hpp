#pragma once
// Chooses the camera for a scene from its bounding box, once, on the first frame rendered.
//   2D:          orthographic view of the x-y plane (x right, y up), whatever the preset.
//   "side":      orthographic, looking along +y at the x-z plane (x right, z up).
//   "top":       orthographic, looking down -z at the x-y plane (x right, y up).
//   "perspective" (and "auto" in 3D): a 3/4 view from the -y side, a little upstream (-x)
//                and above, the whole box in view.
//   explicit pose: perspective from CameraSpec position/target/up/fov_deg.
// A camera region (CameraSpec::region_components > 0) replaces the particles' box in the
// fitting (not for an explicit pose).
#include "render/camera.hpp"
#include "render/render_options.hpp"
#include "render/scene_bounds.hpp"

namespace washout::render {

// Throws RenderError for an unknown preset, a degenerate explicit pose or an empty region.
void validate_camera_spec(const CameraSpec& spec);

// aspect = width / height of the part of the image the scene is drawn into.
// Also throws for a region whose component count is not dim.
Camera fit_camera(const CameraSpec& spec, int dim, const SceneBounds& particles, double aspect);

}  // namespace washout::render
