#include "engine/cli/run_scoring.hpp"

#include <hdf5.h>
#include <sys/resource.h>

#include <cmath>

#include "engine/io/run_file_writer.hpp"

namespace washout::cli {
namespace {

void write_double(hid_t object, const std::string& name, double value, const std::string& file) {
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(object, name.c_str(), H5T_NATIVE_DOUBLE, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, H5T_NATIVE_DOUBLE, &value);
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  if (status < 0) throw io::OutputError("cannot write attribute " + name + " of " + file);
}

// Fixed-length UTF-8, as the run file writer stores its own text attributes.
void write_text(hid_t object, const std::string& name, const std::string& value,
                const std::string& file) {
  hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_strpad(type, H5T_STR_NULLPAD);
  H5Tset_cset(type, H5T_CSET_UTF8);
  if (H5Aexists(object, name.c_str()) > 0) H5Adelete(object, name.c_str());
  hid_t space = H5Screate(H5S_SCALAR);
  hid_t attr = H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
  const herr_t status = attr < 0 ? -1 : H5Awrite(attr, type, value.empty() ? "" : value.data());
  if (attr >= 0) H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
  if (status < 0) throw io::OutputError("cannot write attribute " + name + " of " + file);
}

}  // namespace

long peak_rss_bytes() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
  return usage.ru_maxrss * 1024L;  // Linux reports kilobytes
}

RunCost run_cost(const RunSummary& summary) {
  RunCost c;
  c.wall_seconds = summary.wall_seconds;
  c.fluid_particles = summary.fluid_particles;
  c.particles = summary.fluid_particles + summary.boundary_particles;
  c.steps = summary.steps;
  c.peak_rss_bytes = peak_rss_bytes();
  return c;
}

void write_run_scores(const std::string& run_file, const RunCost& cost,
                      const std::vector<lua::ValidationScore>& scores) {
  hid_t file = H5Fopen(run_file.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  if (file < 0) throw io::OutputError("cannot open " + run_file + " to store the run's cost");
  try {
    write_double(file, "wall_seconds", cost.wall_seconds, run_file);
    write_double(file, "particles", static_cast<double>(cost.particles), run_file);
    write_double(file, "fluid_particles", static_cast<double>(cost.fluid_particles), run_file);
    write_double(file, "steps", static_cast<double>(cost.steps), run_file);
    write_double(file, "peak_rss_bytes", static_cast<double>(cost.peak_rss_bytes), run_file);
    std::string names;
    for (const auto& s : scores) {
      names += (names.empty() ? "" : ",") + s.name;
      write_double(file, "error_" + s.name, s.error, run_file);
      write_double(file, "error_bound_" + s.name, s.bound, run_file);
    }
    if (!scores.empty()) {
      const auto& primary = scores.front();
      write_double(file, "error", primary.error, run_file);
      write_double(file, "error_bound", primary.bound, run_file);
      write_text(file, "error_metric", primary.metric, run_file);
      write_text(file, "reference", primary.reference, run_file);
      write_text(file, "error_names", names, run_file);
    }
  } catch (...) {
    H5Fclose(file);
    throw;
  }
  if (H5Fclose(file) < 0) throw io::OutputError("cannot close " + run_file);
}

void print_run_scores(std::FILE* out, const RunCost& cost,
                      const std::vector<lua::ValidationScore>& scores) {
  for (const auto& s : scores) {
    if (!s.failure.empty()) {
      std::fprintf(out, "error %s: not computed: %s\n", s.name.c_str(), s.failure.c_str());
      continue;
    }
    std::fprintf(out, "error %s = %.4g (%s; against %s", s.name.c_str(), s.error, s.metric.c_str(),
                 s.reference.c_str());
    if (std::isfinite(s.bound))
      std::fprintf(out, "; bound %.4g%s", s.bound, s.error <= s.bound ? "" : ", EXCEEDED");
    std::fprintf(out, ")\n");
  }
  std::fprintf(out,
               "cost: wall %.2f s, %zu particles (%zu fluid), %ld steps, peak memory %.0f MB\n",
               cost.wall_seconds, cost.particles, cost.fluid_particles, cost.steps,
               cost.peak_rss_bytes / 1048576.0);
}

}  // namespace washout::cli
