// Benchmark of the ISPH step: the 2D and 3D dam breaks at two resolutions each. Prints fluid
// particle-steps per second, PPE iterations per step and each stage's share of the time, with
// the thread and particle counts. A benchmark, never a test: figures depend on the machine.
//   ./bench/bench_isph [end_time]      (default end_time 0.1 s)
#include <omp.h>

#include <cstdio>
#include <string>

#include "engine/cli/run_command.hpp"

int main(int argc, char** argv) {
  const std::string end_time = argc > 1 ? argv[1] : "0.1";
  struct Case {
    const char* scene;
    const char* d0;
    const char* label;
  };
  const Case cases[] = {{"dambreak_2d.lua", "0.0146", "2D a/d0=10"},
                        {"dambreak_2d.lua", "0.0073", "2D a/d0=20"},
                        {"dambreak_3d.lua", "0.0146", "3D a/d0=10"},
                        {"dambreak_3d.lua", "0.0073", "3D a/d0=20"}};
  std::printf("threads: %d, simulated time per case: %s s\n", omp_get_max_threads(),
              end_time.c_str());
  for (const auto& c : cases) {
    std::FILE* quiet = std::fopen("/dev/null", "w");
    washout::cli::RunRequest r;
    r.scene_path = std::string(WASHOUT_SOURCE_DIR) + "/scenes/" + c.scene;
    r.out_dir = "/tmp/washout_bench";
    r.overrides = {{"d0", c.d0}, {"end_time", end_time}, {"output_interval", end_time}};
    r.render_frames = false;
    r.log = quiet;
    const auto out = washout::cli::run_scene(r);
    std::fclose(quiet);
    const auto& s = out.summary;
    double total = 0;
    for (const auto& st : s.stage_seconds) total += st.second;
    std::printf(
        "\n%s: %zu fluid + %zu boundary particles, %ld steps, %.2f s wall, "
        "%.3g fluid particle-steps/s, %.1f PPE iterations/step\n",
        c.label, s.fluid_particles, s.boundary_particles, s.steps, s.wall_seconds,
        s.wall_seconds > 0 ? double(s.fluid_particles) * s.steps / s.wall_seconds : 0.0,
        s.mean_ppe_iterations);
    for (const auto& [name, seconds] : s.stage_seconds)
      std::printf("   %-14s %5.1f %%\n", name.c_str(), total > 0 ? 100 * seconds / total : 0.0);
  }
  return 0;
}
