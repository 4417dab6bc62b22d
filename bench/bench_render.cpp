// Seconds per rendered frame at 1280x720 (2x supersampling, the default) for a synthetic 3D
// scene: a block of moving fluid on a two-layer floor of wall particles, ~100k and ~1M
// particles. Prints figures; not a test. Usage: bench_render [max_particles]  (default 1e6)
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
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

  SyntheticScene(int nx, int ny, int nz) {
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        for (int k = 0; k < nz; ++k) {
          const double px = (i + 0.5) * d0, py = (j + 0.5) * d0, pz = (k + 0.5) * d0;
          add(0, px, py, pz, 2.0 * pz + std::sin(py * 20.0), 0.1 * std::cos(px * 10.0), -px,
              9810.0 * (nz * d0 - pz));
        }
      }
    }
    for (int i = -2; i < 2 * nx; ++i) {
      for (int j = -2; j < ny + 2; ++j) {
        for (int k = 1; k <= 2; ++k) add(1, (i + 0.5) * d0, (j + 0.5) * d0, -(k - 0.5) * d0, 0, 0, 0, 0);
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

void bench(const char* label, int nx, int ny, int nz, int frames, const std::string& camera) {
  const SyntheticScene scene(nx, ny, nz);
  washout::render::RenderOptions options;  // 1280x720, supersample 2
  options.camera.preset = camera;
  washout::render::FrameRenderer renderer(options);

  auto start = Clock::now();
  washout::render::Image image = renderer.render(scene.view(0.0));
  const double first = seconds_since(start);

  start = Clock::now();
  for (int f = 1; f <= frames; ++f) image = renderer.render(scene.view(0.04 * f));
  const double per_frame = seconds_since(start) / frames;

  const std::string png = (std::filesystem::temp_directory_path() / "washout_bench_render.png").string();
  start = Clock::now();
  image.write_png(png);
  const double png_seconds = seconds_since(start);
  std::printf("%-5s %9zu particles  camera %-11s  first frame %6.3f s  render %6.3f s/frame"
              "  + PNG %5.3f s  (%d frames)\n",
              label, scene.x.size(), camera.c_str(), first, per_frame, png_seconds, frames);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const double max_particles = argc > 1 ? std::atof(argv[1]) : 1e6;
  std::printf("bench_render: 1280x720, supersample 2 (renders 2560x1440), OSMesa llvmpipe\n");
  bench("100k", 80, 30, 36, 5, "perspective");
  bench("100k", 80, 30, 36, 5, "side");
  if (max_particles >= 1e6) {
    bench("1M", 180, 64, 84, 3, "perspective");
    bench("1M", 180, 64, 84, 3, "side");
  }
  return 0;
}
