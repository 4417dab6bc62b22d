#pragma once
// The dimension as a compile-time constant inside a particle's loop over its neighbours.
// with_dimension(dim, body) calls body(std::integral_constant<int, D>{}) with D = dim (2 or 3)
// and returns what it returns, so that `for (int a = 0; a < D; ++a)` unrolls and a particle's
// small sums (a gradient, a 3 x 3 tensor) stay in registers for the whole walk. Read at run time
// the same loops kept those sums in memory: the eddy viscosity of the 3D same-case dam break at
// a/20 took 0.77 s that way and 0.50 s this way (docs/performance.md, twenty-sixth session).
#include <type_traits>

namespace washout {

template <class Body>
inline decltype(auto) with_dimension(int dim, Body&& body) {
  if (dim == 3) return body(std::integral_constant<int, 3>{});
  return body(std::integral_constant<int, 2>{});
}

}  // namespace washout
