#pragma once
// Draws particle frames offscreen (OSMesa) as PNG images: fluid as lit spheres coloured by a
// field, walls grey, rigid bodies magenta, with a colour bar and the simulated time.
// The camera and (unless fixed) the colour range are chosen on the first frame and kept for
// every later frame, so that a sequence neither jitters nor changes its colours' meaning.
// Usage: FrameRenderer r(options); r.render_png(view, "frames/frame_000000.png"); ...
#include <array>
#include <memory>
#include <optional>
#include <string>

#include "engine/core/particle_view.hpp"
#include "render/color_field.hpp"
#include "render/frame_layout.hpp"
#include "render/image.hpp"
#include "render/render_error.hpp"
#include "render/render_options.hpp"

namespace washout::render {

class FrameRenderer {
 public:
  // Throws RenderError for invalid options (unknown colour field or camera preset, size,
  // supersampling, an empty fixed range). The OpenGL context is created on the first render.
  explicit FrameRenderer(RenderOptions options);
  ~FrameRenderer();
  FrameRenderer(FrameRenderer&&) noexcept;
  FrameRenderer& operator=(FrameRenderer&&) noexcept;

  // Throws RenderError for an empty view, ContextError if OpenGL is unavailable.
  Image render(const ParticleView& view);
  // Also throws ImageWriteError if the file cannot be written.
  void render_png(const ParticleView& view, const std::string& path);

  // Where a world point appears in the image, in pixels: x to the right, y down, pixel (i, j)
  // covering [i, i+1) x [j, j+1). nullopt before the first frame (no camera yet) or for a
  // point behind the camera. In 2D pass z = 0.
  std::optional<std::array<double, 2>> project_to_pixel(double x, double y, double z = 0.0) const;

  const RenderOptions& options() const;
  const FrameLayout& layout() const;
  // The range the last frame was coloured with; nullopt before the first frame.
  std::optional<ValueRange> color_range() const;
  // Spheres sent to OpenGL for the last frame (the rest were hidden or invalid).
  std::size_t drawn_spheres() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace washout::render
