// Checkpoint and restart (issue 16, docs/reliability.md "Restart"): a run continued with
// `washout run SCENE --restart RUN.h5` is, bit for bit, the run that never stopped (at the same
// thread count): every frame (time, step, position, velocity, pressure, kind, id, body), every
// per-step series (/stats but wall_seconds, /probes, /bodies) and the body CSVs. Three ways to
// stop: a run that ended at an earlier end_time, SIGKILL, SIGTERM (which adds a frame of its
// own at the moment it stopped, without a checkpoint: the restart replaces it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "engine/io/run_file_reader.hpp"
#include "reliability/run_washout.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;
const std::string kScenes = std::string(WASHOUT_SOURCE_DIR) + "/scenes/";

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

struct Comparison {
  int frames = 0;        // frames of the uninterrupted run found, identical, in the other
  int frames_after = 0;  // of those, after `restart_time`
  int series = 0;        // per-step datasets compared
  std::size_t series_rows = 0;
};

// Every frame and per-step series of `reference` must be in `restarted`, bit for bit (a frame
// matched by its time: a run stopped by SIGTERM has one frame more, at the moment it stopped).
Comparison expect_same_run(const fs::path& reference, const fs::path& restarted,
                           double restart_time) {
  Comparison c;
  io::RunFileReader a(reference.string()), b(restarted.string());
  const auto times_a = a.frame_times(), times_b = b.frame_times();
  std::map<double, std::size_t> frame_of;
  for (std::size_t k = 0; k < times_b.size(); ++k) frame_of[times_b[k]] = k;
  EXPECT_GE(times_b.size(), times_a.size());
  for (std::size_t k = 0; k < times_a.size(); ++k) {
    const auto it = frame_of.find(times_a[k]);
    if (it == frame_of.end()) {
      ADD_FAILURE() << restarted << " has no frame at t = " << times_a[k];
      continue;
    }
    const io::FrameData x = a.read_frame(k), y = b.read_frame(it->second);
    const bool same = x.step == y.step && same_bits(x.position, y.position) &&
                      same_bits(x.velocity, y.velocity) && same_bits(x.pressure, y.pressure) &&
                      same_bits(x.kind, y.kind) && same_bits(x.id, y.id) &&
                      same_bits(x.body, y.body);
    EXPECT_TRUE(same) << "frame " << k << " (t = " << times_a[k] << " s) differs";
    c.frames += same;
    c.frames_after += same && times_a[k] > restart_time + 1e-9;
  }
  std::vector<std::string> datasets;
  for (const auto& name : a.children("/stats"))
    if (name != "wall_seconds") datasets.push_back("/stats/" + name);
  for (const std::string group : {"/probes", "/bodies"})
    for (const auto& member : a.children(group))
      for (const auto& name : a.children(group + "/" + member))
        datasets.push_back(group + "/" + member + "/" + name);
  for (const auto& d : datasets) {
    if (!b.has(d)) {
      ADD_FAILURE() << restarted << " lacks " << d;
      continue;
    }
    const auto x = a.read_doubles(d), y = b.read_doubles(d);
    EXPECT_TRUE(same_bits(x, y)) << d << " differs (" << x.size() << " and " << y.size()
                                 << " values)";
    ++c.series;
    c.series_rows = std::max(c.series_rows, a.shape(d)[0]);
  }
  // A finished run's summary is written again at the end of the continued one.
  EXPECT_TRUE(b.has_attribute("/", "wall_seconds"));
  return c;
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The frame a restart continued from, from its first line.
int continued_from(const std::string& output) {
  const auto at = output.find(" from frame ");
  return at == std::string::npos ? -1 : std::atoi(output.c_str() + at + 12);
}

// `run` whole into work/full, and again into work/part stopped at its own end_time = `split`
// (0.15 s unless given), then continued there with --restart (to the end_time in `run` or the
// scene's). `run_file`: the scene's run file name.
struct ContinuedRun {
  test::ProgramResult full;  // the uninterrupted run's output
  test::ProgramResult rest;  // the continuation's output
  fs::path file;             // work/part's run file, continued
};
ContinuedRun run_whole_and_in_two(const fs::path& work, const std::vector<std::string>& run,
                                  const std::string& run_file = "dambreak_2d.h5",
                                  const std::string& split = "0.15") {
  fs::remove_all(work);
  fs::create_directories(work);  // for the first run's log
  ContinuedRun c;
  c.full = test::run_washout(with(run, {"--out", (work / "full").string()}),
                             (work / "full.log").string(), 120);
  EXPECT_EQ(c.full.status, 0) << c.full.output;
  const auto half = test::run_washout(
      with(run, {"--out", (work / "part").string(), "--set", "end_time=" + split}),
      (work / "half.log").string(), 120);
  EXPECT_EQ(half.status, 0) << half.output;
  c.file = work / "part" / run_file;
  c.rest = test::run_washout(with(run, {"--restart", c.file.string()}),
                             (work / "rest.log").string(), 120);
  return c;
}

TEST(Restart, DamBreakContinuedToALaterEndTimeIsTheUninterruptedRun) {
  const fs::path work = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "restart_dambreak";
  const std::vector<std::string> run = {
      "run", kScenes + "dambreak_2d.lua", "--set", "d0=0.0146", "--threads", "1", "--quiet"};
  // The first half, stopped at 0.15 s, then continued to the scene's 0.3 s.
  const auto [full, rest, file] = run_whole_and_in_two(work, run);
  ASSERT_EQ(rest.status, 0) << rest.output;
  EXPECT_EQ(continued_from(rest.output), 30) << rest.output;
  const Comparison c = expect_same_run(work / "full" / "dambreak_2d.h5", file, 0.15);
  EXPECT_EQ(c.frames, 61);
  EXPECT_EQ(c.frames_after, 30);
  EXPECT_GE(c.series, 13);  // every /stats series (not wall_seconds), 2 probes x (time, value)
  // The rendered frames go on with the same numbers (every 4th frame) and the same pixels.
  int pngs = 0;
  for (const auto& entry : fs::directory_iterator(work / "full" / "frames")) {
    const fs::path other = work / "part" / "frames" / entry.path().filename();
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_EQ(test::read_text(entry.path()), test::read_text(other)) << other;
    ++pngs;
  }
  EXPECT_EQ(pngs, 16);
  // Continuing a finished run again does nothing and says so.
  const auto again = test::run_washout(with(run, {"--restart", file.string()}),
                                       (work / "again.log").string(), 120);
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("already reached end_time"), std::string::npos) << again.output;
  EXPECT_EQ(io::RunFileReader(file.string()).frame_count(), 61u);
  std::printf(
      "dam break: %d frames (%d after the restart at t = 0.15 s) and %d series of %zu "
      "rows bitwise equal\n",
      c.frames, c.frames_after, c.series, c.series_rows);
}

