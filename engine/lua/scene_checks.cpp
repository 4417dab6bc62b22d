#include "engine/lua/scene_checks.hpp"

#include <algorithm>
#include <cmath>

#include "engine/lua/lua_errors.hpp"
#include "engine/sim/simulation.hpp"

namespace washout::lua {

std::string non_finite_parameter(const ParameterSet& set) {
  for (const auto& name : set.names()) {
    const auto& v = set.get(name);
    std::vector<double> numbers;
    if (auto d = std::get_if<double>(&v)) numbers = {*d};
    if (auto list = std::get_if<std::vector<double>>(&v)) numbers = *list;
    for (double x : numbers)
      if (std::isnan(x) || (name == "gravity" && !std::isfinite(x))) return name;
  }
  return "";
}

void check_probes(const Model& model) {
  const int dim = model.params.dim;
  Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
  auto include = [&](const Shape& s) {
    if (s.empty()) return;
    const Aabb b = s.bounds(dim);
    lo = lo.cwiseMin(b.lower), hi = hi.cwiseMax(b.upper);
  };
  for (const auto& f : model.fluids) include(f.shape);
  for (const auto& w : model.walls) include(w.shape);
  for (const auto& b : model.bodies) include(b.shape);
  const double margin = 2.0 * model.params.h();
  lo.array() -= margin, hi.array() += margin;
  const auto& pmin = model.params.domain_min;
  const auto& pmax = model.params.domain_max;
  for (int a = 0; a < dim; ++a) {
    if (static_cast<int>(pmin.size()) == dim) lo[a] = pmin[a];
    if (static_cast<int>(pmax.size()) == dim) hi[a] = pmax[a];
  }
  // Which axis is "up" for a water height: the one gravity mostly points along.
  int up = dim - 1;
  for (int a = 0; a < dim; ++a)
    if (std::abs(model.params.gravity[a]) > std::abs(model.params.gravity[up])) up = a;
  for (const auto& p : model.probes) {
    if (p.quantity == ProbeSpec::Quantity::Front) continue;
    for (int a = 0; a < dim; ++a) {
      if (p.quantity == ProbeSpec::Quantity::WaterHeight && a == up) continue;
      if (!(p.point[a] >= lo[a] && p.point[a] <= hi[a])) {
        const char axis = static_cast<char>('x' + a);
        throw SceneError("probe '" + p.name + "': its point lies outside the domain (" + axis +
                             " = " + detail::number_text(p.point[a]) + ", the domain spans " +
                             detail::number_text(lo[a]) + " to " + detail::number_text(hi[a]) + ")",
                         p.where);
      }
    }
  }
}

namespace {

// Lattice points in a primitive's bounds, all of them or only those within `depth` of a face.
double lattice_count(const Primitive& p, int dim, double d0, double depth) {
  const Aabb b = p.bounds(dim);
  double all = 1, core = 1;
  for (int a = 0; a < dim; ++a) {
    const double extent = b.upper[a] - b.lower[a];
    all *= extent / d0 + 1;
    core *= std::max(0.0, (extent - 2 * depth) / d0 - 1);
  }
  return depth > 0 ? all - core : all;
}

// Memory a particle takes during a run: the girder scene (124 000 particles, 3D) peaks near
// 1.1 KB a particle above the program's own 64 MB after a step; doubled for the pressure
// solver's factor and the output buffers. The estimate of the count itself runs 1.2-1.4 times
// the particles actually made (measured on the girder, dam-break and floating-box scenes).
double bytes_per_particle(int dim) { return dim == 3 ? 2000.0 : 1000.0; }

}  // namespace

double estimate_particles(const Model& model) {
  const auto& prm = model.params;
  const int dim = prm.dim;
  const double d0 = prm.d0;
  const int layers = prm.wall_layer_count();
  double n = 0;
  for (const auto& f : model.fluids)
    for (const auto& p : f.shape.parts()) n += lattice_count(p, dim, d0, 0);
  for (const auto& w : model.walls)
    for (const auto& p : w.shape.parts()) n += lattice_count(p, dim, d0, layers * d0);
  for (const auto& b : model.bodies)
    for (const auto& p : b.shape.parts()) n += lattice_count(p, dim, d0, layers * d0);
  return n;
}

void check_particle_budget(const Model& model) {
  const double n = estimate_particles(model);
  const double limit = model.params.max_particles;
  if (n <= limit) return;
  const double gib = n * bytes_per_particle(model.params.dim) / (1024.0 * 1024.0 * 1024.0);
  throw SceneError("the scene would make about " + detail::number_text(n) +
                       " particles (d0 = " + detail::number_text(model.params.d0) + " m), about " +
                       detail::number_text(gib) + " GiB of memory, above max_particles = " +
                       detail::number_text(limit) + "; use a larger d0 or raise max_particles",
                   model.scene_path, "max_particles");
}

}  // namespace washout::lua
