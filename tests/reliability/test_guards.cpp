// The run's guards (docs/stability.md), each triggered on purpose by a small case of the real
// program: exit 2, a message that says what fired, when and where, and a run file whose frames
// up to the stop are readable, with the per-step energy and time-step limit in /stats.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "engine/core/particle_view.hpp"
#include "engine/io/run_file_reader.hpp"
#include "reliability/run_washout.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;
const std::string kDamBreak = std::string(WASHOUT_SOURCE_DIR) + "/scenes/dambreak_2d.lua";

struct Fired {
  test::ProgramResult result;
  fs::path file;
};

Fired run_dam_break(const std::string& name, const std::vector<std::string>& sets) {
  const fs::path dir = fs::path(testing::TempDir()) / ("guard_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<std::string> args = {"run",       kDamBreak, "--out", dir.string(), "--quiet",
                                   "--threads", "1",       "--set", "d0=0.0146"};
  for (const auto& s : sets) args.insert(args.end(), {"--set", s});
  Fired f;
  f.result = test::run_washout(args, (dir / "log.txt").string(), 120.0);
  f.file = dir / "dambreak_2d.h5";
  return f;
}

void expect_fired(const Fired& f, const std::string& fragment) {
  const auto at = f.result.output.find("unstable at");
  std::printf("%s\n", at == std::string::npos ? "(no guard fired)" : f.result.output.c_str() + at);
  EXPECT_FALSE(f.result.timed_out);
  EXPECT_EQ(f.result.status, 2);
  EXPECT_NE(f.result.output.find("unstable at t = "), std::string::npos) << f.result.output;
  EXPECT_NE(f.result.output.find(fragment), std::string::npos) << f.result.output;
  EXPECT_NE(f.result.output.find("The last good state is frame"), std::string::npos);
  io::RunFileReader file(f.file.string());
  ASSERT_GE(file.frame_count(), 1u);
  const auto frame = file.read_frame(file.frame_count() - 1);  // the last frame reads back
  EXPECT_GT(frame.position.size(), 0u);
  if (!file.has("/stats/time")) return;  // stopped in its first step: no step to record
  const auto energy = file.read_doubles("/stats/mechanical_energy");
  const auto limit = file.read_doubles("/stats/dt_limit");
  EXPECT_EQ(energy.size(), file.read_doubles("/stats/time").size());
  EXPECT_EQ(limit.size(), energy.size());
}

// alpha = 1 taken per step (alpha_scaling = "per_step", the paper's form) at a twentieth of the
// default time step: the density-invariance term, scaled by 1/dt^2, overshoots and the fluid
// gains energy (docs/stability.md, the (dt, alpha) map). The energy guard fires before any
// particle reaches the speed limit. (With the default "per_time" the same run completes: alpha
// is then 1/20 at that step; docs/method.md, the thirty-fourth session.)
TEST(Guards, EnergyGainStopsTheRun) {
  const Fired f = run_dam_break(
      "energy", {"end_time=0.27", "dt_max=0.01", "cfl=0.01", "alpha=1", "alpha_scaling=per_step"});
  expect_fired(f, "energy gain: the mechanical energy of the fluid and bodies is");
  const auto energy = io::RunFileReader(f.file.string()).read_doubles("/stats/mechanical_energy");
  // Before the blow-up the dam break only loses energy: its largest value is the start's, to
  // within the tolerance (0.1 x M g H = 12.2 J/m here on 61 J/m).
  EXPECT_LT(*std::max_element(energy.begin(), energy.end() - 1), energy.front() + 12.2);
}

TEST(Guards, RunawayVelocityNamesTheParticle) {
  const Fired f = run_dam_break("speed", {"end_time=0.2", "max_speed=0.5"});
  expect_fired(f, "runaway velocity: particle ");
}

TEST(Guards, EscapingTheDomainNamesWhere) {
  // The domain ends 2 cm beyond the column's foot: the surge leaves it, far more than the
  // escape_limit of 1 % of the 200 particles.
  const Fired f =
      run_dam_break("domain", {"end_time=0.2", "domain_min={-0.1,-0.1}", "domain_max={0.17,0.5}"});
  expect_fired(f, "left the domain at (");
  EXPECT_NE(f.result.output.find("more than escape_limit = 0.01 of the 200 fluid particles gone"),
            std::string::npos)
      << f.result.output;
}

