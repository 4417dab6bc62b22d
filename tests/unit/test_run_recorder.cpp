// Recording outside the physics (docs/design.md "Recording"): the engine writes no file of its
// own, a RunRecorder observing the run keeps one row per step and every frame, and the record
// hooks come before any callback, so that a callback that fails leaves its step in the file.
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

#include "engine/io/run_file_reader.hpp"
#include "engine/io/run_recorder.hpp"
#include "engine/lua/lua_scene.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;

// A small 2D tank with a floating block: a few steps, two frames, one body, one probe.
fs::path write_scene(const fs::path& dir) {
  omp_set_num_threads(1);  // a few hundred particles: threads would only wait on each other
  fs::create_directories(dir);
  const fs::path path = dir / "tank.lua";
  std::ofstream(path) << R"(
local P = washout.parameters { dim = 2, d0 = 0.02, end_time = 0.02, output_interval = 0.01 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.3, 0.1 } } }
washout.wall { washout.box { min = { -0.06, -0.06 }, max = { 0.36, 0 } }, name = "floor" }
washout.body { washout.box { min = { 0.1, 0.08 }, max = { 0.16, 0.12 } }, name = "block",
               density = 500 }
washout.probe { name = "front", quantity = "front", axis = "x" }
)";
  return path;
}

// Stops the run by throwing after `steps` steps, as a failing Lua callback does.
class FailingCallback final : public RunObserver {
 public:
  explicit FailingCallback(long steps) : steps_(steps) {}
  bool on_step(const Simulation& sim, const StepReport&) override {
    if (sim.step_count() >= steps_) throw std::runtime_error("the callback failed");
    return true;
  }

 private:
  long steps_;
};

TEST(RunRecorder, TheEngineAloneWritesNoFile) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "run_recorder_none";
  fs::remove_all(dir);
  lua::LuaScene scene(write_scene(dir).string(), {});
  Simulation sim(scene.model());
  const RunSummary summary = sim.run({});
  EXPECT_EQ(summary.status, RunStatus::Completed);
  EXPECT_GT(summary.steps, 0);
  EXPECT_TRUE(summary.output_path.empty());
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename(), "tank.lua");
}

TEST(RunRecorder, KeepsEveryStepAndFrame) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "run_recorder_all";
  fs::remove_all(dir);
  lua::LuaScene scene(write_scene(dir).string(), {});
  Simulation sim(scene.model());
  const std::string file = (dir / "tank.h5").string();
  io::RunRecorder recorder(file);
  const RunSummary summary = sim.run({&recorder});
  EXPECT_EQ(summary.output_path, file);
  io::RunFileReader run(file);
  EXPECT_EQ(run.frame_count(), summary.frames);
  EXPECT_EQ(summary.frames, 3u);
  const auto steps = run.read_doubles("/stats/step");
  ASSERT_EQ(steps.size(), static_cast<std::size_t>(summary.steps));
  for (std::size_t k = 0; k < steps.size(); ++k) EXPECT_EQ(steps[k], double(k + 1));
  EXPECT_EQ(run.read_doubles("/probes/front/value").size(), steps.size());
  EXPECT_EQ(run.read_doubles("/bodies/block/time"), run.read_doubles("/stats/time"));
  EXPECT_FALSE(run.string_attribute("mass", "/bodies/block").empty());
  ASSERT_TRUE(run.checkpoint().has_value());
  EXPECT_EQ(run.checkpoint()->frame, 2);
}

TEST(RunRecorder, AFailingCallbackLeavesItsStepRecordedWhereverTheRecorderIsListed) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "run_recorder_abort";
  fs::remove_all(dir);
  lua::LuaScene scene(write_scene(dir).string(), {});
  Simulation sim(scene.model());
  const std::string file = (dir / "tank.h5").string();
  {
    FailingCallback callback(3);
    io::RunRecorder recorder(file);
    EXPECT_THROW(sim.run({&callback, &recorder}), std::runtime_error);
  }
  io::RunFileReader run(file);
  EXPECT_EQ(run.read_doubles("/stats/step").size(), 3u);
  EXPECT_EQ(run.read_doubles("/bodies/block/time").size(), 3u);
  EXPECT_EQ(run.frame_count(), 1u);  // frame 0; the steps after it are in the series
}

}  // namespace
}  // namespace washout
