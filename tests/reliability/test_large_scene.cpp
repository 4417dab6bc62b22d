// A scene over 64 KiB (HDF5's limit for an attribute in the object header) runs and its text
// comes back whole from the run file's /scene_source dataset.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/io/run_file_reader.hpp"
#include "reliability/run_washout.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;

TEST(LargeScene, A200KiBSceneRunsAndIsStoredWhole) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "large_scene";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ifstream base(std::string(WASHOUT_SOURCE_DIR) + "/tests/data/broken/base.lua");
  std::stringstream text;
  text << base.rdbuf();
  // A long table of gauge positions, as a generated scene might carry.
  text << "local gauges = {\n";
  for (int k = 0; k < 12000; ++k) text << "  " << k * 1e-4 << ", -- gauge " << k << "\n";
  text << "}\nassert(#gauges == 12000)\n";
  const std::string source = text.str();
  ASSERT_GT(source.size(), 200u * 1024u);
  const fs::path scene = dir / "large.lua";
  std::ofstream(scene) << source;
  const auto r =
      test::run_washout({"run", scene.string(), "--out", (dir / "out").string(), "--quiet"},
                        (dir / "log.txt").string(), 120);
  ASSERT_EQ(r.status, 0) << r.output;
  io::RunFileReader reader((dir / "out" / "large.h5").string());
  EXPECT_EQ(reader.scene_source(), source);
  EXPECT_FALSE(reader.has_attribute("/", "scene_source"));  // too large for one
}

TEST(LargeScene, ASmallSceneKeepsTheAttributeToo) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "small_scene";
  fs::remove_all(dir);
  const std::string scene = std::string(WASHOUT_SOURCE_DIR) + "/tests/data/broken/base.lua";
  const auto r =
      test::run_washout({"run", scene, "--out", dir.string(), "--quiet"},
                        (fs::path(WASHOUT_TEST_OUTPUT_DIR) / "small_scene.log").string(), 120);
  ASSERT_EQ(r.status, 0) << r.output;
  io::RunFileReader reader((dir / "base.h5").string());
  EXPECT_EQ(reader.scene_source(), reader.string_attribute("scene_source"));
  EXPECT_NE(reader.scene_source().find("washout.fluid"), std::string::npos);
}

}  // namespace
}  // namespace washout