// Fluid that left the domain stays retired across a restart: the surge of the same dam break
// flows out 2 cm beyond the column's foot (escape_limit = 1), the run is stopped at 0.15 s,
// after the first particles left, and continued to 0.2 s. The fluid is sorted by cell every 7
// steps (the retired go last), so the checkpoint holds the fluid in an order of its own.
TEST(Restart, RetiredFluidStaysRetired) {
  const fs::path work = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "restart_retired";
  const std::vector<std::string> run = {"run",       kScenes + "dambreak_2d.lua",
                                        "--set",     "d0=0.0146",
                                        "--set",     "end_time=0.2",
                                        "--set",     "domain_min={-0.1,-0.1}",
                                        "--set",     "domain_max={0.17,0.5}",
                                        "--set",     "escape_limit=1",
                                        "--set",     "reorder_interval=7",
                                        "--threads", "1",
                                        "--quiet"};
  const auto [full, rest, file] = run_whole_and_in_two(work, run);
  ASSERT_EQ(rest.status, 0) << rest.output;
  // Particles had left before the restart, or the test would not test it.
  io::RunFileReader continued(file.string());
  const auto time = continued.read_doubles("/stats/time");
  const auto retired = continued.read_doubles("/stats/retired_particles");
  const auto at_restart = std::lower_bound(time.begin(), time.end(), 0.15 - 1e-9) - time.begin();
  ASSERT_LT(at_restart, static_cast<long>(retired.size()));
  EXPECT_GT(retired[at_restart], 0.0);
  const Comparison c = expect_same_run(work / "full" / "dambreak_2d.h5", file, 0.15);
  EXPECT_GE(c.frames_after, 10);
  EXPECT_NE(rest.output.find("fluid particles retired as they left the domain: "),
            std::string::npos)
      << rest.output;
  std::printf("retired fluid: %d frames (%d after the restart at t = 0.15 s) bitwise equal\n",
              c.frames, c.frames_after);
}

