// Free-surface detection by a density threshold (METHOD.md step 2, "choose"): a particle whose
// kernel support is partly empty has a low summation density. Such particles take P = 0.
#include "engine/fluid/isph_stages.hpp"

namespace washout {

std::size_t detect_free_surface(const Particles& p, double rho0, double threshold,
                                FluidWork& work) {
  const std::size_t n = p.fluid_count;
  work.free_surface.assign(n, 0);
  std::size_t count = 0;
#pragma omp parallel for reduction(+ : count) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (p.density[i] < threshold * rho0) {
      work.free_surface[i] = 1;
      ++count;
    }
  }
  return count;
}

}  // namespace washout
