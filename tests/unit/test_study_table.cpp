// The study table's convergence fit and CSV (engine/cli/study_table.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "engine/cli/study_table.hpp"

namespace washout::cli {
namespace {

StudyRow row(const std::string& d0, double error, const std::string& status = "ok") {
  StudyRow r;
  r.values = {d0};
  r.status = status;
  r.exit_code = status == "ok" ? 0 : 2;
  r.wall_seconds = {3, 1, 2};
  r.errors = {{"front", error}};
  r.bounds = {{"front", 0.5}};
  return r;
}

// The table of rows over d0, written as CSV and read back: its header and each row, as lines.
std::vector<std::string> csv_lines(const std::vector<StudyRow>& rows, const std::string& name) {
  StudyTable t;
  t.names = {"d0"};
  t.rows = rows;
  const auto path = std::filesystem::temp_directory_path() / name;
  EXPECT_TRUE(t.write_csv(path.string()));
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  EXPECT_EQ(lines.size(), rows.size() + 1);
  lines.resize(rows.size() + 1);
  return lines;
}

TEST(StudyTable, SecondOrderErrorGivesOrderTwo) {
  StudyTable t;
  t.names = {"d0"};
  t.rows = {row("0.04", 0.16), row("0.02", 0.04), row("0.01", 0.01)};
  const auto fits = fit_convergence(t);
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_NEAR(fits[0].order, 2.0, 1e-12);
  EXPECT_TRUE(fits[0].converging);
  EXPECT_EQ(fits[0].points, 3);
}

TEST(StudyTable, RisingErrorIsNotConvergingAndUnstableRowsAreLeftOut) {
  StudyTable t;
  t.names = {"d0"};
  t.rows = {row("0.0146", 0.059), row("0.0073", 0.176), row("0.00365", NAN, "unstable")};
  const auto fits = fit_convergence(t);
  ASSERT_EQ(fits.size(), 1u);
  EXPECT_EQ(fits[0].points, 2);
  EXPECT_LT(fits[0].order, 0);
  EXPECT_FALSE(fits[0].converging);
  EXPECT_NE(fits[0].figures.find("d0 = 0.0073: 0.176"), std::string::npos) << fits[0].figures;
}

TEST(StudyTable, OtherVariedValuesMakeSeparateFits) {
  StudyTable t;
  t.names = {"alpha", "d0"};
  auto a = row("0.02", 0.1), b = row("0.01", 0.05), c = row("0.02", 0.1), d = row("0.01", 0.2);
  a.values = {"0.1", "0.02"}, b.values = {"0.1", "0.01"}, c.values = {"0.2", "0.02"},
  d.values = {"0.2", "0.01"};
  t.rows = {a, b, c, d};
  const auto fits = fit_convergence(t);
  ASSERT_EQ(fits.size(), 2u);
  EXPECT_EQ(fits[0].group, "alpha = 0.1");
  EXPECT_NEAR(fits[0].order, 1.0, 1e-12);
  EXPECT_NEAR(fits[1].order, -1.0, 1e-12);
}

TEST(StudyTable, CsvHasMinAndMedianWallTimeAndEmptyCellsForNan) {
  const auto lines =
      csv_lines({row("0.02", 0.1), row("0.01", NAN, "unstable")}, "washout_study_table.csv");
  const std::string &header = lines[0], &first = lines[1], &second = lines[2];
  EXPECT_EQ(header.rfind("d0,status,exit_code,particles", 0), 0u) << header;
  EXPECT_NE(first.find(",1,2,3,"), std::string::npos) << first;  // min 1, median 2, 3 repeats
  EXPECT_NE(second.find("unstable,2,"), std::string::npos) << second;
  EXPECT_NE(second.find(",,0.5,"), std::string::npos) << second;  // no error, bound 0.5
}

// A row's wall time is the machine's only when its threads found their cores: the study marks the
// rows whose threads outnumbered the cores other processes left idle, and writes both figures.
TEST(StudyTable, RowsWhoseThreadsWaitedForCoresAreMarked) {
  StudyRow quiet = row("0.02", 0.1), busy = row("0.01", 0.2), single = row("0.005", 0.3);
  quiet.threads = busy.threads = 2, single.threads = 1;
  quiet.cores = busy.cores = single.cores = 2;
  quiet.cores_busy_elsewhere = 0.1;
  busy.cores_busy_elsewhere = single.cores_busy_elsewhere = 1.0;
  EXPECT_FALSE(quiet.waited_for_cores());
  EXPECT_TRUE(busy.waited_for_cores());
  EXPECT_FALSE(single.waited_for_cores());            // one thread waits for no other
  EXPECT_FALSE(row("0.01", 0.2).waited_for_cores());  // an older run file: not known
  const auto lines = csv_lines({quiet, busy}, "washout_study_cores.csv");
  const std::string &header = lines[0], &first = lines[1], &second = lines[2];
  EXPECT_NE(header.find(",ppe_iterations_per_step,threads,cores_busy_elsewhere,"),
            std::string::npos)
      << header;
  EXPECT_NE(first.find(",2,0.1,"), std::string::npos) << first;
  EXPECT_NE(second.find(",2,1,"), std::string::npos) << second;
}

}  // namespace
}  // namespace washout::cli
