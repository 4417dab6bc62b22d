// SIGTERM and SIGINT during a run (INTERFACE.md, exit 4): the run finishes its step, writes a
// last frame, the body CSV and the summary, closes the file and exits 4; a second signal ends
// it at once, also with 4. The run file is readable afterwards in both cases.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "engine/io/run_file_reader.hpp"
#include "reliability/run_washout.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;

// Starts a long scene, waits until two frames are on disk, sends `signals` signals 0.1 s apart.
test::ProgramResult interrupt_run(const fs::path& out, int signals, int sig = SIGTERM,
                                  const char* scene_name = "interrupt_body") {
  fs::remove_all(out);
  fs::create_directories(out);
  const std::string scene = std::string(WASHOUT_SOURCE_DIR) + "/tests/data/" + scene_name + ".lua";
  const auto log = (out / "log.txt").string();
  const pid_t pid = test::start_washout({"run", scene, "--out", out.string(), "--quiet"}, log);
  // The quiet log prints one line per frame: wait for frame 1 (or give up after 60 s).
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < std::chrono::seconds(60)) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    if (text.str().find("frame    1 ") != std::string::npos) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const auto sent = std::chrono::steady_clock::now();
  for (int k = 0; k < signals; ++k) {
    if (k > 0) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    kill(pid, sig);
  }
  auto r = test::wait_washout(pid, log, 120);
  std::printf("%s: ended %.2f s after the first signal\n", out.filename().c_str(),
              std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count());
  return r;
}

TEST(Interrupt, SigtermEndsTheRunCleanlyWithStatusFour) {
  const fs::path out = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "interrupt_once";
  const auto r = interrupt_run(out, 1);
  EXPECT_EQ(r.signal, 0) << r.output;
  EXPECT_EQ(r.status, 4) << r.output;
  EXPECT_NE(r.output.find("interrupted by SIGTERM"), std::string::npos) << r.output;
  io::RunFileReader reader((out / "interrupt_body.h5").string());
  ASSERT_GE(reader.frame_count(), 2u);
  const auto last = reader.read_frame(reader.frame_count() - 1);
  EXPECT_GT(last.count, 0u);
  EXPECT_LT(last.time, 100.0);
  // The summary attributes and the body report are written after the loop.
  EXPECT_TRUE(reader.has_attribute("/", "wall_seconds"));
  EXPECT_TRUE(reader.has("/bodies/block"));
  EXPECT_TRUE(fs::exists(out / "block.csv"));
}

TEST(Interrupt, SigintAlsoEndsWithStatusFour) {
  const fs::path out = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "interrupt_sigint";
  const auto r = interrupt_run(out, 1, SIGINT);
  EXPECT_EQ(r.status, 4) << r.output;
  EXPECT_NE(r.output.find("interrupted by SIGINT"), std::string::npos) << r.output;
}

TEST(Interrupt, SecondSignalEndsAtOnceAndLeavesAReadableFile) {
  // Each step of this scene takes 0.3 s: the second signal, 0.1 s after the first, arrives
  // inside the step and must end the run without waiting for it.
  const fs::path out = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "interrupt_twice";
  const auto start = std::chrono::steady_clock::now();
  const auto r = interrupt_run(out, 2, SIGTERM, "interrupt_slow");
  EXPECT_EQ(r.signal, 0) << r.output;
  EXPECT_EQ(r.status, 4) << r.output;
  EXPECT_NE(r.output.find("second signal"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("cost:"), std::string::npos) << r.output;  // no summary: at once
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 30);
  io::RunFileReader reader((out / "interrupt_slow.h5").string());
  EXPECT_GE(reader.frame_count(), 2u);
  EXPECT_GT(reader.read_frame(1).count, 0u);
}

// Not a signal but a scene error during the run (exit 1): the steps before it stay in the file,
// flushed, and get their body report as after any other stopped run.
TEST(Interrupt, ALuaErrorMidRunKeepsTheStepsBeforeItAndTheirBodyReport) {
  const fs::path out = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "midrun_lua_error";
  fs::remove_all(out);
  const std::string scene = std::string(WASHOUT_SOURCE_DIR) + "/tests/data/body_late_error.lua";
  const auto r = test::run_washout({"run", scene, "--out", out.string(), "--quiet"},
                                   (out.string() + ".log"), 60);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("the scene's own check failed"), std::string::npos) << r.output;
  io::RunFileReader reader((out / "body_late_error.h5").string());
  // The error comes in step 50 (t > 0.05 s): its row and the 49 before it, not only the 40 of
  // the last frame.
  const auto time = reader.read_doubles("/stats/time");
  ASSERT_EQ(time.size(), 50u);
  EXPECT_EQ(reader.read_doubles("/bodies/block/time").size(), 50u);
  std::ifstream csv(out / "block.csv");
  ASSERT_TRUE(csv) << "no body report after the error";
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 51);  // the header and one row per step
  EXPECT_NE(r.output.find("block: wave arrives"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace washout