// With escape_limit = 1 the same surge flows out of the domain and the run goes on: the fluid
// that left is retired (kind 4), parked where it left, at rest, counted per step in
// /stats/retired_particles; none is lost from the file and none moves again.
TEST(Guards, FluidLeavingTheDomainIsRetired) {
  const Fired f = run_dam_break("retired", {"end_time=0.2", "domain_min={-0.1,-0.1}",
                                            "domain_max={0.17,0.5}", "escape_limit=1"});
  ASSERT_EQ(f.result.status, 0) << f.result.output;
  EXPECT_NE(f.result.output.find("fluid particles retired as they left the domain: "),
            std::string::npos)
      << f.result.output;
  io::RunFileReader file(f.file.string());
  const auto retired_series = file.read_doubles("/stats/retired_particles");
  ASSERT_FALSE(retired_series.empty());
  const auto first = file.read_frame(0), last = file.read_frame(file.frame_count() - 1);
  std::size_t retired = 0, fluid = 0, moved = 0;
  for (std::size_t i = 0; i < last.kind.size(); ++i) {
    if (last.kind[i] == 0) ++fluid;
    if (last.kind[i] != static_cast<std::uint8_t>(ParticleKind::Retired)) continue;
    ++retired;
    EXPECT_EQ(first.kind[i], 0u);
    EXPECT_GT(last.position[2 * i], 0.17);  // x beyond domain_max: where it left
    EXPECT_EQ(last.velocity[2 * i], 0.0);
    EXPECT_EQ(last.velocity[2 * i + 1], 0.0);
  }
  // A particle retired by the frame before the last has not moved since.
  const auto before = file.read_frame(file.frame_count() - 2);
  for (std::size_t i = 0; i < before.kind.size(); ++i)
    if (before.kind[i] == static_cast<std::uint8_t>(ParticleKind::Retired))
      moved += before.position[2 * i] != last.position[2 * i] ||
               before.position[2 * i + 1] != last.position[2 * i + 1];
  std::printf("%zu of 200 fluid particles retired by t = 0.2 s, %zu still fluid, %zu moved\n",
              retired, fluid, moved);
  EXPECT_GT(retired, 10u);
  EXPECT_EQ(retired + fluid, 200u);
  EXPECT_EQ(moved, 0u);
  EXPECT_EQ(static_cast<std::size_t>(retired_series.back()), retired);
}

TEST(Guards, StalledPressureSolveSaysSo) {
  const Fired f =
      run_dam_break("solver", {"end_time=0.1", "solver=pcg", "solver_max_iterations=3"});
  expect_fired(f, "the pressure solver did not converge in 3 iterations");
}

TEST(Guards, TimeStepBelowTheMinimumSaysWhichLimit) {
  // A viscosity of 10 m^2/s asks for a step of 3.8e-6 s, below dt_min = 1e-5 s.
  const Fired f = run_dam_break("dt_min", {"end_time=0.1", "viscosity=10", "dt_min=1e-5"});
  expect_fired(f, "below dt_min");
  EXPECT_NE(f.result.output.find("(set by the viscous limit)"), std::string::npos);
}

// A box dropped into water lands on the floor; with the overlap allowed at 1e-7 d0 (2e-9 m; the
// default is half a spacing) the landing's contact overlap, 6.5e-6 m at E = 3e10 Pa, fires
// the contact guard and names the body and the wall.
TEST(Guards, ContactOverlapNamesBodyAndWall) {
  const fs::path dir = fs::path(testing::TempDir()) / "guard_overlap";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Fired f;
  f.result = test::run_washout(
      {"run", std::string(WASHOUT_SOURCE_DIR) + "/scenes/stability/box_drop_2d.lua", "--out",
       dir.string(), "--quiet", "--threads", "1", "--set", "d0=0.02", "--set",
       "contact_overlap_limit=1e-7"},
      (dir / "log.txt").string(), 120.0);
  f.file = dir / "box_drop_2d.h5";
  expect_fired(f, "body 'box' overlaps wall 'tank' by ");
}

