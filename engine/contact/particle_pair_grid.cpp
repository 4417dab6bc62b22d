#include "engine/contact/particle_pair_grid.hpp"

#include <algorithm>
#include <cmath>

namespace washout::contact {
namespace {

// 21 bits per axis, offset so that negative cells stay positive.
constexpr std::int64_t kOffset = 1 << 20;
constexpr std::uint64_t kMask = (1u << 21) - 1;

std::uint64_t cell_key(std::int64_t ix, std::int64_t iy, std::int64_t iz) {
  return (static_cast<std::uint64_t>(ix + kOffset) & kMask) << 42 |
         (static_cast<std::uint64_t>(iy + kOffset) & kMask) << 21 |
         (static_cast<std::uint64_t>(iz + kOffset) & kMask);
}

}  // namespace

void ParticlePairGrid::find_pairs(const rigid::Vec3Array& position,
                                  const std::vector<std::int32_t>& group, double cutoff, int dim,
                                  std::vector<ParticlePair>& pairs) {
  pairs.clear();
  const std::size_t n = position.size();
  if (n < 2 || !(cutoff > 0.0)) return;
  // Cells relative to the first particle keep the indices small wherever the bodies are.
  const double inv = 1.0 / cutoff;
  const double ox = position.x[0], oy = position.y[0], oz = position.z[0];
  auto cell = [&](std::size_t i, int axis) {
    const double origin = axis == 0 ? ox : (axis == 1 ? oy : oz);
    const double v = axis == 0 ? position.x[i] : (axis == 1 ? position.y[i] : position.z[i]);
    return static_cast<std::int64_t>(std::floor((v - origin) * inv));
  };
  sorted_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t iz = dim == 3 ? cell(i, 2) : 0;
    sorted_[i] = {cell_key(cell(i, 0), cell(i, 1), iz), static_cast<std::int32_t>(i)};
  }
  std::sort(sorted_.begin(), sorted_.end(), [](const Entry& a, const Entry& b) {
    return a.key != b.key ? a.key < b.key : a.index < b.index;
  });
  const double cutoff2 = cutoff * cutoff;
  const int z_reach = dim == 3 ? 1 : 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int64_t cx = cell(i, 0), cy = cell(i, 1), cz = dim == 3 ? cell(i, 2) : 0;
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dz = -z_reach; dz <= z_reach; ++dz) {
          const std::uint64_t key = cell_key(cx + dx, cy + dy, cz + dz);
          auto it = std::lower_bound(sorted_.begin(), sorted_.end(), key,
                                     [](const Entry& e, std::uint64_t k) { return e.key < k; });
          for (; it != sorted_.end() && it->key == key; ++it) {
            const auto j = static_cast<std::size_t>(it->index);
            if (j <= i || group[i] == group[j]) continue;
            const double rx = position.x[i] - position.x[j];
            const double ry = position.y[i] - position.y[j];
            const double rz = dim == 3 ? position.z[i] - position.z[j] : 0.0;
            if (rx * rx + ry * ry + rz * rz < cutoff2)
              pairs.push_back({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j)});
          }
        }
      }
    }
  }
}

}  // namespace washout::contact
