// The body report of a finished run (engine/cli/body_report.hpp, docs/output.md "Body
// reports"): a synthetic wash-out series with known arrival, lift-off, peaks, displacement and
// rotation must be summarised exactly (to the row), and the CSV and the /bodies/NAME attributes
// must hold what the summary says.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "engine/cli/body_report.hpp"
#include "engine/io/run_file_writer.hpp"

namespace washout {
namespace {

constexpr double kDt = 0.001;  // one row per millisecond; row k is at t = (k + 1) dt
constexpr int kRows = 2000;
constexpr double kMass = 2.0;
const Vec3 kGravity(0, 0, -10);  // W = 20 N

double row_time(int k) { return (k + 1) * kDt; }

// A girder-like history, 3D, z up:
//  - dry until the wave: F_fluid = 0 for t <= 0.3 s;
//  - F_x = 50 sin(pi (t - 0.3) / 0.4) N on 0.3 < t < 0.7 (50 N at 0.5 s), then a -60 N
//    backwash pulse at 1.5 s (so the peak of largest magnitude is the negative one);
//  - F_z: +15 N uplift pulse at 0.45 s, -40 N downward pulse at 0.6 s;
//  - vertical contact W until row 619, a 20-row hop (0.02 s < 0.05 s: still on the support),
//    back until row 700, off for rows 700-899 (0.2 s: it has left), then W again (landed);
//    a constant 5 N side-wall push across (y) all along, which is not support;
//  - x moves 0.8 m/s after 0.7 s, z drops 0.06 m over 0.2 s; the angle starts at 0.01 rad,
//    turns +0.5 rad (peak at 1.0 s) and later -0.3 rad (a smaller peak of the other sign).
cli::BodyTrack synthetic_track() {
  cli::BodyTrack t;
  t.name = "girder";
  t.dim = 3;
  t.mass = kMass;
  const double pi = std::numbers::pi;
  for (int k = 0; k < kRows; ++k) {
    const double s = row_time(k);
    t.time.push_back(s);
    const double moved = s > 0.7 ? s - 0.7 : 0.0;
    t.position.insert(t.position.end(),
                      {1.0 + 0.8 * moved, 0.24, 0.09 - 0.06 * std::min(moved / 0.2, 1.0)});
    double angle = 0.01;
    if (s > 0.7 && s < 1.3) angle += 0.5 * std::sin(pi * (s - 0.7) / 0.6);
    angle -= 0.3 * std::exp(-std::pow((s - 1.7) / 0.05, 2));
    t.angle.push_back(angle);
    double fx = (s > 0.3 && s < 0.7) ? 50.0 * std::sin(pi * (s - 0.3) / 0.4) : 0.0;
    fx -= 60.0 * std::exp(-std::pow((s - 1.5) / 0.02, 2));
    double fz = 15.0 * std::exp(-std::pow((s - 0.45) / 0.02, 2)) -
                40.0 * std::exp(-std::pow((s - 0.6) / 0.02, 2));
    if (s <= 0.3) fz = 0.0;  // dry: the pulses' far tails would count as an early load
    t.force_fluid.insert(t.force_fluid.end(), {fx, 0.0, fz});
    const bool off = (k >= 619 && k < 639) || (k >= 700 && k < 900);
    t.force_contact.insert(t.force_contact.end(), {0.0, 5.0, off ? 0.0 : kMass * 10.0});
  }
  return t;
}

TEST(BodyReport, FindsTheKnownTimesAndPeaks) {
  const cli::BodyTrack track = synthetic_track();
  const cli::BodySummary s = cli::summarize_body(track, kGravity);
  // Arrival: the first row with |F| > 1 % of W = 0.2 N: 50 sin(pi (t - 0.3)/0.4) > 0.2.
  const double t_load = 0.3 + 0.4 * std::asin(0.2 / 50.0) / std::numbers::pi;
  int first = 0;
  while (row_time(first) <= t_load) ++first;
  std::printf("weight %.3f N; arrival %.4f s (expected %.4f); leave %.4f s (expected %.4f)\n",
              s.weight, s.arrival_time, row_time(first), s.leave_time, row_time(700));
  std::printf(
      "peak Fx %.3f N at %.4f s, peak Fz %.3f N at %.4f s, displacement (%.4f, %.4f, "
      "%.4f) m, peak angle %.4f rad at %.4f s\n",
      s.peak_force_horizontal, s.peak_force_horizontal_time, s.peak_force_vertical,
      s.peak_force_vertical_time, s.displacement[0], s.displacement[1], s.displacement[2],
      s.peak_angle, s.peak_angle_time);
  EXPECT_DOUBLE_EQ(s.weight, 20.0);
  EXPECT_DOUBLE_EQ(s.arrival_time, row_time(first));
  // The 0.02 s hop at rows 619-638 is shorter than the 0.05 s hold: not leaving.
  EXPECT_DOUBLE_EQ(s.leave_time, row_time(700));
  // Peaks: sampled on the rows, the pulses' centres are rows themselves.
  EXPECT_NEAR(s.peak_force_horizontal, -60.0, 1e-9);
  EXPECT_NEAR(s.peak_force_horizontal_time, 1.5, 1e-9);
  EXPECT_NEAR(s.peak_force_vertical, -40.0, 1e-6);
  EXPECT_NEAR(s.peak_force_vertical_time, 0.6, 1e-9);
  // Displacement: last row minus first row, 0.8 m/s over 1.3 s and 0.06 m down.
  EXPECT_NEAR(s.displacement[0], 0.8 * 1.3, 1e-9);
  EXPECT_NEAR(s.displacement[1], 0.0, 1e-12);
  EXPECT_NEAR(s.displacement[2], -0.06, 1e-9);
  // Rotation from the starting 0.01 rad: +0.5 at 1.0 s beats -0.3 at 1.7 s.
  EXPECT_NEAR(s.peak_angle, 0.5, 1e-9);
  EXPECT_NEAR(s.peak_angle_time, 1.0, 1e-9);
}

// A load that lasts one step only, above 10 W and twice both neighbours (the water under a
// landing body stopped in one step), is counted as a spike and left out of the peaks; the same
// load held for two steps is a load and stays in them; spike_weights = 0 keeps every load.
TEST(BodyReport, OneStepSpikesAreFlaggedNotKeptInThePeaks) {
  cli::BodyTrack t = synthetic_track();
  t.force_fluid[3 * 1200 + 2] = 500.0;  // 25 W for one step at t = 1.201 s
  cli::BodySummary s = cli::summarize_body(t, kGravity);
  std::printf("%s\n", cli::format_body_summary(t, s).c_str());
  EXPECT_EQ(s.load_spikes, 1);
  EXPECT_NEAR(s.largest_spike, 500.0, 1e-9);
  EXPECT_NEAR(s.largest_spike_time, row_time(1200), 1e-12);
  EXPECT_NEAR(s.peak_force_vertical, -40.0, 0.1);  // the pulse at 0.6 s, as without the spike
  EXPECT_NE(cli::format_body_summary(t, s).find("1 one-step load spike left out"),
            std::string::npos);
  t.force_fluid[3 * 1201 + 2] = 500.0;  // held for a second step: a real load
  s = cli::summarize_body(t, kGravity);
  EXPECT_EQ(s.load_spikes, 0);
  EXPECT_NEAR(s.peak_force_vertical, 500.0, 1e-9);
  t.force_fluid[3 * 1201 + 2] = 0.0;
  cli::BodyReportSettings keep_all;
  keep_all.spike_weights = 0;
  s = cli::summarize_body(t, kGravity, keep_all);
  EXPECT_EQ(s.load_spikes, 0);
  EXPECT_NEAR(s.peak_force_vertical, 500.0, 1e-9);
}

// A load reversing every step (the landed girder sliding on the floor, docs/stability.md), each
// step above 10 W, is eight spikes, not a peak; a load that keeps its direction is not.
TEST(BodyReport, ALoadReversingEveryStepIsFlaggedStepByStep) {
  cli::BodyTrack t = synthetic_track();
  for (int k = 1000; k < 1008; ++k) t.force_fluid[3 * k] = k % 2 == 0 ? 300.0 : -300.0;  // 15 W
  cli::BodySummary s = cli::summarize_body(t, kGravity);
  std::printf("%s\n", cli::format_body_summary(t, s).c_str());
  EXPECT_EQ(s.load_spikes, 8);
  EXPECT_NEAR(s.largest_spike, 300.0, 1e-9);
  EXPECT_NEAR(s.peak_force_horizontal, -60.0, 1e-9);  // the pulse at 1.5 s, as without them
  EXPECT_NEAR(std::abs(s.peak_force_horizontal_one_step), 300.0, 1e-9);  // shown, not kept
  for (int k = 1000; k < 1008; ++k) t.force_fluid[3 * k] = k % 2 == 0 ? 300.0 : 250.0;
  s = cli::summarize_body(t, kGravity);
  EXPECT_EQ(s.load_spikes, 0);
  EXPECT_NEAR(s.peak_force_horizontal, 300.0, 1e-9);
}

TEST(BodyReport, ABodyNeverReachedNorReleasedHasNoTimes) {
  cli::BodyTrack track = synthetic_track();
  for (auto& f : track.force_fluid) f = 0.0;
  for (std::size_t k = 0; k < track.rows(); ++k) track.force_contact[3 * k + 2] = 20.0;
  const cli::BodySummary s = cli::summarize_body(track, kGravity);
  EXPECT_TRUE(std::isnan(s.arrival_time));
  EXPECT_TRUE(std::isnan(s.leave_time));
  EXPECT_TRUE(std::isnan(s.peak_force_horizontal_time));
  EXPECT_EQ(s.peak_force_horizontal, 0.0);
  // A body never carried (a floating one) never "leaves its support" either, even though its
  // contact is zero throughout.
  for (auto& f : track.force_contact) f = 0.0;
  EXPECT_TRUE(std::isnan(cli::summarize_body(track, kGravity).leave_time));
}

TEST(BodyReport, TwoDimensionalSeriesUseYAsVertical) {
  cli::BodyTrack track = synthetic_track();
  track.dim = 2;
  // Rotate the synthetic history into the (x, y) plane: z becomes y.
  for (auto* v : {&track.position, &track.force_fluid, &track.force_contact})
    for (std::size_t k = 0; k < track.rows(); ++k) {
      std::swap((*v)[3 * k + 1], (*v)[3 * k + 2]);
      (*v)[3 * k + 2] = 0.0;
    }
  const cli::BodySummary s = cli::summarize_body(track, Vec3(0, -10, 0));
  EXPECT_DOUBLE_EQ(s.leave_time, row_time(700));
  EXPECT_NEAR(s.peak_force_vertical, -40.0, 1e-6);
  EXPECT_NEAR(s.displacement[1], -0.06, 1e-9);
  std::printf("2D: leave %.4f s, peak vertical %.3f N/m\n", s.leave_time, s.peak_force_vertical);
}

// Writes a run file holding only /bodies/girder, as the engine writes it.
std::string write_run_file(const cli::BodyTrack& track, const std::filesystem::path& dir) {
  const std::string path = (dir / "synthetic.h5").string();
  io::RunHeader header;
  header.scene_name = "synthetic";
  header.dim = 3;
  header.d0 = 0.01;
  io::RunFileWriter w(path, header);
  const std::string g = "/bodies/" + track.name;
  w.set_string_attribute(g, "mass", "2");
  w.append(g + "/time", track.time.data(), track.rows());
  w.append(g + "/position", track.position.data(), track.rows(), 3);
  w.append(g + "/angle", track.angle.data(), track.rows());
  w.append(g + "/force_fluid", track.force_fluid.data(), track.rows(), 3);
  w.append(g + "/force_contact", track.force_contact.data(), track.rows(), 3);
  return path;
}

double read_attribute(const std::string& file, const std::string& object, const char* name,
                      int index = 0) {
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  hid_t g = H5Gopen2(f, object.c_str(), H5P_DEFAULT);
  hid_t a = H5Aopen(g, name, H5P_DEFAULT);
  double values[3] = {NAN, NAN, NAN};
  if (a >= 0) H5Aread(a, H5T_NATIVE_DOUBLE, values);
  H5Aclose(a);
  H5Gclose(g);
  H5Fclose(f);
  return values[index];
}

TEST(BodyReport, WritesTheCsvAndTheAttributes) {
  const auto dir = std::filesystem::path(WASHOUT_TEST_OUTPUT_DIR) / "body_report";
  std::filesystem::create_directories(dir);
  const cli::BodyTrack track = synthetic_track();
  const std::string h5 = write_run_file(track, dir);
  const auto reports = cli::report_bodies(h5, dir.string(), kGravity, stdout);
  ASSERT_EQ(reports.size(), 1u);
  EXPECT_EQ(reports[0].name, "girder");
  const cli::BodySummary expected = cli::summarize_body(track, kGravity);

  std::ifstream csv(reports[0].csv_path);
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  EXPECT_EQ(line, "time,x,y,z,angle,fluid_fx,fluid_fy,fluid_fz,contact_fx,contact_fy,contact_fz");
  int rows = 0;
  std::string row_701;
  while (std::getline(csv, line)) {
    if (rows == 700) row_701 = line;
    ++rows;
  }
  EXPECT_EQ(rows, kRows);
  // Row 700 (t = 0.701 s): the first row off the pier, moving at 0.8 m/s for 1 ms.
  EXPECT_EQ(row_701.substr(0, row_701.find(',')), "0.701");
  EXPECT_NE(row_701.find(",1.0008,0.24,"), std::string::npos) << row_701;

  const std::string g = "/bodies/girder";
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "arrival_time"), expected.arrival_time);
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "leave_time"), expected.leave_time);
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "peak_force_horizontal"), expected.peak_force_horizontal);
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "peak_force_vertical"), expected.peak_force_vertical);
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "peak_angle"), expected.peak_angle);
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "weight"), 20.0);
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "final_displacement", 0), expected.displacement[0]);
  EXPECT_DOUBLE_EQ(read_attribute(h5, g, "final_displacement", 2), expected.displacement[2]);
  // Reporting twice (a re-run of the report) replaces the attributes instead of failing.
  EXPECT_NO_THROW(cli::report_bodies(h5, dir.string(), kGravity, nullptr));
}

TEST(BodyReport, ARunWithoutBodiesReportsNothing) {
  const auto dir = std::filesystem::path(WASHOUT_TEST_OUTPUT_DIR) / "body_report_none";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "empty.h5").string();
  {
    io::RunHeader header;
    header.dim = 2;
    header.d0 = 0.01;
    io::RunFileWriter w(path, header);
  }
  EXPECT_TRUE(cli::report_bodies(path, dir.string(), Vec3(0, -9.81, 0), nullptr).empty());
  EXPECT_THROW(
      cli::report_bodies((dir / "missing.h5").string(), dir.string(), Vec3(0, -9.81, 0), nullptr),
      std::runtime_error);
}

}  // namespace
}  // namespace washout
