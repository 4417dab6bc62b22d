#include "engine/cli/busy_cores.hpp"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <limits>
#include <sstream>

namespace washout {
namespace {

constexpr unsigned long long kFewestTicks = 50;

double wall_now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace

std::optional<MachineTicks> parse_machine_ticks(const std::string& proc_stat) {
  std::istringstream lines(proc_stat);
  std::string first;
  std::getline(lines, first);
  std::istringstream in(first);
  std::string label;
  if (!(in >> label) || label != "cpu") return std::nullopt;
  // user nice system idle iowait irq softirq steal; guest time is already inside user.
  unsigned long long field[8] = {};
  for (auto& f : field)
    if (!(in >> f)) return std::nullopt;
  MachineTicks t;
  for (const auto f : field) t.total += f;
  t.busy = t.total - field[3] - field[4];
  for (std::string line; std::getline(lines, line);)
    if (line.size() > 3 && line.compare(0, 3, "cpu") == 0 && std::isdigit(line[3])) ++t.cores;
  if (t.cores == 0) return std::nullopt;
  return t;
}

std::optional<MachineTicks> read_machine_ticks() {
  std::ifstream file("/proc/stat");
  if (!file) return std::nullopt;
  std::ostringstream text;
  text << file.rdbuf();
  return parse_machine_ticks(text.str());
}

double cores_busy_elsewhere(const MachineTicks& before, const MachineTicks& after,
                            double own_cpu_seconds, double wall_seconds) {
  if (after.total <= before.total || !(wall_seconds > 0.0)) return 0.0;
  const double busy_share = static_cast<double>(after.busy - before.busy) /
                            static_cast<double>(after.total - before.total);
  return std::max(0.0, busy_share * after.cores - own_cpu_seconds / wall_seconds);
}

bool threads_lack_cores(int threads, int cores, double busy_elsewhere) {
  return threads > 1 && threads >= cores - busy_elsewhere + 0.5;
}

std::string busy_cores_note(int threads, int cores, double busy_elsewhere) {
  if (!threads_lack_cores(threads, cores, busy_elsewhere)) return "";
  const double idle = cores - busy_elsewhere;
  char note[400];
  std::snprintf(note, sizeof note,
                "note: other processes keep %.1f of the %d cores busy, and %d threads will not all "
                "find a core: each step waits for its slowest thread, which can make the run "
                "several times slower than with fewer threads (--threads %d)",
                busy_elsewhere, cores, threads, std::max(1, static_cast<int>(idle + 0.5)));
  return note;
}

BusyCoresProbe::BusyCoresProbe()
    : start_(read_machine_ticks()), start_wall_(wall_now()), start_cpu_(process_cpu_seconds()) {}

double BusyCoresProbe::seconds() const { return wall_now() - start_wall_; }

double BusyCoresProbe::busy_elsewhere() const {
  const auto now = read_machine_ticks();
  const double wall = seconds();
  // Fewer than kFewestTicks a core in between (half a second at Linux's 100 Hz): too coarse.
  if (!start_ || !now || now->total < start_->total + kFewestTicks * now->cores || !(wall > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  return cores_busy_elsewhere(*start_, *now, process_cpu_seconds() - start_cpu_, wall);
}

int BusyCoresProbe::cores() const { return start_ ? start_->cores : 0; }

std::string BusyCoresProbe::note(int threads, double min_seconds) const {
  if (!start_ || seconds() < min_seconds) return "";
  const double elsewhere = busy_elsewhere();
  if (!std::isfinite(elsewhere)) return "";
  return busy_cores_note(threads, cores(), elsewhere);
}

}  // namespace washout
