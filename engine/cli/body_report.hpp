#pragma once
// What a run with rigid bodies reports about each body once it has finished: one CSV of its
// motion and loads (DIR/NAME.csv) and a summary of the wash-out (when the wave first loads the
// body, when it leaves its support, the peak fluid forces, the final displacement, the peak
// rotation), printed and stored as attributes of /bodies/NAME. docs/output.md ("Body reports")
// documents the columns, the attributes and the definitions below.
#include <array>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "engine/core/vec3.hpp"

namespace washout::cli {

// One body's series as written to /bodies/NAME: one row per fluid step.
struct BodyTrack {
  std::string name;
  int dim = 3;
  double mass = 0.0;                // kg (2D: kg per metre)
  std::vector<double> time;         // [T] s
  std::vector<double> position;     // [T x 3] centre of mass, m
  std::vector<double> angle;        // [T] rad about the body's angle_axis
  std::vector<double> force_fluid;  // [T x 3] N (2D: N/m)
  std::vector<double> force_contact;
  std::vector<double> velocity;  // [T x 3] m/s; empty in files written without it
  std::size_t rows() const { return time.size(); }
};

// Thresholds of the definitions, as fractions of the body's weight W = M |g|.
struct BodyReportSettings {
  double arrival_fraction = 0.01;   // wave arrival: first row with |F_fluid| > 0.01 W
  double carried_fraction = 0.5;    // the support carried the body: upward contact >= 0.5 W
  double released_fraction = 0.01;  // ... and no longer: |vertical contact| < 0.01 W
  double release_hold = 0.05;       // s the contact must stay released to count as leaving
  // A load spike: a fluid force above spike_weights W that stands alone: each neighbouring
  // step's force is smaller by more than spike_ratio (the water under a landing body stopped in
  // one step: its size grows as 1/dt) or points the other way (a load reversing every step, as
  // under a landed girder sliding on the floor; docs/stability.md). It is counted and left out of
  // the peaks.
  double spike_weights = 10.0;  // 0: every load counts in the peaks
  double spike_ratio = 2.0;
  // The window of the windowed peaks (engine/cli/landing_load.hpp): 10 fluid steps at the
  // default dt_max = 1 ms, so the mean spans many steps at any dt a run takes, and short beside
  // the rise of a wave's load on a girder (about 0.1 s).
  double load_window = 0.01;  // s
  // The span of a landing's impulse, long enough to hold the landing's hops (the sinking box's
  // second hop can land 0.03 s after its first contact) and the outflow of the water it squeezes:
  // over 0.05 s the box's impulse stays within 11 % of its mid-range over a 4x change of dt,
  // over 0.01 s it changes by up to 2x (docs/stability.md, "Landing loads").
  double landing_duration = 0.05;  // s
};

constexpr double kNotFound = std::numeric_limits<double>::quiet_NaN();

struct BodySummary {
  double weight = 0.0;                 // M |g|
  double arrival_time = kNotFound;     // s; NaN: the fluid never loaded the body
  double leave_time = kNotFound;       // s; NaN: it never left its support
  double peak_force_horizontal = 0.0;  // the x force of largest magnitude (signed)
  double peak_force_horizontal_time = kNotFound;
  double peak_force_vertical = 0.0;  // the upward force of largest magnitude (signed)
  double peak_force_vertical_time = kNotFound;
  std::array<double, 3> displacement{};  // last row minus first row, m
  double peak_angle = 0.0;               // angle - angle(first row) of largest magnitude, rad
  double peak_angle_time = kNotFound;
  int load_spikes = 0;         // one-step spikes left out of the peak forces
  double largest_spike = 0.0;  // |F_fluid| of the largest of them
  double largest_spike_time = kNotFound;
  // The same two extremes over every row, one-step spikes included: the raw per-step load,
  // whose landing peak grows as 1/dt (kept to show it, not to design with).
  double peak_force_horizontal_one_step = 0.0;
  double peak_force_horizontal_one_step_time = kNotFound;
  double peak_force_vertical_one_step = 0.0;
  double peak_force_vertical_one_step_time = kNotFound;
  // The extremes of the fluid load averaged over load_window seconds (signed; the time is the
  // window's centre): bounded as dt falls, the load to compare across resolutions.
  double load_window = 0.0;  // s
  double peak_force_horizontal_windowed = 0.0;
  double peak_force_horizontal_windowed_time = kNotFound;
  double peak_force_vertical_windowed = 0.0;
  double peak_force_vertical_windowed_time = kNotFound;
  // The first landing: the row of the first contact above released_fraction W after at least
  // release_hold s free of contact (NaN: none). The impulses of the fluid and the contact force
  // over landing_duration s from the start of that row's step, N s (2D: N s/m), and the body's
  // velocity at that start (NaN if the file has no velocity): M times it is the momentum the
  // landing stops, and J_fluid + J_contact + M g landing_duration = M (v_after - v_landing).
  double landing_duration = 0.0;  // s
  double landing_time = kNotFound;
  std::array<double, 3> landing_velocity{kNotFound, kNotFound, kNotFound};
  std::array<double, 3> landing_impulse_fluid{kNotFound, kNotFound, kNotFound};
  std::array<double, 3> landing_impulse_contact{kNotFound, kNotFound, kNotFound};
};

BodySummary summarize_body(const BodyTrack& track, const Vec3& gravity,
                           const BodyReportSettings& settings = {});

// Every /bodies/NAME series of a run file (empty if the run has no bodies).
std::vector<BodyTrack> read_body_tracks(const std::string& h5_path);

// DIR/NAME.csv: time,x,y,z,angle,fluid_fx,fluid_fy,fluid_fz,contact_fx,contact_fy,contact_fz.
void write_body_csv(const BodyTrack& track, const std::string& path);

// Stores the summary as attributes of /bodies/NAME (double scalars; displacement has 3 values).
void store_body_summary(const std::string& h5_path, const std::string& body,
                        const BodySummary& summary);

// One line per body, e.g. "girder: wave arrives at 0.412 s, leaves its support at ...".
std::string format_body_summary(const BodyTrack& track, const BodySummary& summary);

struct BodyReport {
  std::string name;
  std::string csv_path;
  BodySummary summary;
};

// All of the above for every body of a finished run: CSVs into out_dir, attributes into the run
// file, one printed line per body on `log` (may be null). Throws io::OutputError if a CSV or an
// attribute cannot be written, io::RunFileError if the run file cannot be read.
std::vector<BodyReport> report_bodies(const std::string& h5_path, const std::string& out_dir,
                                      const Vec3& gravity, std::FILE* log);

}  // namespace washout::cli
