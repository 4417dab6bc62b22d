#include "engine/cli/study_table.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>

#include "engine/cli/busy_cores.hpp"

namespace washout::cli {
namespace {

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

// CSV cells here are numbers and short words; a comma or quote gets the cell quoted.
std::string cell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

double lookup(const std::vector<std::pair<std::string, double>>& v, const std::string& name) {
  for (const auto& [n, x] : v)
    if (n == name) return x;
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

bool StudyRow::waited_for_cores() const {
  return std::isfinite(threads) && std::isfinite(cores) && std::isfinite(cores_busy_elsewhere) &&
         threads_lack_cores(static_cast<int>(threads), static_cast<int>(cores),
                            cores_busy_elsewhere);
}

double StudyRow::wall_min() const {
  if (wall_seconds.empty()) return std::numeric_limits<double>::quiet_NaN();
  return *std::min_element(wall_seconds.begin(), wall_seconds.end());
}

double StudyRow::wall_median() const {
  if (wall_seconds.empty()) return std::numeric_limits<double>::quiet_NaN();
  auto w = wall_seconds;
  std::sort(w.begin(), w.end());
  const std::size_t n = w.size();
  return n % 2 ? w[n / 2] : 0.5 * (w[n / 2 - 1] + w[n / 2]);
}

std::vector<std::string> StudyTable::score_names() const {
  std::vector<std::string> names;
  for (const auto& r : rows)
    for (const auto& [n, e] : r.errors)
      if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
  return names;
}

bool StudyTable::write_csv(const std::string& path) const {
  std::ofstream out(path);
  if (!out) return false;
  const auto scores = score_names();
  for (const auto& n : names) out << cell(n) << ",";
  out << "status,exit_code,particles,fluid_particles,steps,wall_seconds_min,wall_seconds_median,"
         "repeats,peak_rss_bytes,ppe_iterations_per_step,threads,cores_busy_elsewhere,error,"
         "error_bound";
  // Every score beyond the primary gets its own pair of columns.
  for (std::size_t k = 1; k < scores.size(); ++k)
    out << ",error_" << scores[k] << ",error_bound_" << scores[k];
  out << ",error_name,error_metric\n";
  for (const auto& r : rows) {
    for (const auto& v : r.values) out << cell(v) << ",";
    out << cell(r.status) << "," << r.exit_code << "," << number(r.particles) << ","
        << number(r.fluid_particles) << "," << number(r.steps) << "," << number(r.wall_min()) << ","
        << number(r.wall_median()) << "," << r.wall_seconds.size() << ","
        << number(r.peak_rss_bytes) << "," << number(r.ppe_iterations_per_step) << ","
        << number(r.threads) << "," << number(r.cores_busy_elsewhere);
    for (std::size_t k = 0; k < std::max<std::size_t>(scores.size(), 1); ++k) {
      const std::string name = k < scores.size() ? scores[k] : "";
      out << "," << number(lookup(r.errors, name)) << "," << number(lookup(r.bounds, name));
    }
    out << "," << cell(scores.empty() ? "" : scores.front()) << "," << cell(r.error_metric) << "\n";
  }
  return static_cast<bool>(out);
}

std::vector<ConvergenceFit> fit_convergence(const StudyTable& table) {
  std::vector<ConvergenceFit> fits;
  const auto it = std::find(table.names.begin(), table.names.end(), "d0");
  if (it == table.names.end()) return fits;
  const std::size_t d0_column = static_cast<std::size_t>(it - table.names.begin());
  for (const auto& score : table.score_names()) {
    // Rows grouped by the values of the other varied parameters.
    std::map<std::string, std::vector<std::pair<double, double>>> groups;
    for (const auto& r : table.rows) {
      std::string group;
      for (std::size_t k = 0; k < r.values.size(); ++k)
        if (k != d0_column)
          group += (group.empty() ? "" : ", ") + table.names[k] + " = " + r.values[k];
      const double e = lookup(r.errors, score);
      auto& points = groups[group];
      if (r.status == "ok" && std::isfinite(e) && e > 0)
        points.emplace_back(std::stod(r.values[d0_column]), e);
    }
    for (auto& [group, points] : groups) {
      ConvergenceFit f;
      f.score = score;
      f.group = group;
      f.points = static_cast<int>(points.size());
      std::sort(points.begin(), points.end(), [](auto& a, auto& b) { return a.first > b.first; });
      for (const auto& [d0, e] : points) {
        char b[64];
        std::snprintf(b, sizeof b, "%sd0 = %g: %.4g", f.figures.empty() ? "" : "; ", d0, e);
        f.figures += b;
      }
      if (points.size() >= 2) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        const double n = static_cast<double>(points.size());
        for (const auto& [d0, e] : points) {
          const double x = std::log(d0), y = std::log(e);
          sx += x, sy += y, sxx += x * x, sxy += x * y;
        }
        const double denominator = n * sxx - sx * sx;
        if (denominator > 0) f.order = (n * sxy - sx * sy) / denominator;
        f.converging = f.order > 0 && points.back().second < points.front().second;
      }
      fits.push_back(f);
    }
  }
  return fits;
}

}  // namespace washout::cli
