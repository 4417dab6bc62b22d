#include "engine/sim/implicit_body_coupling.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "engine/fluid/wall_velocity_response.hpp"
#include "engine/rigid/body_state.hpp"
#include "engine/sim/rigid_body_system.hpp"
#include "engine/sim/simulation.hpp"

namespace washout {
namespace {

// A body's block of the stacked degrees of freedom: linear then angular components
// (x, y, w_z in 2D; x, y, z, w_x, w_y, w_z in 3D).
void pack(const Vec3& linear, const Vec3& angular, int dim, int first,
          Eigen::Ref<Eigen::VectorXd> out) {
  for (int a = 0; a < dim; ++a) out[first + a] = linear[a];
  if (dim == 2)
    out[first + 2] = angular.z();
  else
    for (int a = 0; a < 3; ++a) out[first + 3 + a] = angular[a];
}

void unpack(const Eigen::VectorXd& in, int dim, int first, Vec3& linear, Vec3& angular) {
  linear = angular = Vec3::Zero();
  for (int a = 0; a < dim; ++a) linear[a] = in[first + a];
  if (dim == 2)
    angular.z() = in[first + 2];
  else
    for (int a = 0; a < 3; ++a) angular[a] = in[first + 3 + a];
}

// G_k = F(S_k): the load of each response field on each body, for the columns k marked in
// `stale`. The field replaces p.pressure for the evaluation.
void response_loads(const SphContext& ctx, const NeighborGrid& grid, Particles& p,
                    const FluidWork& work, RigidBodySystem& bodies,
                    const std::vector<int>& first_column,
                    const std::vector<std::vector<double>>& solution,
                    const std::vector<std::uint8_t>& stale, std::vector<double>& field,
                    Eigen::MatrixXd& G) {
  const int columns = static_cast<int>(solution.size());
  std::swap(field, p.pressure);
  p.pressure.assign(p.size(), 0.0);
  for (int k = 0; k < columns; ++k) {
    if (!stale[k]) continue;
    G.col(k).setZero();
    for (std::size_t i = 0; i < p.fluid_count; ++i)
      p.pressure[i] = work.unknown[i] >= 0 ? solution[k][work.unknown[i]] : 0.0;
    const auto& loads = bodies.loads_of_pressure(ctx, grid, p, Vec3::Zero(), true);
    for (std::size_t b = 0; b < bodies.size(); ++b)
      if (first_column[b] >= 0)
        pack(loads[b].force, loads[b].torque, ctx.dim, first_column[b], G.col(k));
  }
  std::swap(field, p.pressure);
}

// (M / dt - G) dxi = F(P0) + M g + F_c - w x I w
Eigen::VectorXd velocity_change(const Eigen::MatrixXd& G, const std::vector<rigid::BodyLoad>& base,
                                const std::vector<int>& first_column, const RigidBodySystem& bodies,
                                int dim, const Vec3& gravity, double dt) {
  Eigen::MatrixXd K = -G;
  Eigen::VectorXd rhs(G.rows());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int first = first_column[b];
    if (first < 0) continue;
    const rigid::BodyModel& model = bodies.model(b);
    const rigid::BodyState& s = bodies.state(b);
    const Eigen::Matrix3d I = rigid::world_inertia(model, s.orientation);
    const rigid::BodyLoad& contact = bodies.contact_load(b);
    pack(base[b].force + model.mass * gravity + contact.force,
         base[b].torque + contact.torque - s.angular_velocity.cross(I * s.angular_velocity), dim,
         first, rhs);
    for (int a = 0; a < dim; ++a) K(first + a, first + a) += model.mass / dt;
    if (dim == 2)
      K(first + 2, first + 2) += I(2, 2) / dt;
    else
      K.block(first + 3, first + 3, 3, 3) += I / dt;
  }
  const Eigen::VectorXd dxi = K.partialPivLu().solve(rhs);
  if (!dxi.allFinite()) throw UnstableError("the body coupling's velocity system is singular");
  return dxi;
}

}  // namespace

