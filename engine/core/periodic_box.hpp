#pragma once
// Periodic directions of the domain: minimum-image displacements and wrapping.
#include <cmath>

namespace washout {

struct PeriodicBox {
  bool periodic[3] = {false, false, false};
  double lower[3] = {0, 0, 0};
  double length[3] = {0, 0, 0};

  bool any() const { return periodic[0] || periodic[1] || periodic[2]; }

  // Turns x_i - x_j into the shortest displacement across periodic boundaries.
  void minimum_image(double* d) const {
    for (int a = 0; a < 3; ++a)
      if (periodic[a]) d[a] -= length[a] * std::nearbyint(d[a] / length[a]);
  }
  double wrap(double x, int axis) const {
    if (!periodic[axis]) return x;
    double s = std::fmod(x - lower[axis], length[axis]);
    if (s < 0) s += length[axis];
    return lower[axis] + s;
  }
};

}  // namespace washout
