// `washout study` end to end, as a user runs it: child runs of the real program, study.csv,
// the self-scoring dam break's error within its bound, an unstable run kept as a row, and a
// misspelt --vary name refused before anything runs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

struct Command {
  int status;
  std::string output;
};

// Runs washout with the arguments; stdout and stderr together.
Command washout_cli(const std::string& args) {
  const std::string command = std::string(WASHOUT_EXE) + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  std::string output;
  char buffer[4096];
  while (pipe && fgets(buffer, sizeof buffer, pipe)) output += buffer;
  const int status = pipe ? pclose(pipe) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

// study.csv as rows of header -> cell (no quoted commas in the columns read here).
std::vector<std::map<std::string, std::string>> read_rows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::map<std::string, std::string>> rows;
  std::string line;
  std::vector<std::string> header;
  if (std::getline(in, line)) {
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) header.push_back(cell);
  }
  while (std::getline(in, line)) {
    std::stringstream s(line);
    std::map<std::string, std::string> row;
    std::string cell;
    for (std::size_t k = 0; k < header.size() && std::getline(s, cell, ','); ++k)
      row[header[k]] = cell;
    rows.push_back(row);
  }
  return rows;
}

double number(const std::map<std::string, std::string>& row, const std::string& column) {
  const auto it = row.find(column);
  if (it == row.end() || it->second.empty()) return NAN;
  return std::atof(it->second.c_str());
}

TEST(Study, DamBreakTwoResolutionsScoreThemselves) {
  const std::string out = testing::output_dir("study_dambreak_2d");
  std::filesystem::remove_all(out);
  // end_time 0.27 s: T = 3.28, past the last table point used (T <= 3).
  const auto r =
      washout_cli("study " + testing::scene_path("dambreak_2d.lua") +
                  " --vary d0=0.0146,0.0073 --set end_time=0.27 --threads 1 --out " + out);
  std::printf("%s", r.output.c_str());
  ASSERT_EQ(r.status, 0);
  const auto rows = read_rows(out + "/study.csv");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    const double error = number(row, "error"), bound = number(row, "error_bound");
    std::printf("d0 = %s: status %s, %s particles, %s steps, wall %s s, error %.4f (bound %.3g)\n",
                row.at("d0").c_str(), row.at("status").c_str(), row.at("particles").c_str(),
                row.at("steps").c_str(), row.at("wall_seconds_min").c_str(), error, bound);
    EXPECT_EQ(row.at("status"), "ok");
    EXPECT_TRUE(std::isfinite(error));
    EXPECT_TRUE(std::isfinite(bound));
    EXPECT_LE(error, bound);  // the bound dambreak_2d.lua documents
    EXPECT_GT(number(row, "particles"), 0);
    EXPECT_GT(number(row, "wall_seconds_min"), 0);
    EXPECT_GT(number(row, "peak_rss_bytes"), 1e6);
    EXPECT_GE(number(row, "ppe_iterations_per_step"), 1);
  }
  // The finer run has about four times the fluid particles.
  EXPECT_NEAR(number(rows[1], "fluid_particles") / number(rows[0], "fluid_particles"), 4, 0.2);
  // Each run is a complete run folder whose file carries the score.
  io::RunFileReader run(out + "/run_01/dambreak_2d.h5");
  EXPECT_NEAR(run.double_attribute("error"), number(rows[0], "error"), 1e-5);
  EXPECT_NE(run.string_attribute("reference").find("Martin & Moyce"), std::string::npos);
  // The convergence line names the observed order or says it is not converging.
  EXPECT_NE(r.output.find("convergence of front:"), std::string::npos);
}

TEST(Study, UnstableRunIsARow) {
  const std::string out = testing::output_dir("study_blow_up");
  std::filesystem::remove_all(out);
  const auto r =
      washout_cli("study " + std::string(WASHOUT_SOURCE_DIR) +
                  "/tests/data/blow_up.lua --vary max_speed=0.5,100 --threads 1 --out " + out);
  std::printf("%s", r.output.c_str());
  EXPECT_EQ(r.status, 0);
  const auto rows = read_rows(out + "/study.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("status"), "unstable");
  EXPECT_EQ(rows[0].at("exit_code"), "2");
  EXPECT_EQ(rows[1].at("status"), "ok");
}

TEST(Study, UnknownVaryNameIsRefusedBeforeAnyRun) {
  const std::string out = testing::output_dir("study_bad");
  std::filesystem::remove_all(out);
  const auto r = washout_cli("study " + testing::scene_path("dambreak_2d.lua") +
                             " --vary d0=0.0146 --vary resolutoin=1,2 --out " + out);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("--vary resolutoin"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out + "/study.csv"));
}

}  // namespace
}  // namespace washout