// A plate teleported 2 cm into a column of 200 particles (tests/data/wall_jump.lua): 20 of them
// are inside it after one step, more than the crossing guard's floor of 10 (2 % of 200 is 4).
TEST(Guards, WallCrossingsStopTheRun) {
  const fs::path dir = fs::path(testing::TempDir()) / "guard_crossing";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Fired f;
  f.result =
      test::run_washout({"run", std::string(WASHOUT_SOURCE_DIR) + "/tests/data/wall_jump.lua",
                         "--out", dir.string(), "--quiet", "--threads", "1"},
                        (dir / "log.txt").string(), 120.0);
  f.file = dir / "wall_jump.h5";
  expect_fired(f, "wall crossings: ");
  EXPECT_NE(f.result.output.find("more than wall_crossing_limit = 0.02 of the 200 fluid particles"),
            std::string::npos)
      << f.result.output;
  // With the guard off the 20 are pushed out, those put back onto another particle moving on
  // to a free place, and the run goes on (before the fourteenth session the energy guard fired a
  // step later): the guard is what stops such a step, and it names the cause.
  const fs::path off = dir / "off";
  const auto unguarded = test::run_washout(
      {"run", std::string(WASHOUT_SOURCE_DIR) + "/tests/data/wall_jump.lua", "--out", off.string(),
       "--quiet", "--threads", "1", "--set", "wall_crossing_limit=0"},
      (dir / "log_off.txt").string(), 120.0);
  EXPECT_EQ(unguarded.status, 0) << unguarded.output;
  EXPECT_EQ(unguarded.output.find("wall crossings: "), std::string::npos);
  EXPECT_NE(unguarded.output.find("moved to a free place"), std::string::npos) << unguarded.output;
  EXPECT_NE(f.result.output.find("(step 21): wall crossings: 20 fluid particles"),
            std::string::npos);
}

// The same jump with the crossing guard off, seen frame by frame: the 20 particles inside the
// plate are put back d0/2 outside its face, onto the column's last row (before the fix, exactly
// onto those particles: separation 0, and the energy guard fired two steps later); each one put
// back onto another particle moves on to a free place instead, so that after the jump no two
// fluid particles are closer than d0/2 and the run goes on.
TEST(Guards, ParticlesPutBackOutOfAWallDoNotLandOnEachOther) {
  const fs::path dir = fs::path(testing::TempDir()) / "guard_put_back";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const auto result = test::run_washout(
      {"run", std::string(WASHOUT_SOURCE_DIR) + "/tests/data/wall_jump.lua", "--out", dir.string(),
       "--quiet", "--threads", "1", "--set", "wall_crossing_limit=0", "--set", "end_time=0.022",
       "--set", "output_interval=0.001"},
      (dir / "log.txt").string(), 120.0);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_NE(result.output.find("moved to a free place"), std::string::npos) << result.output;
  io::RunFileReader file((dir / "wall_jump.h5").string());
  const double d0 = file.d0();
  for (std::size_t f = file.frame_count() - 3; f < file.frame_count(); ++f) {
    const auto frame = file.read_frame(f);
    double closest2 = 1e300;
    for (std::size_t i = 0; i < frame.kind.size(); ++i)
      for (std::size_t j = i + 1; j < frame.kind.size(); ++j) {
        if (frame.kind[i] != 0 || frame.kind[j] != 0) continue;
        const double dx = frame.position[2 * i] - frame.position[2 * j];
        const double dy = frame.position[2 * i + 1] - frame.position[2 * j + 1];
        closest2 = std::min(closest2, dx * dx + dy * dy);
      }
    std::printf("frame %zu (t = %.3f s): closest fluid particles %.4f m apart (d0 = %g m)\n", f,
                file.frame_times()[f], std::sqrt(closest2), d0);
    EXPECT_GE(std::sqrt(closest2), 0.5 * d0);
  }
}

}  // namespace
}  // namespace washout
