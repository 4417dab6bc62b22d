#pragma once
// Helpers for scene tests: run a scene in-process (same pipeline as `washout run`), then read
// its HDF5 output, and load reference data from validation/reference/.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "engine/cli/run_command.hpp"
#include "engine/io/run_file_reader.hpp"

namespace washout::testing {

inline std::string scene_path(const std::string& name) {
  return std::string(WASHOUT_SOURCE_DIR) + "/scenes/" + name;
}

inline std::string output_dir(const std::string& test_name) {
  const auto dir = std::filesystem::path(WASHOUT_TEST_OUTPUT_DIR) / test_name;
  std::filesystem::create_directories(dir);
  return dir.string();
}

// Runs a scene with --set overrides; fails the test if the run does not complete.
inline cli::RunOutcome run_scene(const std::string& scene, const std::string& test_name,
                                 const lua::Overrides& overrides, bool expect_success = true) {
  cli::RunRequest request;
  request.scene_path = scene_path(scene);
  request.out_dir = output_dir(test_name);
  request.overrides = overrides;
  request.render_frames = false;
  request.log = stdout;
  cli::RunOutcome outcome = cli::run_scene(request);
  if (expect_success) {
    EXPECT_EQ(outcome.exit_code, 0) << outcome.error << outcome.summary.message;
  }
  return outcome;
}

// A validation scene's own score by name (scripts/validation.lua); a test failure if it has none.
inline double score(const cli::RunOutcome& out, const std::string& name) {
  for (const lua::ValidationScore& s : out.scores)
    if (s.name == name) return s.error;
  ADD_FAILURE() << "no score '" << name << "'";
  return 1e9;
}

// Columns of a CSV with one header line, keyed by header name; rows filtered by `keep`.
inline std::map<std::string, std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << "cannot read " << path;
  std::map<std::string, std::vector<std::string>> columns;
  std::string line;
  std::vector<std::string> header;
  if (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) header.push_back(cell);
  }
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::string cell;
    for (std::size_t k = 0; k < header.size() && std::getline(s, cell, ','); ++k)
      columns[header[k]].push_back(cell);
  }
  return columns;
}

inline std::string refdata(const std::string& file) {
  return std::string(WASHOUT_REFDATA_DIR) + "/" + file;
}

// Linear interpolation of y(x) at x0 (x increasing).
inline double interpolate(const std::vector<double>& x, const std::vector<double>& y, double x0) {
  if (x0 <= x.front()) return y.front();
  for (std::size_t k = 1; k < x.size(); ++k)
    if (x0 <= x[k]) return y[k - 1] + (y[k] - y[k - 1]) * (x0 - x[k - 1]) / (x[k] - x[k - 1]);
  return y.back();
}

}  // namespace washout::testing
