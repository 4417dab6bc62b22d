#pragma once
// Three plain arrays (x, y, z) for per-particle vectors: contiguous loops, no per-particle
// objects. Body-level math uses Vec3 (Eigen) instead.
#include <cstddef>
#include <vector>

#include "engine/core/vec3.hpp"

namespace washout::rigid {

struct Vec3Array {
  std::vector<double> x, y, z;

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    x.resize(n);
    y.resize(n);
    z.resize(n);
  }
  void clear() { resize(0); }
  void push_back(const Vec3& v) {
    x.push_back(v.x());
    y.push_back(v.y());
    z.push_back(v.z());
  }
  Vec3 operator[](std::size_t i) const { return Vec3(x[i], y[i], z[i]); }
  void set(std::size_t i, const Vec3& v) {
    x[i] = v.x();
    y[i] = v.y();
    z[i] = v.z();
  }
};

}  // namespace washout::rigid
