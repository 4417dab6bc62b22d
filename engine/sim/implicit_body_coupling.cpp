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

// The linear surface load of a pressure field on the PPE's rows, packed by body into `out`.
void linear_load(const SphContext& ctx, const Particles& p, RigidBodySystem& bodies,
                 const std::vector<int>& first_column, const std::vector<double>& rows,
                 Eigen::Ref<Eigen::VectorXd> out) {
  out.setZero();
  const auto& loads = bodies.linear_load(ctx, p, rows);
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (first_column[b] >= 0) pack(loads[b].force, loads[b].torque, ctx.dim, first_column[b], out);
}

// M / dt - G, the bodies' mass and inertia over the step less the response loads.
Eigen::MatrixXd coupled_matrix(const Eigen::MatrixXd& G, const std::vector<int>& first_column,
                               const RigidBodySystem& bodies, int dim, double dt) {
  Eigen::MatrixXd K = -G;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int first = first_column[b];
    if (first < 0) continue;
    const rigid::BodyModel& model = bodies.model(b);
    const Eigen::Matrix3d I = rigid::world_inertia(model, bodies.state(b).orientation);
    for (int a = 0; a < dim; ++a) K(first + a, first + a) += model.mass / dt;
    if (dim == 2)
      K(first + 2, first + 2) += I(2, 2) / dt;
    else
      K.block(first + 3, first + 3, 3, 3) += I / dt;
  }
  return K;
}

