#include "engine/rigid/lattice_body.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace washout::rigid {
namespace {

BodyParticles empty_body(int dim, double spacing, double density) {
  if (!(spacing > 0.0) || !(density > 0.0))
    throw std::invalid_argument("lattice body: spacing and density must be > 0");
  BodyParticles p;
  p.dim = dim;
  p.spacing = spacing;
  p.particle_mass = density * std::pow(spacing, dim);
  return p;
}

// Cells of a centred lattice within `half_cells` of the centre along each axis: offsets
// k d0 with |k| <= half_cells (so the centre is a particle).
template <typename Inside>
void fill_centred(BodyParticles& p, const Vec3& centre, int half_cells, int half_cells_z,
                  Inside inside) {
  const double d0 = p.spacing;
  for (int k = -half_cells_z; k <= half_cells_z; ++k)
    for (int j = -half_cells; j <= half_cells; ++j)
      for (int i = -half_cells; i <= half_cells; ++i) {
        const Vec3 offset(i * d0, j * d0, k * d0);
        if (inside(offset)) p.position.push_back(centre + offset);
      }
}

}  // namespace

BodyParticles lattice_box(int dim, double spacing, const Vec3& lower, const Vec3& upper,
                          double density) {
  BodyParticles p = empty_body(dim, spacing, density);
  const double d0 = spacing;
  int cells[3] = {1, 1, 1};
  for (int a = 0; a < dim; ++a) {
    cells[a] = static_cast<int>(std::lround((upper[a] - lower[a]) / d0));
    if (cells[a] < 1) throw std::invalid_argument("lattice_box: a side shorter than d0");
  }
  const double face = dim == 3 ? d0 * d0 : d0;  // area of one cell face (2D: per unit depth)
  for (int k = 0; k < cells[2]; ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i) {
        const int index[3] = {i, j, k};
        Vec3 x = lower + d0 * Vec3(i + 0.5, j + 0.5, k + 0.5);
        if (dim == 2) x.z() = 0.0;
        p.position.push_back(x);
        Vec3 vector_area = Vec3::Zero();
        for (int a = 0; a < dim; ++a) {
          if (index[a] == 0) vector_area[a] -= face;
          if (index[a] == cells[a] - 1) vector_area[a] += face;
        }
        // Where the box is one cell thick, that particle's two opposite faces cancel.
        const double area = vector_area.norm();
        p.surface.push_back(area > 0.0 ? 1 : 0);
        p.normal.push_back(area > 0.0 ? Vec3(vector_area / area) : Vec3::UnitZ());
        p.area.push_back(area);
      }
  return p;
}

BodyParticles lattice_ball(int dim, double spacing, const Vec3& centre, double radius,
                           double density) {
  BodyParticles p = empty_body(dim, spacing, density);
  const int half = static_cast<int>(std::ceil(radius / spacing)) + 1;
  const double r2 = radius * radius;
  auto inside = [&](const Vec3& offset) { return offset.squaredNorm() < r2; };
  fill_centred(p, centre, half, dim == 3 ? half : 0, inside);
  const std::size_t n = p.position.size();
  std::size_t count = 0;
  p.surface.assign(n, 0);
  p.normal.resize(n);
  p.area.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 offset = p.position[i] - centre;
    bool outer = false;
    for (int a = 0; a < dim; ++a)
      for (double s : {-1.0, 1.0})
        if (!inside(offset + s * spacing * Vec3::Unit(a))) outer = true;
    p.normal.set(i, offset.norm() > 0.0 ? Vec3(offset.normalized()) : Vec3::UnitZ());
    if (outer) {
      p.surface[i] = 1;
      ++count;
    }
  }
  const double total = dim == 3 ? 4.0 * std::numbers::pi * r2 : 2.0 * std::numbers::pi * radius;
  for (std::size_t i = 0; i < n; ++i)
    if (p.surface[i]) p.area[i] = total / static_cast<double>(count);
  return p;
}

BodyParticles lattice_cylinder(double spacing, const Vec3& centre, double radius, double length,
                               double density) {
  BodyParticles p = empty_body(3, spacing, density);
  const int half = static_cast<int>(std::ceil(radius / spacing)) + 1;
  const int layers = static_cast<int>(std::lround(length / spacing));
  if (layers < 1) throw std::invalid_argument("lattice_cylinder: length shorter than d0");
  const double r2 = radius * radius;
  for (int k = 0; k < layers; ++k) {
    const double z = centre.z() - 0.5 * layers * spacing + (k + 0.5) * spacing;
    for (int j = -half; j <= half; ++j)
      for (int i = -half; i <= half; ++i) {
        const double x = i * spacing, y = j * spacing;
        if (x * x + y * y < r2) p.position.push_back(Vec3(centre.x() + x, centre.y() + y, z));
      }
  }
  return p;
}

}  // namespace washout::rigid
