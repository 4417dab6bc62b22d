#include "engine/cli/frame_output.hpp"

namespace washout::cli {
namespace {

// Placeholder until the renderer lands: frames requested but not drawn are reported once.
class NoFrames final : public RunObserver {
 public:
  void on_start(const Simulation&) override {
    std::fprintf(stderr, "note: this build has no renderer; washout.frames{} is ignored\n");
  }
};

}  // namespace

std::unique_ptr<RunObserver> make_frame_output(const lua::FrameRequest&, const std::string&) {
  return std::make_unique<NoFrames>();
}

}  // namespace washout::cli
