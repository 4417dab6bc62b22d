#include "engine/cli/body_report.hpp"

#include <hdf5.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "engine/cli/landing_load.hpp"
#include "engine/io/run_file_reader.hpp"
#include "engine/io/run_file_writer.hpp"

namespace washout::cli {
namespace {

Vec3 row3(const std::vector<double>& v, std::size_t k) {
  return Vec3(v[3 * k], v[3 * k + 1], v[3 * k + 2]);
}

void write_double_attribute(hid_t object, const std::string& name, const double* values,
                            hsize_t count, const std::string& where) {
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
  hid_t space = count == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &count, nullptr);
  hid_t attr = H5Acreate2(object, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, H5T_NATIVE_DOUBLE, values);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  if (status < 0) throw io::OutputError("cannot write attribute " + name + " of " + where);
}

// A time for the printed summary: "0.412 s", or "never".
std::string when(double t) {
  if (std::isnan(t)) return "never";
  char b[32];
  std::snprintf(b, sizeof b, "%.3f s", t);
  return b;
}

// The windowed peaks and the first landing's impulses (engine/cli/landing_load.hpp).
void summarize_landing(const BodyTrack& track, const Vec3& up, const BodyReportSettings& settings,
                       BodySummary& s) {
  const std::size_t n = track.rows();
  const std::vector<double> bounds = step_bounds(track.time);
  const double window = settings.load_window;
  s.load_window = window;
  std::vector<double> vertical(n), contact(n);
  for (std::size_t k = 0; k < n; ++k) {
    vertical[k] = row3(track.force_fluid, k).dot(up);
    contact[k] = row3(track.force_contact, k).norm();
  }
  const WindowedPeak fx = windowed_peak(bounds, track.force_fluid, 3, 0, window);
  const WindowedPeak fv = windowed_peak(bounds, vertical, 1, 0, window);
  s.peak_force_horizontal_windowed = fx.value;
  s.peak_force_horizontal_windowed_time = fx.time;
  s.peak_force_vertical_windowed = fv.value;
  s.peak_force_vertical_windowed_time = fv.time;

  const std::size_t k =
      first_landing(bounds, contact, settings.released_fraction * s.weight, settings.release_hold);
  if (k >= n) return;
  s.landing_time = track.time[k];
  s.landing_duration = settings.landing_duration;
  const double a = bounds[k], b = bounds[k] + settings.landing_duration;
  for (std::size_t c = 0; c < 3; ++c) {
    s.landing_impulse_fluid[c] = load_integral(bounds, track.force_fluid, 3, c, a, b);
    s.landing_impulse_contact[c] = load_integral(bounds, track.force_contact, 3, c, a, b);
    if (k > 0 && track.velocity.size() == 3 * n)
      s.landing_velocity[c] = track.velocity[3 * (k - 1) + c];
  }
}

}  // namespace

BodySummary summarize_body(const BodyTrack& track, const Vec3& gravity,
                           const BodyReportSettings& settings) {
  BodySummary s;
  const std::size_t n = track.rows();
  const double g = gravity.norm();
  s.weight = track.mass * g;
  if (n == 0) return s;
  // Up is against gravity; horizontal is x, the flume axis of every scene with a flow.
  const Vec3 up = g > 0 ? Vec3(-gravity / g) : (track.dim == 2 ? Vec3::UnitY() : Vec3::UnitZ());
  const Vec3 x0 = row3(track.position, 0);
  const double angle0 = track.angle.empty() ? 0.0 : track.angle[0];

  std::vector<double> magnitude(n);
  for (std::size_t k = 0; k < n; ++k) magnitude[k] = row3(track.force_fluid, k).norm();
  // A one-step spike stands above spike_weights W, and each neighbouring step's load is either
  // smaller by spike_ratio or points the other way (a load that reverses every step).
  const auto spike = [&](std::size_t k) {
    if (!(settings.spike_weights > 0) || !(magnitude[k] > settings.spike_weights * s.weight))
      return false;
    const Vec3 f = row3(track.force_fluid, k);
    const auto stands_apart_from = [&](std::size_t j) {
      return f.dot(row3(track.force_fluid, j)) < 0.0 ||
             settings.spike_ratio * magnitude[j] < magnitude[k];
    };
    return (k == 0 || stands_apart_from(k - 1)) && (k + 1 == n || stands_apart_from(k + 1));
  };

  bool carried = false;
  std::size_t release_start = n;  // first row of the current run of released rows
  for (std::size_t k = 0; k < n; ++k) {
    const double t = track.time[k];
    const Vec3 ff = row3(track.force_fluid, k);
    // The body is dry before the wave: the first load above 1 % of its weight is the wave.
    if (std::isnan(s.arrival_time) && ff.norm() > settings.arrival_fraction * s.weight)
      s.arrival_time = t;
    const bool is_spike = spike(k);
    if (is_spike) {
      ++s.load_spikes;
      if (magnitude[k] > s.largest_spike) s.largest_spike = magnitude[k], s.largest_spike_time = t;
    }
    if (std::abs(ff.x()) > std::abs(s.peak_force_horizontal_one_step)) {
      s.peak_force_horizontal_one_step = ff.x();
      s.peak_force_horizontal_one_step_time = t;
    }
    if (std::abs(ff.dot(up)) > std::abs(s.peak_force_vertical_one_step)) {
      s.peak_force_vertical_one_step = ff.dot(up);
      s.peak_force_vertical_one_step_time = t;
    }
    if (!is_spike && std::abs(ff.x()) > std::abs(s.peak_force_horizontal)) {
      s.peak_force_horizontal = ff.x();
      s.peak_force_horizontal_time = t;
    }
    const double fv = ff.dot(up);
    if (!is_spike && std::abs(fv) > std::abs(s.peak_force_vertical)) {
      s.peak_force_vertical = fv;
      s.peak_force_vertical_time = t;
    }
    if (!track.angle.empty() && std::abs(track.angle[k] - angle0) > std::abs(s.peak_angle)) {
      s.peak_angle = track.angle[k] - angle0;
      s.peak_angle_time = t;
    }
    // Leaving the support: only the vertical part of the contact is the support's (frictionless
    // side walls push across the flume). Once the support has carried at least half the weight,
    // the body has left it at the first row from which the vertical contact stays below 1 % of
    // the weight for release_hold seconds; shorter gaps are hops on the support.
    if (std::isnan(s.leave_time)) {
      const double fc = row3(track.force_contact, k).dot(up);
      if (fc >= settings.carried_fraction * s.weight) carried = true;
      if (carried && std::abs(fc) < settings.released_fraction * s.weight) {
        if (release_start == n) release_start = k;
        if (t - track.time[release_start] >= settings.release_hold)
          s.leave_time = track.time[release_start];
      } else {
        release_start = n;
      }
    }
  }
  const Vec3 d = row3(track.position, n - 1) - x0;
  s.displacement = {d.x(), d.y(), d.z()};
  summarize_landing(track, up, settings, s);
  return s;
}

