// Dam break of Martin & Moyce (1952), n^2 = 2: surge front Z = x/a against T = t sqrt(2g/a),
// compared with their Table 2 (validation/reference/mm1952_n2_front_table.csv, Ocellaris
// transcription) over T <= 3. The scenes score themselves the same way (scripts/validation.lua);
// this file recomputes the error independently and checks the scene's own figure against it.
#include <gtest/gtest.h>

#include <cmath>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

constexpr double kColumn = 0.146;  // a [m], as in the scenes

// RMS of Z_sim - Z_exp over the table's points with T <= 3 (and within the run).
double front_rms(const std::string& h5, double* mean_error) {
  io::RunFileReader run(h5);
  const auto t = run.read_doubles("/probes/front/time");
  const auto x = run.read_doubles("/probes/front/value");
  std::vector<double> T, Z;
  for (std::size_t k = 0; k < t.size(); ++k) {
    T.push_back(t[k] * std::sqrt(2 * 9.81 / kColumn));
    Z.push_back(x[k] / kColumn);
  }
  const auto csv = testing::read_csv(testing::refdata("mm1952_n2_front_table.csv"));
  double sum2 = 0, sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < csv.at("source").size(); ++k) {
    if (csv.at("source")[k] != "ocellaris_table2") continue;
    const double Tr = std::stod(csv.at("T_t_sqrt_2g_over_a")[k]);
    const double Zr = std::stod(csv.at("Z_x_over_a")[k]);
    if (Tr > 3.0 || Tr > T.back()) continue;
    const double e = testing::interpolate(T, Z, Tr) - Zr;
    std::printf("  T = %.2f  Z_exp = %.2f  Z_sim = %.3f\n", Tr, Zr, Zr + e);
    sum2 += e * e, sum += e, ++count;
  }
  EXPECT_GE(count, 12);  // 13 points of the table have T <= 3
  *mean_error = sum / count;
  return std::sqrt(sum2 / count);
}

// Runs a dam-break scene, prints the front error and returns {RMS, mean}.
struct FrontResult {
  double rms, mean;
  long wall_crossings;
};
FrontResult run_front(const std::string& scene, const std::string& test_name, const char* label,
                      const lua::Overrides& overrides) {
  const auto out = testing::run_scene(scene, test_name, overrides);
  EXPECT_EQ(out.exit_code, 0);
  if (out.exit_code != 0) return {1e9, 1e9, 0};
  FrontResult r{0, 0, out.summary.wall_crossings};
  r.rms = front_rms(out.h5_path, &r.mean);
  // The scene's own score (washout.validation in the scene) is the same number.
  io::RunFileReader run(out.h5_path);
  EXPECT_NEAR(run.double_attribute("error"), r.rms, 1e-9);
  EXPECT_EQ(run.string_attribute("error_names"), "front");
  std::printf("dam break %s: front RMS error %.4f (mean %+.4f), %ld steps, %.1f s\n", label, r.rms,
              r.mean, out.summary.steps, out.summary.wall_seconds);
  return r;
}

// Bounds: Martin & Moyce's front lags an instantaneous release at early times (their column
// was not released instantaneously: at t = 0.072 s their toe had advanced 0.032 m, Lobovsky et
// al.'s, from a column as high, 0.097 m; docs/method.md), so the error does not fall with d0
// and these are regression bounds: what washout measures now with a margin of about 20 %.
// At a/d0 = 10 the surge is two particles thick and its tip lags (P = 0 is imposed d0/2
// beyond the surface particles, which at a two-particle tip slows it): measured 0.156, mean
// -0.136 in 2D; 0.199, mean -0.175 in 3D. At a/d0 = 20 it leads: 0.147, mean +0.13.
TEST(DamBreak, Front2dCoarse) {
  const auto r =
      run_front("dambreak_2d.lua", "dambreak_2d_a10", "2D, a/d0 = 10", {{"d0", "0.0146"}});
  EXPECT_LT(r.rms, 0.19);
  EXPECT_EQ(r.wall_crossings, 0);
}

TEST(DamBreak, Front2dDefault) {
  const auto r = run_front("dambreak_2d.lua", "dambreak_2d_a20", "2D, a/d0 = 20", {});
  EXPECT_LT(r.rms, 0.25);
  EXPECT_GT(r.mean, 0.0);  // the front runs early, as in the other SPH codes
  EXPECT_EQ(r.wall_crossings, 0);
}

TEST(DamBreak, Front3dCoarse) {
  const auto r =
      run_front("dambreak_3d.lua", "dambreak_3d_a10", "3D, a/d0 = 10", {{"d0", "0.0146"}});
  EXPECT_LT(r.rms, 0.24);
}

}  // namespace
}  // namespace washout
