#pragma once
// Whether other processes leave this run the cores its threads need. Every stage of a step ends
// at a barrier, so an OpenMP thread that waits for a busy core holds up the whole team: with one
// of two cores taken by another process, the 3D dam break at a/20 ran 3.4 times slower on two
// threads than on a quiet machine, and 1.8 times slower than on one thread (docs/performance.md,
// thirty-fifth session). The run measures what the other processes took over its first second
// (the machine's busy time from /proc/stat less the run's own processor time: its threads take
// what the scheduler gives them, spinning at barriers included; progress_display.cpp) and says so
// when its threads will not all find a core.
#include <optional>
#include <string>

namespace washout {

// The machine's processor time, summed over its cores, in clock ticks (/proc/stat's "cpu" line),
// and its cores (the "cpuN" lines).
struct MachineTicks {
  unsigned long long busy = 0, total = 0;
  int cores = 0;
};
// Parses /proc/stat's text: the first line ("cpu  user nice system idle iowait irq softirq steal
// ..."; idle and iowait count as idle) and one line per core. Nothing when they are not there.
std::optional<MachineTicks> parse_machine_ticks(const std::string& proc_stat);
// The same from /proc/stat itself (nothing where there is none).
std::optional<MachineTicks> read_machine_ticks();

// The cores other processes kept busy between two readings: the machine's busy share times its
// cores, less own_cpu_seconds / wall_seconds (this process's own use over the same interval).
double cores_busy_elsewhere(const MachineTicks& before, const MachineTicks& after,
                            double own_cpu_seconds, double wall_seconds);

// Whether `threads` (more than one) exceed the cores other processes left idle by half a core or
// more: then some thread waits for a core and holds up every step.
bool threads_lack_cores(int threads, int cores, double busy_elsewhere);
// A note for the run's log when they do; empty otherwise.
std::string busy_cores_note(int threads, int cores, double busy_elsewhere);

// Measures over the interval from its construction to note() (at least min_seconds long, else
// nothing is said: too short to tell).
class BusyCoresProbe {
 public:
  BusyCoresProbe();
  std::string note(int threads, double min_seconds) const;
  // The cores other processes kept busy since construction; NaN where it cannot be told (no
  // /proc/stat, or under half a second of clock ticks in between).
  double busy_elsewhere() const;
  int cores() const;       // the machine's, 0 where unknown
  double seconds() const;  // since construction

 private:
  std::optional<MachineTicks> start_;
  double start_wall_ = 0.0, start_cpu_ = 0.0;
};

}  // namespace washout