std::vector<BodyTrack> read_body_tracks(const std::string& h5_path) {
  std::vector<BodyTrack> tracks;
  const io::RunFileReader run(h5_path);
  for (const std::string& name : run.children("/bodies")) {
    BodyTrack t;
    t.name = name;
    t.dim = run.dim();
    const std::string group = "/bodies/" + name;
    t.mass =
        run.has_attribute(group, "mass") ? std::stod(run.string_attribute("mass", group)) : 0.0;
    if (run.has(group + "/time")) {  // not when the run stopped before its first step
      t.time = run.read_doubles(group + "/time");
      t.position = run.read_doubles(group + "/position");
      t.angle = run.read_doubles(group + "/angle");
      t.force_fluid = run.read_doubles(group + "/force_fluid");
      t.force_contact = run.read_doubles(group + "/force_contact");
      if (run.has(group + "/velocity")) t.velocity = run.read_doubles(group + "/velocity");
      const std::size_t n = t.time.size();
      if (t.position.size() != 3 * n || t.angle.size() != n || t.force_fluid.size() != 3 * n ||
          t.force_contact.size() != 3 * n || (!t.velocity.empty() && t.velocity.size() != 3 * n))
        throw io::RunFileError(h5_path + ": the datasets of " + group + " differ in length");
    }
    tracks.push_back(std::move(t));
  }
  return tracks;
}

void write_body_csv(const BodyTrack& track, const std::string& path) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw io::OutputError("cannot write '" + path + "'");
  std::fprintf(out,
               "time,x,y,z,angle,fluid_fx,fluid_fy,fluid_fz,contact_fx,contact_fy,contact_fz\n");
  for (std::size_t k = 0; k < track.rows(); ++k) {
    const double* p = &track.position[3 * k];
    const double* f = &track.force_fluid[3 * k];
    const double* c = &track.force_contact[3 * k];
    std::fprintf(out, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", track.time[k],
                 p[0], p[1], p[2], track.angle[k], f[0], f[1], f[2], c[0], c[1], c[2]);
  }
  const bool failed = std::ferror(out) != 0;
  if (std::fclose(out) != 0 || failed) throw io::OutputError("cannot write '" + path + "'");
}

