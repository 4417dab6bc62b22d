// Dam break of Martin & Moyce (1952), n^2 = 2: surge front Z = x/a against T = t sqrt(2g/a),
// compared with their Table 2 (validation/reference/mm1952_n2_front_table.csv, Ocellaris
// transcription) over T <= 3. The scenes score themselves the same way (scripts/validation.lua);
// this file recomputes the error independently and checks the scene's own figure against it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "engine/model/parameters.hpp"
#include "engine/sim/time_step_limits.hpp"
#include "support/scene_runner.hpp"

namespace washout {
namespace {

constexpr double kColumn = 0.146;  // a [m], as in the scenes

// The run's front as Z = x/a against T = t sqrt(2g/a), and Martin & Moyce's Table 2 points.
struct FrontSeries {
  std::vector<double> T, Z, T_table, Z_table;
};
FrontSeries read_front(const std::string& h5) {
  io::RunFileReader run(h5);
  const auto t = run.read_doubles("/probes/front/time");
  const auto x = run.read_doubles("/probes/front/value");
  FrontSeries f;
  for (std::size_t k = 0; k < t.size(); ++k) {
    f.T.push_back(t[k] * std::sqrt(2 * 9.81 / kColumn));
    f.Z.push_back(x[k] / kColumn);
  }
  const auto csv = testing::read_csv(testing::refdata("mm1952_n2_front_table.csv"));
  for (std::size_t k = 0; k < csv.at("source").size(); ++k) {
    if (csv.at("source")[k] != "ocellaris_table2") continue;
    f.T_table.push_back(std::stod(csv.at("T_t_sqrt_2g_over_a")[k]));
    f.Z_table.push_back(std::stod(csv.at("Z_x_over_a")[k]));
  }
  return f;
}

// RMS of Z_sim - Z_exp over the table's points with T <= 3 (and within the run).
double front_rms(const std::string& h5, double* mean_error) {
  const FrontSeries f = read_front(h5);
  double sum2 = 0, sum = 0;
  int count = 0;
  for (std::size_t k = 0; k < f.T_table.size(); ++k) {
    const double Tr = f.T_table[k], Zr = f.Z_table[k];
    if (Tr > 3.0 || Tr > f.T.back()) continue;
    const double e = testing::interpolate(f.T, f.Z, Tr) - Zr;
    std::printf("  T = %.2f  Z_exp = %.2f  Z_sim = %.3f\n", Tr, Zr, Zr + e);
    sum2 += e * e, sum += e, ++count;
  }
  EXPECT_GE(count, 12);  // 13 points of the table have T <= 3
  *mean_error = sum / count;
  return std::sqrt(sum2 / count);
}

// The same RMS with the experiment's clock moved: the run's front at t against the table at
// t + delay, for delays of -40 to 40 ms in steps of 0.5 ms (at least 5 table points with T <= 3
// inside the run); the best RMS and its delay.
double delayed_front_rms(const std::string& h5, double* best_delay) {
  const FrontSeries f = read_front(h5);
  const double scale = std::sqrt(2 * 9.81 / kColumn);
  double best = 1e9;
  for (int k = -80; k <= 80; ++k) {
    const double delay = 0.0005 * k, shift = delay * scale;
    double sum2 = 0;
    int count = 0;
    for (std::size_t m = 0; m < f.T_table.size(); ++m) {
      const double Tr = f.T_table[m];
      if (Tr > 3.0 || Tr - shift < f.T.front() || Tr - shift > f.T.back()) continue;
      const double e = testing::interpolate(f.T, f.Z, Tr - shift) - f.Z_table[m];
      sum2 += e * e, ++count;
    }
    if (count >= 5 && std::sqrt(sum2 / count) < best) {
      best = std::sqrt(sum2 / count);
      *best_delay = delay;
    }
  }
  return best;
}

// Martin & Moyce's second measurement: the residual height of the column at the back wall,
// H = eta/(2a) against tau = t sqrt(g/a) (mm1952_n2_residual_height_table.csv), the run's
// `residual_height` probe; RMS over the table's points with tau <= 3.5 within the run, the
// experiment's clock moved by `delay` [s] (the run at t against the table at t + delay).
double residual_height_rms(const std::string& h5, double delay) {
  io::RunFileReader run(h5);
  const auto t = run.read_doubles("/probes/residual_height/time");
  const auto eta = run.read_doubles("/probes/residual_height/value");
  const double scale = std::sqrt(9.81 / kColumn);
  std::vector<double> tau, H;
  for (std::size_t k = 0; k < t.size(); ++k) {
    tau.push_back((t[k] + delay) * scale);
    H.push_back(eta[k] / (2 * kColumn));
  }
  const auto csv = testing::read_csv(testing::refdata("mm1952_n2_residual_height_table.csv"));
  double sum2 = 0;
  int count = 0;
  for (std::size_t k = 0; k < csv.at("tau_t_sqrt_g_over_a").size(); ++k) {
    const double tr = std::stod(csv.at("tau_t_sqrt_g_over_a")[k]);
    if (tr > 3.5 || tr > tau.back()) continue;
    const double e = testing::interpolate(tau, H, tr) - std::stod(csv.at("H_eta_over_2a")[k]);
    sum2 += e * e, ++count;
  }
  EXPECT_GE(count, 5);
  return std::sqrt(sum2 / count);
}

// The surge's speed once the release is over: the least-squares slope of the run's Z(T) at the
// table's points with 1.15 <= T <= 3.15 over the table's own slope there, minus one.
double front_speed_error(const std::string& h5) {
  const FrontSeries f = read_front(h5);
  std::vector<double> T, run, table;
  for (std::size_t k = 0; k < f.T_table.size(); ++k) {
    const double Tr = f.T_table[k];
    if (Tr < 1.15 || Tr > 3.15 || Tr > f.T.back()) continue;
    T.push_back(Tr);
    run.push_back(testing::interpolate(f.T, f.Z, Tr));
    table.push_back(f.Z_table[k]);
  }
  EXPECT_GE(T.size(), 5u);
  const auto slope = [&](const std::vector<double>& y) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = static_cast<double>(T.size());
    for (std::size_t k = 0; k < T.size(); ++k)
      sx += T[k], sy += y[k], sxx += T[k] * T[k], sxy += T[k] * y[k];
    return (n * sxy - sx * sy) / (n * sxx - sx * sx);
  };
  return slope(run) / slope(table) - 1.0;
}

// Runs a dam-break scene, prints the front error and returns {RMS, mean}.
struct FrontResult {
  double rms, mean;
  long wall_crossings;
  std::string h5;
};
FrontResult run_front(const std::string& scene, const std::string& test_name, const char* label,
                      const lua::Overrides& overrides) {
  const auto out = testing::run_scene(scene, test_name, overrides);
  EXPECT_EQ(out.exit_code, 0);
  if (out.exit_code != 0) return {1e9, 1e9, 0, ""};
  FrontResult r{0, 0, out.summary.wall_crossings, out.h5_path};
  r.rms = front_rms(out.h5_path, &r.mean);
  // The scene's own score (washout.validation in the scene) is the same number.
  io::RunFileReader run(out.h5_path);
  EXPECT_NEAR(run.double_attribute("error"), r.rms, 1e-9);
  EXPECT_EQ(run.string_attribute("error_names").rfind("front", 0), 0u);  // the primary score
  std::printf("dam break %s: front RMS error %.4f (mean %+.4f), %ld steps, %.1f s\n", label, r.rms,
              r.mean, out.summary.steps, out.summary.wall_seconds);
  return r;
}

// Bounds: Martin & Moyce's front lags an instantaneous release at early times (their column
// was not released instantaneously: at t = 0.072 s their toe had advanced 0.032 m, Lobovsky et
// al.'s, from a column as high, 0.097 m; docs/method.md), so the error does not fall with d0
// and these are regression bounds: what washout measures now with a margin of about 20 %.
// At a/d0 = 10 the surge is two particles thick and its tip lags (P = 0 is imposed d0/2
// beyond the surface particles, which at a two-particle tip slows it) and, since the seventh
// session's defaults, the law-of-the-wall friction slows a surge that shallow further:
// measured 0.153 in 2D; 0.220 in 3D (0.199 without the friction). At a/d0 = 20 it leads:
// 0.129.
TEST(DamBreak, Front2dCoarse) {
  const auto r =
      run_front("dambreak_2d.lua", "dambreak_2d_a10", "2D, a/d0 = 10", {{"d0", "0.0146"}});
  EXPECT_LT(r.rms, 0.19);
  EXPECT_EQ(r.wall_crossings, 0);
}

TEST(DamBreak, Front2dDefault) {
  const auto r = run_front("dambreak_2d.lua", "dambreak_2d_a20", "2D, a/d0 = 20", {});
  EXPECT_LT(r.rms, 0.25);
  EXPECT_GT(r.mean, 0.0);  // the front runs early, as in the other SPH codes
  // With Martin & Moyce's clock moved by the delay that fits best the surge matches their table
  // to 0.039 (0.129 without), the experiment setting out 9 ms after the run (docs/method.md, the
  // twenty-second session). The bound is half the undelayed error: the front's lead is a near
  // constant offset in time, not a surge growing apart from theirs.
  double delay = 0;
  const double delayed = delayed_front_rms(r.h5, &delay);
  std::printf("front RMS with the experiment's clock moved by %.1f ms: %.4f\n", 1e3 * delay,
              delayed);
  EXPECT_LT(delayed, 0.5 * r.rms);
  EXPECT_GT(delay, 0.0);
  io::RunFileReader run(r.h5);
  EXPECT_NEAR(run.double_attribute("error_front_after_delay"), delayed, 1e-9);
  // But the same experiment's residual height at the back wall does not take that offset: it
  // matches undelayed (0.036) and moving its clock by the front's delay makes it worse (0.052;
  // docs/method.md, the twenty-third session). Regression bound on the undelayed height with
  // the margin of the bounds above; both recomputed here and checked against the scene's scores.
  const double height = residual_height_rms(r.h5, 0.0);
  const double height_delayed = residual_height_rms(r.h5, delay);
  std::printf("residual height RMS %.4f; with the front's delay %.4f\n", height, height_delayed);
  EXPECT_NEAR(run.double_attribute("error_residual_height"), height, 1e-9);
  EXPECT_NEAR(run.double_attribute("error_residual_height_at_front_delay"), height_delayed, 1e-9);
  EXPECT_LT(height, 0.045);
  // The lead is made before T = 1.15 (the release); from there the surge runs at Martin &
  // Moyce's speed: at the default Courant number 0.3, 10.9 % slower at a/10, 3.3 % at a/20, 0.2 %
  // at a/40 (at 0.2: 2.1 % at a/20, 0.9 % at a/40, 0.4 % faster at a/80; docs/method.md, the
  // twenty-third and forty-fifth sessions). Bound: 5 % at a/20, 1.5 times the measured figure.
  const double speed = front_speed_error(r.h5);
  std::printf("surge speed for 1.15 <= T <= 3.15 against Martin & Moyce's: %+.2f %%\n",
              100 * speed);
  EXPECT_NEAR(run.double_attribute("error_front_speed"), std::abs(speed), 1e-9);
  EXPECT_LT(std::abs(speed), 0.05);
  // Near the surface only the wall's clearance (engine/fluid/ppe_source.cpp) holds a particle
  // off the floor, gently: one touching it and being put back is allowed (none did at a/20 with
  // the seventh session's defaults); a row of them would mean a leaking wall.
  EXPECT_LE(r.wall_crossings, 2);
  // At the default limits the density relaxation is alpha as given at every step, to the bit
  // (alpha_scaling = "per_time" only scales steps shorter than the default's).
  for (double a : run.read_doubles("/stats/alpha")) EXPECT_EQ(a, 0.05);
}

// With turbulence_at_walls = "wall_function" the wall's turbulent stress is the law of the
// wall's alone (engine/fluid/predictor.cpp): the defaults' eddy stress at the back wall, which at
// a/160 holds a layer of particles up as the column drains (residual height 0.174), is gone, and
// the shape measures converge (docs/method.md, the thirty-third session). At a/20: residual
// height 0.021 (defaults 0.033), delayed front 0.031 (0.039), surge speed +3.5 %; the undelayed
// front runs further ahead, 0.201 (0.129). Bounds with the margin of the bounds above.
TEST(DamBreak, WallFunctionAtTheWalls2d) {
  const auto r = run_front("dambreak_2d.lua", "dambreak_2d_a20_wall_function",
                           "2D, a/d0 = 20, turbulence_at_walls = wall_function",
                           {{"turbulence_at_walls", "wall_function"}});
  double delay = 0;
  const double delayed = delayed_front_rms(r.h5, &delay);
  const double height = residual_height_rms(r.h5, 0.0);
  const double speed = front_speed_error(r.h5);
  std::printf("after a delay of %.1f ms %.4f; residual height %.4f; surge speed %+.2f %%\n",
              1e3 * delay, delayed, height, 100 * speed);
  EXPECT_GT(r.mean, 0.0);
  EXPECT_LT(r.rms, 0.25);
  EXPECT_LT(delayed, 0.04);
  EXPECT_LT(height, 0.027);
  EXPECT_LT(std::abs(speed), 0.045);
  EXPECT_LE(r.wall_crossings, 2);
}

// alpha per unit time (engine/fluid/density_relaxation.hpp; docs/method.md, the thirty-fourth
// session). At a tenth of the default step (cfl 0.02, dt_max lifted as in the stability sweep)
// alpha = 0.05 taken per step relaxed the density error ten times faster in time, and the energy
// guard stopped this run at t = 0.208 s (docs/stability.md); the default alpha_scaling =
// "per_time" relaxes it at the default step's rate and the run completes (measured: front
// 0.065, surge speed -6.9 %, 2,852 steps). The front is slower than at the default step (0.129)
// because the per-step surface smoothing acts ten times as often (the eleventh session): bounds
// with the margin of the default's.
TEST(DamBreak, SmallStepsRelaxTheDensityAtTheDefaultRate) {
  const auto r = run_front("dambreak_2d.lua", "dambreak_2d_a20_cfl002", "2D, a/d0 = 20, cfl 0.02",
                           {{"cfl", "0.02"}, {"dt_max", "0.01"}});
  const double speed = front_speed_error(r.h5);
  std::printf("surge speed for 1.15 <= T <= 3.15 against Martin & Moyce's: %+.2f %%\n",
              100 * speed);
  EXPECT_LT(r.rms, 0.25);
  EXPECT_LT(std::abs(speed), 0.1);
  EXPECT_LE(r.wall_crossings, 2);
  // The alpha each step used (/stats/alpha): never above the given 0.05, and at every step the
  // Courant number set (/stats/dt_limit "cfl"), 0.05 dt / dt_default exactly, where dt_default is
  // the step the default limits take in the same state: cfl_default h / max|u|, i.e.
  // cfl_default / 0.02 times the run's step, or dt_max if that is shorter. At the default cfl 0.3
  // the surge at a/20 (below 2.6 m/s) never outruns dt_max, so dt_max is the reference there.
  // The first steps, from rest, are longer than the default's 1 ms cap and keep 0.05.
  io::RunFileReader run(r.h5);
  const auto alpha = run.read_doubles("/stats/alpha");
  const auto dt = run.read_doubles("/stats/dt");
  const auto limit = run.read_doubles("/stats/dt_limit");
  ASSERT_FALSE(alpha.empty());
  ASSERT_EQ(alpha.size(), dt.size());
  ASSERT_EQ(alpha.size(), limit.size());
  const SimulationParameters defaults;
  int advective_steps = 0;
  for (std::size_t k = 0; k < alpha.size(); ++k) {
    EXPECT_LE(alpha[k], 0.05);
    if (limit[k] != double(StepLimit::advective)) continue;
    ++advective_steps;
    const double dt_default = std::min(defaults.cfl / 0.02 * dt[k], defaults.dt_max);
    EXPECT_NEAR(alpha[k], 0.05 * std::min(1.0, dt[k] / dt_default), 1e-12) << "step " << k;
  }
  auto sorted = alpha;
  std::sort(sorted.begin(), sorted.end());
  std::printf("alpha per step: %.4g to %.4g, median %.6g; %d of %zu steps set by the cfl\n",
              sorted.front(), sorted.back(), sorted[sorted.size() / 2], advective_steps,
              alpha.size());
  EXPECT_GT(advective_steps, int(alpha.size()) / 2);
}

TEST(DamBreak, Front3dCoarse) {
  const auto r =
      run_front("dambreak_3d.lua", "dambreak_3d_a10", "3D, a/d0 = 10", {{"d0", "0.0146"}});
  EXPECT_LT(r.rms, 0.29);
}

// Potential flow of an instantaneous release at t = 0+ (Pohle 1952), written here from the
// series independently of scripts/validation.lua: a column 0 < x < a, 0 < z < H, P = 0 on the
// face x = a and the top, dP/dz = -rho g on the floor, dP/dx = 0 on the back wall:
//   P = rho g (H - z) - sum_{n odd} 8 rho g H / (n pi)^2 cosh(k x) / cosh(k a) cos(k z),
// k = n pi / 2H; the horizontal acceleration -dP/dx / rho follows term by term.
struct ReleaseField {
  double pressure, acceleration_x;
};
ReleaseField instant_release(double x, double z, double a, double H, double rho, double g) {
  ReleaseField f{rho * g * (H - z), 0.0};
  for (int n = 1; n <= 4001; n += 2) {
    const double k = n * M_PI / (2 * H);
    const double c = 8 * rho * g * H / (n * n * M_PI * M_PI);
    const double cosh_ratio = std::cosh(k * x) / std::cosh(k * a);
    const double sinh_ratio = std::sinh(k * x) / std::cosh(k * a);
    if (!std::isfinite(cosh_ratio) || c * cosh_ratio < 1e-13 * rho * g * H) break;
    f.pressure -= c * cosh_ratio * std::cos(k * z);
    f.acceleration_x += c * k * sinh_ratio * std::cos(k * z) / rho;
  }
  return f;
}

// The first frame of the dam break (t = 0.005 s, a few steps after the release) against the
// potential flow: the pressure solve must give the t = 0+ field, converging with d0. Measured
// at a/d0 = 10, 20, 40: pressure RMS 0.91 %, 0.34 %, 0.16 % of rho g H; face acceleration
// 7.2 %, 5.5 %, 3.7 %. Bounds: at a/20, twice the measured figure (a one-particle shift of the
// surface would give about 1 % and 15 %), and the error must fall from a/10 to a/20.
TEST(DamBreak, InstantReleaseMatchesPotentialFlow) {
  const double rho = 1000, g = 9.81, H = 2 * kColumn;
  double previous_pressure = 1e9, previous_acceleration = 1e9;
  for (const char* d0 : {"0.0146", "0.0073"}) {
    const auto out = testing::run_scene("dambreak_2d.lua", std::string("release_") + d0,
                                        {{"d0", d0}, {"end_time", "0.15"}});
    ASSERT_EQ(out.exit_code, 0);
    io::RunFileReader run(out.h5_path);
    const auto frame = run.read_frame(1);
    const double t = frame.time, spacing = std::stod(d0);
    double p2 = 0, a2 = 0, a_ref2 = 0;
    std::size_t fluid = 0;
    for (std::size_t i = 0; i < frame.count; ++i) {
      if (frame.kind[i] != 0) continue;
      const double x = frame.position[2 * i], z = frame.position[2 * i + 1];
      const auto exact = instant_release(x, z, kColumn, H, rho, g);
      p2 += std::pow(frame.pressure[i] - exact.pressure, 2), ++fluid;
      if (x > kColumn - spacing && z > 0.05 * H && z < 0.95 * H) {
        a2 += std::pow(frame.velocity[2 * i] - exact.acceleration_x * t, 2);
        a_ref2 += std::pow(exact.acceleration_x * t, 2);
      }
    }
    const double pressure_error = std::sqrt(p2 / fluid) / (rho * g * H);
    const double acceleration_error = std::sqrt(a2 / a_ref2);
    std::printf(
        "instant release, d0 = %s m, t = %.4f s: pressure RMS %.4f of rho g H, face "
        "acceleration %.4f (relative L2)\n",
        d0, t, pressure_error, acceleration_error);
    // The scene scores itself the same way (scripts/validation.lua).
    EXPECT_NEAR(run.double_attribute("error_release_pressure"), pressure_error, 1e-6);
    EXPECT_NEAR(run.double_attribute("error_release_acceleration"), acceleration_error, 1e-6);
    EXPECT_LT(pressure_error, previous_pressure);
    EXPECT_LT(acceleration_error, previous_acceleration);
    previous_pressure = pressure_error, previous_acceleration = acceleration_error;
  }
  EXPECT_LT(previous_pressure, 0.007);
  EXPECT_LT(previous_acceleration, 0.11);
}

// Z = x/a of the front probe at T = t sqrt(2g/a), interpolated between frames.
double front_at(const std::string& h5, double T_wanted) {
  io::RunFileReader run(h5);
  const auto t = run.read_doubles("/probes/front/time");
  const auto x = run.read_doubles("/probes/front/value");
  std::vector<double> T, Z;
  for (std::size_t k = 0; k < t.size(); ++k) {
    T.push_back(t[k] * std::sqrt(2 * 9.81 / kColumn));
    Z.push_back(x[k] / kColumn);
  }
  return testing::interpolate(T, Z, T_wanted);
}

// Z(T = 1.19) of the 2D dam break at spacing d0 with dt_max = 1 and 0.5 ms, the settings given
// on top of the defaults; each printed.
std::array<double, 2> front_at_two_steps(const std::string& label, const std::string& d0,
                                         const lua::Overrides& settings) {
  std::array<double, 2> Z{};
  int k = 0;
  for (const char* dt_max : {"0.001", "0.0005"}) {
    lua::Overrides all{{"d0", d0}, {"end_time", "0.27"}, {"dt_max", dt_max}};
    all.insert(all.end(), settings.begin(), settings.end());
    const auto out = testing::run_scene("dambreak_2d.lua", label + "_" + d0 + "_" + dt_max, all);
    EXPECT_EQ(out.exit_code, 0);
    Z[k] = front_at(out.h5_path, 1.19);
    std::printf("%s front, d0 = %s m, dt_max = %s s: Z(T = 1.19) = %.4f (table 1.44)\n",
                label.c_str(), d0.c_str(), dt_max, Z[k]);
    ++k;
  }
  return Z;
}

// The eleventh session's finding (docs/method.md): the surface velocity smoothing then acted
// per step, so the early front depended on the step (2D a/20, Z at T = 1.19: 1.581, 1.549, 1.475
// with dt_max = 1, 0.5, 0.25 ms). Without it (the ghost surface gradient holds the surface) the
// solution does not depend on the step: Z(1.19) = 1.664 and 1.662 at a/10, 1.705 and 1.705 at
// a/20, 1.704 and 1.699 at a/40, ahead of Martin & Moyce's 1.44 by the same amount at every
// resolution: the converged instantaneous release. Bounds: 0.01 between the two steps (measured
// 0.0014; the default's smoothing moves a/20 by 0.032 for the same halving, and a/10 to a/20
// moves it by 0.04), and a lead over the table of at least 0.15 (measured 0.22).
TEST(DamBreak, WithoutSmoothingTheFrontDoesNotDependOnTheStep) {
  const auto Z = front_at_two_steps("unsmoothed", "0.0146",
                                    {{"surface_gradient", "ghost"}, {"surface_smoothing", "0"}});
  for (double z : Z) EXPECT_GT(z, 1.44 + 0.15);
  EXPECT_NEAR(Z[0], Z[1], 0.01);
}

// The twelfth session's option (docs/method.md): the smoothing as a rate in the distance
// travelled (surface_smoothing_courant = 0.2) with the ghost surface gradient, and the front no
// longer depends on the step. Z at T = 1.19 with dt_max = 1 and 0.5 ms: 1.559 / 1.565 at a/10
// and 1.648 / 1.653 at a/20 (the per-step default moves them by 0.087 and 0.032). Bound: 0.02
// for the halving, three times the largest change measured and under the a/10 to a/20 step of
// 0.09; and still the lead the converged release has over Martin & Moyce's 1.44 (at least
// 0.08; measured 0.12 and 0.21).
TEST(DamBreak, WithTheRateSmoothingTheFrontDoesNotDependOnTheStep) {
  for (const char* d0 : {"0.0146", "0.0073"}) {
    const auto Z = front_at_two_steps(
        "rate-smoothed", d0, {{"surface_gradient", "ghost"}, {"surface_smoothing_courant", "0.2"}});
    for (double z : Z) EXPECT_GT(z, 1.44 + 0.08);
    EXPECT_NEAR(Z[0], Z[1], 0.02) << "d0 = " << d0;
  }
}

}  // namespace
}  // namespace washout