// The sinking box at rest on the floor: contact springs with friction, the body's velocity
// solved with the pressure (implicit coupling, its solves warm-started from the last step's
// response fields), particle shifting. Killed with Jacobi PCG, stopped by SIGTERM with
// BoomerAMG PCG and the aggregates' PCG (a set-up serves 20 and 10 solves, 4 a step here: with
// 21 steps a frame, one would carry over a frame if the solver did not start afresh there).
std::vector<std::string> box_run(const std::string& solver) {
  return {"run",       kScenes + "sinking_box_2d.lua",
          "--set",     "d0=0.01",
          "--set",     "drop=0.01",
          "--set",     "output_interval=0.021",
          "--set",     "end_time=0.3",
          "--set",     "solver=" + solver,
          "--threads", "1",
          "--quiet"};
}

// The uninterrupted box run (each test makes its own: ctest runs them side by side).
fs::path box_reference(const std::string& name, const std::string& solver) {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / name;
  fs::remove_all(dir);
  const auto r =
      test::run_washout(with(box_run(solver), {"--out", dir.string()}), dir.string() + ".log", 120);
  EXPECT_EQ(r.status, 0) << r.output;
  return dir;
}

// Starts the box run into `dir`, waits for frame 3 in its log and sends `sig`.
test::ProgramResult stop_box_run(const fs::path& dir, const std::string& solver, int sig) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string log = (dir / "first.log").string();
  const pid_t pid = test::start_washout(with(box_run(solver), {"--out", dir.string()}), log);
  test::wait_for_log(log, "frame    3 ", 60);
  kill(pid, sig);
  return test::wait_washout(pid, log, 120);
}

TEST(Restart, BodyInContactKilledAndRestartedIsTheUninterruptedRun) {
  const fs::path reference = box_reference("restart_box_killed_reference", "pcg");
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "restart_box_killed";
  const auto first = stop_box_run(dir, "pcg", SIGKILL);
  ASSERT_EQ(first.signal, SIGKILL) << "the run ended before it was killed:\n" << first.output;
  const fs::path file = dir / "sinking_box_2d.h5";
  const auto rest = test::run_washout(with(box_run("pcg"), {"--restart", file.string()}),
                                      (dir / "rest.log").string(), 120);
  ASSERT_EQ(rest.status, 0) << rest.output;
  const int from = continued_from(rest.output);
  EXPECT_GE(from, 3) << rest.output;
  EXPECT_LT(from, 15) << rest.output;
  const double restart_time = 0.021 * from;
  const Comparison c = expect_same_run(reference / "sinking_box_2d.h5", file, restart_time);
  EXPECT_EQ(c.frames, 16);
  EXPECT_EQ(c.frames_after, 15 - from);
  // 0.3 s at dt_max = 1 ms, and the few shorter steps of the landing (one since particles put
  // back onto another move to a free place).
  EXPECT_GE(c.series_rows, 300u);
  EXPECT_LE(c.series_rows, 310u);
  EXPECT_EQ(test::read_text(reference / "box.csv"), test::read_text(dir / "box.csv"));
  std::printf(
      "box killed by SIGKILL, continued from frame %d: %d frames (%d after it) and %d "
      "series of %zu rows bitwise equal, box.csv equal\n",
      from, c.frames, c.frames_after, c.series, c.series_rows);
}

