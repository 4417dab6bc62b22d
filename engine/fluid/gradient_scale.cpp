// The pressure gradient's normalisation by each particle's own neighbours (gradient_scale =
// "particle"). Every SPH operator here is divided by its sum over a perfect lattice
// (sph_context.hpp), which makes it exact on the initial lattice. Once the flow has moved, the
// particles settle into a disordered arrangement whose gradient moment
//   m_i = (1/dim) sum_j V (-(x_j - x_i) . grad W_ij)      (1 on the lattice)
// is larger: 1.03 in 2D after a floating box's heave. The corrector's gradient of a linear
// pressure is then m_i times too large, and since at rest it must balance gravity exactly, the
// pressure itself settles m_i times too low: a box floated 2.9 % too deep (docs/method.md,
// seventeenth session). The corrector multiplies its pair force by (s_i + s_j)/2, s_i = 1/m_i,
// which keeps the pair force antisymmetric (momentum conserved).
//
// m_i measures the arrangement only where the support is full. Within a support of the free
// surface (a surface neighbour) it is low because the support is cut, so those particles take the
// mean s of their neighbours with a full support, and the surface particles the mean of those
// (1 where none is in reach: a film, a drop). The surface particles' own gradient is the corrected
// or ghost form, exact for a linear field; their s enters their neighbours' pair factors.
// s is bounded to [1/1.15, 1.15]: a support so irregular lies beyond what a scale can mend.
#include <algorithm>

#include "engine/core/sph_operators.hpp"
#include "engine/fluid/isph_stages.hpp"

namespace washout {
namespace {

constexpr double kLargestScale = 1.15;

}  // namespace

void compute_gradient_scale(const SphContext& ctx, const NeighborList& list, const Particles& p,
                            bool symmetric, FluidWork& work) {
  compute_gradient_moment(ctx, list, p, symmetric, work);
  scale_from_gradient_moment(list, p, work);
}

void compute_gradient_moment(const SphContext& ctx, const NeighborList& list, const Particles& p,
                             bool symmetric, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  const bool own_kernel = symmetric && ctx.symmetric_has_own_kernel();
  work.gradient_moment.resize(n);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    double moment = 0.0;
    for_each_neighbor(ctx, list, p, i, [&](const NeighborPair& q) {
      moment -= gradient_moment_weight(ctx, own_kernel, q.r) * q.r2;
    });
    work.gradient_moment[i] = moment / ctx.dim;
  }
}

void scale_from_gradient_moment(const NeighborList& list, const Particles& p, FluidWork& work) {
  const std::size_t n = p.fluid_count;
  std::vector<double>& scale = work.gradient_scale;
  std::vector<std::uint8_t>& origin = work.gradient_scale_level;
  scale.assign(n, 1.0);
  origin.assign(n, 0);
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    if (work.free_surface[i]) continue;
    // Measured only where no surface particle is in reach (a cut support reads low).
    bool cut = false;
    for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1] && !cut; ++k) {
      const std::size_t j = list.index[k];
      cut = j < n && work.free_surface[j] != 0;
    }
    const double moment = work.gradient_moment[i];
    if (cut || !(moment > 0.0)) continue;
    scale[i] = std::clamp(1.0 / moment, 1.0 / kLargestScale, kLargestScale);
    origin[i] = 1;
  }
  // The band, then the surface row beyond it: each takes the mean of the neighbours one level
  // further in (level 1 measured, 2 from those, 3 from the second level).
  std::vector<double>& pending = work.gradient_scale_pending;
  for (std::uint8_t level = 2; level <= 3; ++level) {
    pending.assign(n, 0.0);  // 0: nothing in reach (a scale is never 0)
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      if (origin[i]) continue;
      double sum = 0.0;
      int count = 0;
      for (std::uint64_t k = list.offset[i]; k < list.offset[i + 1]; ++k) {
        const std::size_t j = list.index[k];
        if (j < n && origin[j] == level - 1) sum += scale[j], ++count;
      }
      if (count > 0) pending[i] = sum / count;
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n; ++i)
      if (pending[i] > 0.0) scale[i] = pending[i], origin[i] = level;
  }
}

}  // namespace washout