// F(P0) + M g + F_c - w x I w
Eigen::VectorXd coupled_load(const std::vector<rigid::BodyLoad>& base,
                             const std::vector<int>& first_column, const RigidBodySystem& bodies,
                             int dim, int columns, const Vec3& gravity) {
  Eigen::VectorXd rhs(columns);
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
  }
  return rhs;
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
  std::vector<rigid::BodyLoad> base(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) base[b] = bodies.fluid_load(b);
  const std::size_t n = p.fluid_count;
  // The bodies' new loads F(P0) + change, and their particles' accelerations (the walls'
  // velocities of the next step's markers).
  const auto finish = [&](const Eigen::VectorXd& dxi, const Eigen::VectorXd& load_change) {
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const int first = first_column[b];
      if (first < 0) continue;
      Vec3 dforce, dtorque;
      unpack(load_change, dim, first, dforce, dtorque);
      rigid::BodyLoad changed = base[b];
      changed.force += dforce;
      changed.torque += dtorque;
      bodies.set_fluid_load(b, changed);
    }
    for (std::size_t w = n; w < p.size(); ++w) {
      const std::int32_t b = p.body[w];
      if (b < 0 || first_column[b] < 0) continue;
      Vec3 dT, dw;
      unpack(dxi, dim, first_column[b], dT, dw);
      const Vec3 du = dT + dw.cross(p.x(w) - centre[b]);
      for (int a = 0; a < 3; ++a) work.boundary.wall_acceleration[a][w] = du[a] / dt;
    }
  };
  const Eigen::VectorXd load = coupled_load(base, first_column, bodies, dim, columns, gravity);
  // (M / dt - G) dxi = load
  const auto velocity_change = [&](const Eigen::PartialPivLU<Eigen::MatrixXd>& K) {
    Eigen::VectorXd dxi = K.solve(load);
    if (!dxi.allFinite()) throw UnstableError("the body coupling's velocity system is singular");
    return dxi;
  };
  if (bodies.dry()) {
    // No fluid near any body (the girder before the wave): the responses are zero, the pressure
    // stays P0, and the last step's responses are no warm start for the next.
    previous_.assign(columns, {});
    const Eigen::MatrixXd G = Eigen::MatrixXd::Zero(columns, columns);
    finish(velocity_change(Eigen::PartialPivLU<Eigen::MatrixXd>(
               coupled_matrix(G, first_column, bodies, dim, dt))),
           Eigen::VectorXd::Zero(columns));
    return report;
  }

  // S_k = A^-1 B_k, warm-started from the last step's S_k (by particle).
  response_.resize(columns);
  fluid_beside_bodies(ctx, grid, p, first_column, beside_mark_, beside_);
  assemble_wall_velocity_response(ctx, list, p, work, first_column, centre, dt, beside_, response_);
  solution_.resize(columns);
  previous_.resize(columns);
  residual_.assign(columns, 0.0);
  const auto norm = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return std::sqrt(s);
  };
  for (int k = 0; k < columns; ++k) {
    auto& x = solution_[k];
    x.assign(work.matrix.rows, 0.0);
    if (previous_[k].size() == n)
      for (std::size_t i = 0; i < n; ++i)
        if (work.unknown[i] >= 0) x[work.unknown[i]] = previous_[k][i];
  }
  std::vector<double> response_norm(columns, 0.0);
  for (int k = 0; k < columns; ++k) response_norm[k] = norm(response_[k]);
  const bool wet = *std::max_element(response_norm.begin(), response_norm.end()) > 0.0;
  // The responses are solved as a set, each to `response` times the largest of its kind
  // (translations, rotations): one the body's wet faces hardly excite (the sideways push of a
  // girder wetted on its front and floor, 1e-15 of the others) needs no iterations of its own.
  std::vector<double> largest(columns, 0.0);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const int first = first_column[b];
    if (first < 0) continue;
    const int translations = dim;
    for (int k = first; k < first + per_body; ++k) {
      const bool rotation = k - first >= translations;
      for (int j = first; j < first + per_body; ++j)
        if ((j - first >= translations) == rotation)
          largest[k] = std::max(largest[k], response_norm[j]);
    }
  }
  // Side by side: an iterative solver reads the matrix once for the products of all of them,
  // the warm starts' residuals first, and a response already within its tolerance takes no
  // iteration. residual_[k] = |B_k - A S_k|.
  std::vector<const std::vector<double>*> right_side;
  std::vector<std::vector<double>*> unsolved;
  std::vector<double> tolerance;
  for (int k = 0; k < columns; ++k) {
    right_side.push_back(&response_[k]);
    unsolved.push_back(&solution_[k]);
    tolerance.push_back(response_norm[k] > 0.0 ? tolerances.response * largest[k] / response_norm[k]
                                               : tolerances.response);
  }
  const std::vector<SolveReport> solves =
      solver.solve_many_again_to(work.matrix, right_side, unsolved, tolerance);
  for (int k = 0; k < columns; ++k) {
    if (!solves[k].converged)
      throw UnstableError("the body coupling's pressure response did not converge in " +
                          std::to_string(solves[k].iterations) + " iterations");
    if (solves[k].iterations > 0 || solver.direct()) ++report.solves;
    report.iterations += solves[k].iterations;
    residual_[k] = solves[k].relative_residual * response_norm[k];
  }

  // A body with no fluid beside it has zero responses and loads.
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(columns, columns);
  if (wet) {
    bodies.build_linear_load(ctx, grid, p, work.unknown);
    for (int k = 0; k < columns; ++k)
      linear_load(ctx, p, bodies, first_column, solution_[k], G.col(k));
  }
  const Eigen::PartialPivLU<Eigen::MatrixXd> K(coupled_matrix(G, first_column, bodies, dim, dt));
  Eigen::VectorXd dxi = velocity_change(K);

  // The responses only enter the pressure as sum_k S_k dxi_k, dxi a step's small change of the
  // bodies' velocities: they need not meet the pressure solve's tolerance, only their share of
  // the coupled pressure's residual, sum_k |B_k - A S_k| |dxi_k|, must stay within the solve's
  // own |b| tolerance. Where it does not (a body whose velocity changes much), the coupled
  // pressure is solved once for the walls' velocities of dxi, warm-started from
  // P0 + sum S_k dxi_k, and its exact load corrects dxi: the loose G serves as the Jacobian of a
  // defect correction, each round shrinking dxi's error by about G's relative error.
  const double allowed = tolerances.pressure * norm(work.rhs);
  const auto share = [&](const Eigen::VectorXd& change) {
    double sum = 0.0;
    for (int k = 0; k < columns; ++k) sum += residual_[k] * std::abs(change[k]);
    return sum;
  };
  const std::size_t rows = work.matrix.rows;
  coupled_.assign(work.solution.begin(), work.solution.begin() + rows);
  coupled_rhs_.assign(work.rhs.begin(), work.rhs.begin() + rows);
  field_rows_.resize(rows);
  const auto move_by = [&](const Eigen::VectorXd& change) {
#pragma omp parallel for schedule(static)
    for (std::size_t r = 0; r < rows; ++r) {
      double x = 0.0, b = 0.0;
      for (int k = 0; k < columns; ++k) {
        x += solution_[k][r] * change[k];
        b += response_[k][r] * change[k];
      }
      coupled_[r] += x;
      coupled_rhs_[r] += b;
    }
  };
  move_by(dxi);
  Eigen::VectorXd load_change = G * dxi;  // F(P) - F(P0)
  if (share(dxi) > allowed) {
    for (int round = 0; round < 3; ++round) {
      const SolveReport solve =
          solver.solve_again_to(work.matrix, coupled_rhs_, coupled_, tolerances.pressure);
      if (!solve.converged)
        throw UnstableError("the body coupling's pressure did not converge in " +
                            std::to_string(solve.iterations) + " iterations");
      ++report.solves;
      report.iterations += solve.iterations;
      for (std::size_t r = 0; r < rows; ++r) field_rows_[r] = coupled_[r] - work.solution[r];
      linear_load(ctx, p, bodies, first_column, field_rows_, load_change);
      const Eigen::VectorXd change = K.solve(load + load_change - G * dxi) - dxi;
      move_by(change);
      load_change += G * change;
      dxi += change;
      if (share(change) <= allowed) break;
    }
  }
  for (int k = 0; k < columns; ++k) {
    previous_[k].assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      if (work.unknown[i] >= 0) previous_[k][i] = solution_[k][work.unknown[i]];
  }

  // The loads, pressure and wall accelerations that belong to the new velocities.
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t row = work.unknown[i];
    if (row >= 0) p.pressure[i] = coupled_[row];
  }
  finish(dxi, load_change);
  return report;
}

}  // namespace washout