// Stopped by SIGTERM with a solver whose set-up serves several solves (`solver`, its name in
// the printout), continued from the last grid frame: the uninterrupted run, bit for bit.
void expect_sigterm_restart_is_uninterrupted(const std::string& solver, const std::string& name) {
  const fs::path reference = box_reference(name + "_reference", solver);
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / name;
  const auto first = stop_box_run(dir, solver, SIGTERM);
  ASSERT_EQ(first.status, 4) << first.output;
  const fs::path file = dir / "sinking_box_2d.h5";
  const auto rest = test::run_washout(with(box_run(solver), {"--restart", file.string()}),
                                      (dir / "rest.log").string(), 120);
  ASSERT_EQ(rest.status, 0) << rest.output;
  const int from = continued_from(rest.output);
  EXPECT_GE(from, 3) << rest.output;
  const Comparison c = expect_same_run(reference / "sinking_box_2d.h5", file, 0.021 * from);
  EXPECT_EQ(c.frames, 16);
  // The frame SIGTERM wrote between two grid frames has no checkpoint and was replaced.
  EXPECT_EQ(io::RunFileReader(file.string()).frame_count(), 16u);
  // 0.3 s at dt_max = 1 ms, and the few shorter steps of the landing (one since particles put
  // back onto another move to a free place).
  EXPECT_GE(c.series_rows, 300u);
  EXPECT_LE(c.series_rows, 310u);
  EXPECT_EQ(test::read_text(reference / "box.csv"), test::read_text(dir / "box.csv"));
  std::printf(
      "box (%s) stopped by SIGTERM, continued from frame %d: %d frames and %d series bitwise "
      "equal\n",
      solver.c_str(), from, c.frames, c.series);
}

TEST(Restart, BodyInContactStoppedBySigtermAndRestartedIsTheUninterruptedRun) {
  expect_sigterm_restart_is_uninterrupted("pcg_amg", "restart_box_sigterm");
}

// The aggregates' set-up serves 10 solves (4 a step here): it too must start afresh at a frame.
TEST(Restart, BodyInContactWithTheAggregatesSolverRestartedIsTheUninterruptedRun) {
  expect_sigterm_restart_is_uninterrupted("pcg_agg", "restart_box_sigterm_agg");
}

// The 2D girder asleep on its pier (no contact sub-steps: docs/rigid_bodies.md "Rest") when the
// first part ends at 0.3 s; the continuation must sleep on and wake at the same step (0.576 s,
// fluid within reach) and then be the uninterrupted run through the wave's arrival (0.62 s).
TEST(Restart, GirderAsleepOnItsPierRestartedIsTheUninterruptedRun) {
  const fs::path work = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "restart_girder_asleep";
  const std::vector<std::string> run = {"run",       kScenes + "girder_washout_2d.lua",
                                        "--set",     "d0=0.02",
                                        "--set",     "end_time=0.7",
                                        "--threads", "1",
                                        "--quiet"};
  const auto [full, rest, file] = run_whole_and_in_two(work, run, "girder_washout_2d.h5", "0.3");
  ASSERT_EQ(rest.status, 0) << rest.output;
  const Comparison c = expect_same_run(work / "full" / "girder_washout_2d.h5", file, 0.3);
  EXPECT_EQ(test::read_text(work / "full" / "girder.csv"),
            test::read_text(work / "part" / "girder.csv"));
  // It was asleep at the restart and woke after it: sub-steps 0 at 0.3 s, and again above 0.
  const auto time = io::RunFileReader(file.string()).read_doubles("/stats/time");
  const auto substeps = io::RunFileReader(file.string()).read_doubles("/stats/substeps");
  int asleep_at_restart = 0, awake_after = 0;
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (std::abs(time[k] - 0.3) < 1e-9) asleep_at_restart = substeps[k] == 0.0;
    if (time[k] > 0.6) awake_after += substeps[k] > 0.0;
  }
  EXPECT_EQ(asleep_at_restart, 1);
  EXPECT_GT(awake_after, 0);
  // The summary counts the steps slept before the restart too.
  const auto asleep_line = [](const std::string& output) {
    const auto at = output.find("bodies asleep at rest");
    return at == std::string::npos ? std::string("(none)")
                                   : output.substr(at, output.find('\n', at) - at);
  };
  EXPECT_EQ(asleep_line(rest.output), asleep_line(full.output));
  EXPECT_NE(asleep_line(full.output), "(none)") << full.output;
  EXPECT_GE(c.series_rows, 700u);
  std::printf(
      "girder asleep at the restart (t = 0.3 s), awake by 0.6 s: %d frames (%d after it) and "
      "%d series of %zu rows bitwise equal, girder.csv equal\n",
      c.frames, c.frames_after, c.series, c.series_rows);
}

}  // namespace
}  // namespace washout
