// The machine's memory bandwidth as STREAM's triad measures it (a[i] = b[i] + s c[i], counted as
// 24 bytes moved per element: two reads and a write), on the same OpenMP threads as the runs,
// the roof that a sparse matrix-vector product, which streams its matrix once, can approach.
// Prints one JSON line. A benchmark, never a test.
//   bench_stream [--mib N] [--repeats R]     (default: three arrays of 256 MiB each, 10 repeats)
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

int main(int argc, char** argv) {
  std::size_t mib = 256;
  int repeats = 10;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--mib" && k + 1 < argc)
      mib = std::strtoul(argv[++k], nullptr, 10);
    else if (a == "--repeats" && k + 1 < argc)
      repeats = std::atoi(argv[++k]);
    else {
      std::fprintf(stderr, "usage: bench_stream [--mib N] [--repeats R]\n");
      return 1;
    }
  }
  if (mib == 0 || repeats < 1) {
    std::fprintf(stderr, "bench_stream: --mib and --repeats must be positive\n");
    return 1;
  }
  const std::size_t n = mib * 1024 * 1024 / sizeof(double);
  // Not value-initialised: the first touch below happens on the threads that use each page.
  std::unique_ptr<double[]> a(new double[n]), b(new double[n]), c(new double[n]);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  const double s = 3.0;
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  // Read the result back so that the loop cannot be dropped.
  double check = 0.0;
  for (std::size_t i = 0; i < n; i += 4096) check += a[i];
  if (check != 7.0 * double((n + 4095) / 4096)) {
    std::fprintf(stderr, "bench_stream: wrong triad result\n");
    return 1;
  }
  const double bytes = 3.0 * sizeof(double) * double(n);
  std::printf(
      "{\"kind\": \"stream\", \"kernel\": \"triad\", \"threads\": %d, \"array_bytes\": %zu, "
      "\"repeats\": %d, \"best_seconds\": %.6g, \"bytes_per_second\": %.6g}\n",
      omp_get_max_threads(), n * sizeof(double), repeats, best, bytes / best);
  return 0;
}
