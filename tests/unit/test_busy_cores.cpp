// The note a run prints when other processes leave its threads too few cores
// (engine/cli/busy_cores.hpp): /proc/stat's ticks read right, the other processes' share taken
// without the run's own, and the note said exactly when a thread will wait for a core.
#include <gtest/gtest.h>

#include <cstdio>

#include "engine/cli/busy_cores.hpp"

namespace washout {
namespace {

// Two cores; then 100 ticks later (1 s at 100 Hz on two cores: 200 ticks in all) with `busy` of
// them spent busy.
const char* kBefore =
    "cpu  1000 0 500 8000 100 0 0 0 0 0\n"
    "cpu0 500 0 250 4000 50 0 0 0 0 0\n"
    "cpu1 500 0 250 4000 50 0 0 0 0 0\n"
    "intr 12345\n";

std::string after_with(int busy) {
  char text[256];
  std::snprintf(text, sizeof text,
                "cpu  %d 0 500 %d 100 0 0 0 0 0\ncpu0 0 0 0 0 0 0 0 0 0 0\n"
                "cpu1 0 0 0 0 0 0 0 0 0 0\n",
                1000 + busy, 8000 + 200 - busy);
  return text;
}

TEST(BusyCores, ReadsTheMachinesTicksAndCores) {
  const auto t = parse_machine_ticks(kBefore);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->total, 9600u);
  EXPECT_EQ(t->busy, 1500u);  // idle and iowait left out
  EXPECT_EQ(t->cores, 2);
  EXPECT_FALSE(parse_machine_ticks("intr 1 2 3\n").has_value());
  EXPECT_FALSE(parse_machine_ticks("cpu  1 2\n").has_value());  // a line cut short
}

TEST(BusyCores, TakesTheOtherProcessesShareWithoutTheRunsOwn) {
  const auto before = parse_machine_ticks(kBefore);
  // Both cores busy for the second, one of them by this run (1 s of its own processor time):
  // one core busy elsewhere.
  const auto both = parse_machine_ticks(after_with(200));
  const double elsewhere = cores_busy_elsewhere(*before, *both, 1.0, 1.0);
  std::printf("both cores busy, one by the run: %.3f cores elsewhere\n", elsewhere);
  EXPECT_NEAR(elsewhere, 1.0, 1e-12);
  // Only the run's own core busy: none elsewhere.
  const auto own = parse_machine_ticks(after_with(100));
  EXPECT_NEAR(cores_busy_elsewhere(*before, *own, 1.0, 1.0), 0.0, 1e-12);
  // No ticks between the readings: nothing can be told, nothing is said to be busy.
  EXPECT_EQ(cores_busy_elsewhere(*before, *before, 0.0, 1.0), 0.0);
}

TEST(BusyCores, NotesOnlyThreadsThatWillWaitForACore) {
  // Two cores, two threads: quiet, a little background work, then one core taken.
  EXPECT_TRUE(busy_cores_note(2, 2, 0.05).empty());
  EXPECT_TRUE(busy_cores_note(2, 2, 0.45).empty());
  const std::string busy = busy_cores_note(2, 2, 1.0);
  std::printf("%s\n", busy.c_str());
  EXPECT_NE(busy.find("1.0 of the 2 cores"), std::string::npos);
  EXPECT_NE(busy.find("--threads 1"), std::string::npos);
  // One thread never waits for another.
  EXPECT_TRUE(busy_cores_note(1, 2, 1.9).empty());
  // Sixteen cores, eight threads beside four busy cores: room enough.
  EXPECT_TRUE(busy_cores_note(8, 16, 4.0).empty());
  EXPECT_NE(busy_cores_note(16, 16, 4.0).find("--threads 12"), std::string::npos);
  // The same threshold as the note's, for the cost line and the study's rows.
  EXPECT_FALSE(threads_lack_cores(2, 2, 0.45));
  EXPECT_TRUE(threads_lack_cores(2, 2, 0.5));
  EXPECT_FALSE(threads_lack_cores(1, 2, 1.9));
}

}  // namespace
}  // namespace washout
