// Seconds per rendered frame at 1280x720 (2x supersampling, the default) for a synthetic 3D
// scene: a block of moving fluid on a two-layer floor of wall particles, ~100k and ~1M
// particles, seen in perspective and from the side. The fluid is either a perfect lattice (a
// run's initial state, the worst case for hiding particles) or jittered by up to 0.15 d0 (as
// after some flow). Prints figures; not a test.
// Usage: bench_render [max_particles]  (default 1e6; 1e5 skips the 1M cases)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "render/frame_renderer.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// A dam-break-like block (nx, ny, nz fluid particles) on a floor twice as long.
struct SyntheticScene {
  double d0 = 0.01;
  std::vector<double> x, y, z, u, v, w, p;
  std::vector<std::uint8_t> kind;

  SyntheticScene(int nx, int ny, int nz, bool jittered) {
    std::uint64_t state = 12345;  // a fixed LCG: the same scene on every run
    auto jitter = [&] {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      const double unit = static_cast<double>(state >> 11) / 9007199254740992.0;  // [0, 1)
      return jittered ? 0.15 * d0 * (2.0 * unit - 1.0) : 0.0;
    };
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        for (int k = 0; k < nz; ++k) {
          const double px = (i + 0.5) * d0 + jitter(), py = (j + 0.5) * d0 + jitter(),
                       pz = (k + 0.5) * d0 + jitter();
          add(0, px, py, pz, 2.0 * pz + std::sin(py * 20.0), 0.1 * std::cos(px * 10.0), -px,
              9810.0 * (nz * d0 - pz));
        }
      }
    }
    for (int i = -2; i < 2 * nx; ++i) {
      for (int j = -2; j < ny + 2; ++j) {
        for (int k = 1; k <= 2; ++k)
          add(1, (i + 0.5) * d0, (j + 0.5) * d0, -(k - 0.5) * d0, 0, 0, 0, 0);
      }
    }
  }

  void add(std::uint8_t k, double px, double py, double pz, double ux, double uy, double uz,
           double pressure) {
    x.push_back(px);
    y.push_back(py);
    z.push_back(pz);
    u.push_back(ux);
    v.push_back(uy);
    w.push_back(uz);
    p.push_back(pressure);
    kind.push_back(k);
  }

  washout::ParticleView view(double time) const {
    washout::ParticleView view;
    view.dim = 3;
    view.count = x.size();
    view.time = time;
    view.d0 = d0;
    view.position.component[0] = x.data();
    view.position.component[1] = y.data();
    view.position.component[2] = z.data();
    view.velocity.component[0] = u.data();
    view.velocity.component[1] = v.data();
    view.velocity.component[2] = w.data();
    view.pressure = p.data();
    view.kind = kind.data();
    return view;
  }
};

void bench(const char* label, int nx, int ny, int nz, int frames, const std::string& camera,
           bool jittered) {
  const SyntheticScene scene(nx, ny, nz, jittered);
  washout::render::RenderOptions options;  // 1280x720, supersample 2
  options.camera.preset = camera;
  washout::render::FrameRenderer renderer(options);

  auto start = Clock::now();
  washout::render::Image image = renderer.render(scene.view(0.0));
  const double first = seconds_since(start);

  // The fastest frame is reported beside the mean: on a shared machine it is the steadier.
  double total = 0.0, fastest = 1e300;
  const std::clock_t cpu_start = std::clock();  // all threads: less sensitive to other load
  for (int f = 1; f <= frames; ++f) {
    start = Clock::now();
    image = renderer.render(scene.view(0.04 * f));
    const double s = seconds_since(start);
    total += s;
    fastest = std::min(fastest, s);
  }
  const double per_frame = total / frames;
  const double cpu_per_frame =
      static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC / frames;

  const std::string png =
      (std::filesystem::temp_directory_path() / "washout_bench_render.png").string();
  start = Clock::now();
  image.write_png(png);
  const double png_seconds = seconds_since(start);
  std::printf(
      "%-4s %8zu particles %-8s %-11s first %5.2f s  mean %5.2f s/frame  fastest %5.2f s"
      "  CPU %5.2f s/frame  PNG %4.2f s  (%zu spheres drawn)\n",
      label, scene.x.size(), jittered ? "jittered" : "lattice", camera.c_str(), first, per_frame,
      fastest, cpu_per_frame, png_seconds, renderer.drawn_spheres());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const double max_particles = argc > 1 ? std::atof(argv[1]) : 1e6;
  std::printf("bench_render: 1280x720, supersample 2 (renders 2560x1440), OSMesa llvmpipe\n");
  for (const bool jittered : {false, true}) {
    for (const char* camera : {"perspective", "side"})
      bench("100k", 80, 30, 36, 5, camera, jittered);
  }
  if (max_particles >= 1e6) {
    for (const bool jittered : {false, true}) {
      for (const char* camera : {"perspective", "side"})
        bench("1M", 180, 64, 84, 3, camera, jittered);
    }
  }
  return 0;
}