void store_body_summary(const std::string& h5_path, const std::string& body, const BodySummary& s) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hid_t file = H5Fopen(h5_path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) throw io::OutputError("cannot open '" + h5_path + "' to store the body summary");
  const std::string path = "/bodies/" + body;
  hid_t group = H5Gopen2(file, path.c_str(), H5P_DEFAULT);
  if (group < 0) {
    H5Fclose(file);
    throw io::OutputError(h5_path + ": no group " + path);
  }
  const std::string where = h5_path + ":" + path;
  try {
    const std::pair<const char*, double> scalars[] = {
        {"weight", s.weight},
        {"arrival_time", s.arrival_time},
        {"leave_time", s.leave_time},
        {"peak_force_horizontal", s.peak_force_horizontal},
        {"peak_force_horizontal_time", s.peak_force_horizontal_time},
        {"peak_force_vertical", s.peak_force_vertical},
        {"peak_force_vertical_time", s.peak_force_vertical_time},
        {"peak_angle", s.peak_angle},
        {"peak_angle_time", s.peak_angle_time},
        {"load_spikes", static_cast<double>(s.load_spikes)},
        {"largest_spike", s.largest_spike},
        {"largest_spike_time", s.largest_spike_time},
        {"peak_force_horizontal_one_step", s.peak_force_horizontal_one_step},
        {"peak_force_horizontal_one_step_time", s.peak_force_horizontal_one_step_time},
        {"peak_force_vertical_one_step", s.peak_force_vertical_one_step},
        {"peak_force_vertical_one_step_time", s.peak_force_vertical_one_step_time},
        {"load_window", s.load_window},
        {"peak_force_horizontal_windowed", s.peak_force_horizontal_windowed},
        {"peak_force_horizontal_windowed_time", s.peak_force_horizontal_windowed_time},
        {"peak_force_vertical_windowed", s.peak_force_vertical_windowed},
        {"peak_force_vertical_windowed_time", s.peak_force_vertical_windowed_time},
        {"landing_time", s.landing_time},
        {"landing_duration", s.landing_duration}};
    for (const auto& [name, value] : scalars) write_double_attribute(group, name, &value, 1, where);
    write_double_attribute(group, "final_displacement", s.displacement.data(), 3, where);
    write_double_attribute(group, "landing_velocity", s.landing_velocity.data(), 3, where);
    write_double_attribute(group, "landing_impulse_fluid", s.landing_impulse_fluid.data(), 3,
                           where);
    write_double_attribute(group, "landing_impulse_contact", s.landing_impulse_contact.data(), 3,
                           where);
  } catch (...) {
    H5Gclose(group);
    H5Fclose(file);
    throw;
  }
  H5Gclose(group);
  if (H5Fclose(file) < 0) throw io::OutputError("cannot close '" + h5_path + "'");
}

std::string format_body_summary(const BodyTrack& track, const BodySummary& s) {
  const char* unit = track.dim == 2 ? "N/m" : "N";
  std::ostringstream o;
  char b[256];
  o << track.name << ": wave arrives " << when(s.arrival_time) << ", leaves its support "
    << when(s.leave_time) << "; peak fluid force";
  std::snprintf(b, sizeof b, " horizontal %.4g %s (%s), vertical %.4g %s (%s); weight %.4g %s",
                s.peak_force_horizontal, unit, when(s.peak_force_horizontal_time).c_str(),
                s.peak_force_vertical, unit, when(s.peak_force_vertical_time).c_str(), s.weight,
                unit);
  o << b;
  std::snprintf(b, sizeof b, "; displacement (%.4f, %.4f, %.4f) m; peak rotation %.2f deg (%s)",
                s.displacement[0], s.displacement[1], s.displacement[2],
                s.peak_angle * 180.0 / M_PI, when(s.peak_angle_time).c_str());
  o << b;
  if (s.load_spikes > 0) {
    std::snprintf(b, sizeof b,
                  "; %d one-step load spike%s left out of the peaks (largest %.4g %s = %.0f W, %s)",
                  s.load_spikes, s.load_spikes == 1 ? "" : "s", s.largest_spike, unit,
                  s.weight > 0 ? s.largest_spike / s.weight : 0.0,
                  when(s.largest_spike_time).c_str());
    o << b;
  }
  std::snprintf(b, sizeof b,
                "; mean over %.3g s windows: horizontal %.4g %s (%s), vertical %.4g %s (%s)",
                s.load_window, s.peak_force_horizontal_windowed, unit,
                when(s.peak_force_horizontal_windowed_time).c_str(), s.peak_force_vertical_windowed,
                unit, when(s.peak_force_vertical_windowed_time).c_str());
  o << b;
  if (!std::isnan(s.landing_time)) {
    const char* impulse_unit = track.dim == 2 ? "N s/m" : "N s";
    const int v = track.dim == 2 ? 1 : 2;  // the vertical axis of the scenes
    std::snprintf(b, sizeof b,
                  "; lands %s: fluid impulse %.4g %s, contact %.4g %s over %.3g s (vertical)",
                  when(s.landing_time).c_str(), s.landing_impulse_fluid[v], impulse_unit,
                  s.landing_impulse_contact[v], impulse_unit, s.landing_duration);
    o << b;
  }
  return o.str();
}

std::vector<BodyReport> report_bodies(const std::string& h5_path, const std::string& out_dir,
                                      const Vec3& gravity, std::FILE* log) {
  std::vector<BodyReport> reports;
  for (const BodyTrack& track : read_body_tracks(h5_path)) {
    BodyReport r;
    r.name = track.name;
    r.csv_path = (std::filesystem::path(out_dir) / (track.name + ".csv")).string();
    r.summary = summarize_body(track, gravity);
    write_body_csv(track, r.csv_path);
    store_body_summary(h5_path, track.name, r.summary);
    if (log) std::fprintf(log, "%s\n", format_body_summary(track, r.summary).c_str());
    reports.push_back(std::move(r));
  }
  return reports;
}

}  // namespace washout::cli
