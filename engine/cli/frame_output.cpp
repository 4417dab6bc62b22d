#include "engine/cli/frame_output.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "engine/io/run_file_writer.hpp"
#include "render/frame_renderer.hpp"
#include "render/render_error.hpp"

namespace washout::cli {
namespace {

render::RenderOptions to_render_options(const lua::FrameRequest& r) {
  render::RenderOptions o;
  o.width = r.width;
  o.height = r.height;
  o.color_field = r.color;
  o.fixed_range = r.fixed_range;
  o.range_min = r.range_min;
  o.range_max = r.range_max;
  o.camera.preset = r.camera_preset;
  o.camera.explicit_pose = r.camera_explicit;
  for (int a = 0; a < 3; ++a) {
    o.camera.position[a] = r.camera_position[a];
    o.camera.target[a] = r.camera_target[a];
    o.camera.up[a] = r.camera_up[a];
  }
  o.camera.fov_deg = r.camera_fov;
  o.camera.region_components = r.camera_region_components;
  for (int a = 0; a < 3; ++a) {
    o.camera.region_min[a] = r.camera_region_min[a];
    o.camera.region_max[a] = r.camera_region_max[a];
  }
  return o;
}

// Draws every `every`-th output frame to folder/frame_NNNNNN.png (numbered by output frame, so
// ffmpeg -i frame_%06d.png stitches them) and reports the share of the run spent drawing.
class FrameOutput final : public RunObserver {
 public:
  FrameOutput(render::RenderOptions options, int every, std::string folder)
      : renderer_(std::move(options)), every_(every), folder_(std::move(folder)) {}

  bool on_frame(const Simulation& sim, std::size_t frame) override {
    if (frame % static_cast<std::size_t>(every_) != 0) return true;
    const auto start = std::chrono::steady_clock::now();
    char name[32];
    std::snprintf(name, sizeof name, "frame_%06zu.png", frame);
    try {
      std::filesystem::create_directories(folder_);
      renderer_.render_png(sim.view(), (std::filesystem::path(folder_) / name).string());
    } catch (const render::RenderError& e) {
      throw io::OutputError(std::string("frame rendering failed: ") + e.what());
    } catch (const std::filesystem::filesystem_error& e) {
      throw io::OutputError(std::string("cannot create the frames folder: ") + e.what());
    }
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++frames_;
    return true;
  }

  void on_finish(const Simulation&, const RunSummary& summary) override {
    if (frames_ == 0) return;
    std::printf("  frames: %zu PNG in %s, %.2f s drawing (%.1f %% of the run)\n", frames_,
                folder_.c_str(), seconds_,
                summary.wall_seconds > 0 ? 100.0 * seconds_ / summary.wall_seconds : 0.0);
  }

 private:
  render::FrameRenderer renderer_;
  int every_;
  std::string folder_;
  std::size_t frames_ = 0;
  double seconds_ = 0.0;
};

}  // namespace

std::unique_ptr<RunObserver> make_frame_output(const lua::FrameRequest& request,
                                               const std::string& folder) {
  try {
    return std::make_unique<FrameOutput>(to_render_options(request), request.every, folder);
  } catch (const render::RenderError& e) {
    throw SceneError(std::string("washout.frames: ") + e.what(), "", "frames");
  }
}

}  // namespace washout::cli