CouplingReport ImplicitBodyCoupling::couple(const SphContext& ctx, const NeighborList& list,
                                            const NeighborGrid& grid, Particles& p, FluidWork& work,
                                            LinearSolver& solver, RigidBodySystem& bodies,
                                            const Vec3& gravity, double dt,
                                            const CouplingTolerances& tolerances) {
  CouplingReport report;
  const int dim = ctx.dim, per_body = dim == 2 ? 3 : 6;
  std::vector<int> first_column(bodies.size(), -1);
  std::vector<Vec3> centre(bodies.size());
  int columns = 0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    centre[b] = bodies.state(b).position;
    if (bodies.dynamic(b)) {
      first_column[b] = columns;
      columns += per_body;
    }
  }
  bodies.compute_fluid_loads(ctx, grid, p, gravity);  // F(P0)
  if (columns == 0 || work.matrix.rows == 0) return report;

  // S_k = A^-1 B_k, warm-started from the last step's S_k (by particle).
  response_.resize(columns);
  assemble_wall_velocity_response(ctx, list, p, work, first_column, centre, dt, response_);
  solution_.resize(columns);
  previous_.resize(columns);
  residual_.assign(columns, 0.0);
  const std::size_t n = p.fluid_count;
  const auto norm = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
  };
  std::vector<double> response_norm(columns);
  for (int k = 0; k < columns; ++k) response_norm[k] = norm(response_[k]);
  // Solves S_k to a relative residual `tolerance`; residual_[k] = |B_k - A S_k|.
  const auto solve_response = [&](int k, double tolerance) {
    auto& x = solution_[k];
    const SolveReport solve = solver.solve_again_to(work.matrix, response_[k], x, tolerance);
    if (!solve.converged)
      throw UnstableError("the body coupling's pressure response did not converge in " +
                          std::to_string(solve.iterations) + " iterations");
    ++report.solves;
    report.iterations += solve.iterations;
    residual_[k] = solve.relative_residual * response_norm[k];
  };
  for (int k = 0; k < columns; ++k) {
    auto& x = solution_[k];
    x.assign(work.matrix.rows, 0.0);
    if (previous_[k].size() == n)
      for (std::size_t i = 0; i < n; ++i)
        if (work.unknown[i] >= 0) x[work.unknown[i]] = previous_[k][i];
    solve_response(k, tolerances.response);
  }

  std::vector<rigid::BodyLoad> base(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) base[b] = bodies.fluid_load(b);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(columns, columns);
  Eigen::VectorXd dxi;
  std::vector<std::uint8_t> stale(columns, 1);  // G's columns to (re)compute
  // The responses only enter the pressure as sum_k S_k dxi_k, dxi a step's small change of the
  // bodies' velocities: they need not meet the pressure solve's tolerance, only their share of
  // the coupled pressure's residual, sum_k |B_k - A S_k| |dxi_k|, must stay within the solve's
  // own |b| tolerance. Solved loosely first; the few that break that bound, once dxi is known,
  // are solved again to the tolerance it asks for, and the bodies' system with them.
  const double allowed = tolerances.pressure * norm(work.rhs);
  for (int round = 0;; ++round) {
    response_loads(ctx, grid, p, work, bodies, first_column, solution_, stale, field_, G);
    dxi = velocity_change(G, base, first_column, bodies, dim, gravity, dt);
    if (round == 2) break;  // two rounds of re-solves: the second only if dxi moved much
    bool refined = false;
    for (int k = 0; k < columns; ++k) {
      const double share = residual_[k] * std::abs(dxi[k]);
      stale[k] = share > allowed / columns;
      if (!stale[k]) continue;
      // Half of the share it may have: dxi moves a little with the better S_k.
      solve_response(k, 0.5 * allowed / (columns * std::abs(dxi[k]) * response_norm[k]));
      refined = true;
    }
    if (!refined) break;
  }
  for (int k = 0; k < columns; ++k) {
    previous_[k].assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      if (work.unknown[i] >= 0) previous_[k][i] = solution_[k][work.unknown[i]];
  }

  // The loads, pressure and wall accelerations that belong to the new velocities.
  const Eigen::VectorXd dF = G * dxi;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int first = first_column[b];
    if (first < 0) continue;
    Vec3 dforce, dtorque;
    unpack(dF, dim, first, dforce, dtorque);
    rigid::BodyLoad load = base[b];
    load.force += dforce;
    load.torque += dtorque;
    bodies.set_fluid_load(b, load);
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row < 0) continue;
    double sum = 0.0;
    for (int k = 0; k < columns; ++k) sum += solution_[k][row] * dxi[k];
    p.pressure[i] += sum;
  }
  for (std::size_t w = n; w < p.size(); ++w) {
    const std::int32_t b = p.body[w];
    if (b < 0 || first_column[b] < 0) continue;
    Vec3 dT, dw;
    unpack(dxi, dim, first_column[b], dT, dw);
    const Vec3 du = dT + dw.cross(p.x(w) - centre[b]);
    for (int a = 0; a < 3; ++a) work.boundary.wall_acceleration[a][w] = du[a] / dt;
  }
  return report;
}

}  // namespace washout
