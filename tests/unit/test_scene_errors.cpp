// Bad input gets a clear error: the scene file, the line and the parameter; impossible scenes
// are refused before the run; a blow-up stops the run and leaves the frames written readable.
#include <gtest/gtest.h>

#include "engine/cli/run_command.hpp"
#include "engine/io/run_file_reader.hpp"

namespace washout {
namespace {

cli::RunOutcome run(const std::string& file, const lua::Overrides& overrides = {}) {
  cli::RunRequest r;
  r.scene_path = std::string(WASHOUT_SOURCE_DIR) + "/tests/data/" + file;
  r.out_dir = std::string(WASHOUT_TEST_OUTPUT_DIR) + "/errors_" + file;
  r.overrides = overrides;
  r.render_frames = false;
  return cli::run_scene(r);
}

TEST(SceneErrors, MisspeltParameterNamesFileLineAndSuggestion) {
  const auto out = run("misspelt_parameter.lua");
  std::printf("%s\n", out.error.c_str());
  EXPECT_EQ(out.exit_code, cli::kBadInput);
  EXPECT_NE(out.error.find("misspelt_parameter.lua:1"), std::string::npos);
  EXPECT_NE(out.error.find("'alhpa'"), std::string::npos);
  EXPECT_NE(out.error.find("did you mean 'alpha'"), std::string::npos);
}

TEST(SceneErrors, UnknownOverrideSuggestsNearestName) {
  const auto out = run("empty_fluid.lua", {{"viscosty", "1e-3"}});
  std::printf("%s\n", out.error.c_str());
  EXPECT_EQ(out.exit_code, cli::kBadInput);
  EXPECT_NE(out.error.find("--set viscosty"), std::string::npos);
  EXPECT_NE(out.error.find("'viscosity'"), std::string::npos);
}

TEST(SceneErrors, NegativeSpacingRefused) {
  const auto out = run("empty_fluid.lua", {{"d0", "-0.01"}});
  std::printf("%s\n", out.error.c_str());
  EXPECT_EQ(out.exit_code, cli::kBadInput);
  EXPECT_NE(out.error.find("'d0' must be positive"), std::string::npos);
}

TEST(SceneErrors, EmptyFluidRegionRefusedWithItsLine) {
  const auto out = run("empty_fluid.lua");
  std::printf("%s\n", out.error.c_str());
  EXPECT_EQ(out.exit_code, cli::kBadInput);
  EXPECT_NE(out.error.find("empty_fluid.lua:3"), std::string::npos);
  EXPECT_NE(out.error.find("holds no particle"), std::string::npos);
}

TEST(SceneErrors, InvertedBoxNamesTheLine) {
  const auto out = run("bad_box.lua");
  std::printf("%s\n", out.error.c_str());
  EXPECT_EQ(out.exit_code, cli::kBadInput);
  EXPECT_NE(out.error.find("bad_box.lua:3"), std::string::npos);
  EXPECT_NE(out.error.find("min must be below max"), std::string::npos);
}

TEST(SceneErrors, EmptyCameraRegionNamesTheLine) {
  const auto out = run("bad_camera_region.lua");
  std::printf("%s\n", out.error.c_str());
  EXPECT_EQ(out.exit_code, cli::kBadInput);
  EXPECT_NE(out.error.find("bad_camera_region.lua:4"), std::string::npos);
  EXPECT_NE(out.error.find("camera region max must exceed min along x"), std::string::npos);
}

TEST(SceneErrors, BlowUpStopsWithExitTwoAndKeepsFrames) {
  const auto out = run("blow_up.lua");
  std::printf("%s\n", out.summary.message.c_str());
  EXPECT_EQ(out.exit_code, cli::kUnstable);
  EXPECT_NE(out.summary.message.find("runaway velocity"), std::string::npos);
  EXPECT_NE(out.summary.message.find("last good state is frame"), std::string::npos);
  io::RunFileReader file(out.h5_path);  // still readable
  ASSERT_GE(file.frame_count(), 1u);
  EXPECT_EQ(file.read_frame(0).time, 0.0);
}

}  // namespace
}  // namespace washout
