// Window-averaged loads and landing impulses (engine/cli/landing_load.hpp, the body report's
// landing figures; docs/stability.md "Landing loads"), on series whose answers are known in
// closed form: a load stopped in one step has a raw peak growing as 1/dt but a window mean and
// an impulse that do not depend on dt, and the report's impulses balance the body's momentum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/cli/body_report.hpp"
#include "engine/cli/landing_load.hpp"

namespace washout {
namespace {

// Rows of a uniform series: row k covers (k dt, (k + 1) dt].
std::vector<double> uniform_times(double dt, double end) {
  std::vector<double> t;
  const int n = static_cast<int>(std::lround(end / dt));
  for (int k = 0; k < n; ++k) t.push_back((k + 1) * dt);
  return t;
}

// A background load F0 and an impulse J delivered in the single step that starts at 0.2 s:
// the window mean of any window holding that step is F0 + J / T whatever dt is, the raw
// one-step load F0 + J / dt; and the integral over [0.19, 0.21] s is 0.02 F0 + J.
TEST(LandingLoad, APulseStoppedInOneStepHasADtFreeWindowMean) {
  const double f0 = 3.0, impulse = 2.0, window = 0.01;
  for (double dt : {0.00025, 0.0005, 0.001}) {
    const std::vector<double> time = uniform_times(dt, 0.5);
    std::vector<double> load(time.size(), f0);
    const std::size_t pulse = std::lround(0.2 / dt);
    load[pulse] += impulse / dt;
    const std::vector<double> bounds = cli::step_bounds(time);
    const cli::WindowedPeak peak = cli::windowed_peak(bounds, load, 1, 0, window);
    const double integral = cli::load_integral(bounds, load, 1, 0, 0.19, 0.21);
    std::printf(
        "dt %.2e s: raw peak %.2f N, windowed peak %.6f N at %.4f s (expected %.6f N), "
        "integral %.9f N s (expected %.9f)\n",
        dt, load[pulse], peak.value, peak.time, f0 + impulse / window, integral,
        0.02 * f0 + impulse);
    EXPECT_NEAR(peak.value, f0 + impulse / window, 1e-9 * (f0 + impulse / window));
    // The window holds the pulse step: its centre is within half a window of the pulse.
    EXPECT_LE(std::abs(peak.time - 0.2), 0.5 * window + dt);
    EXPECT_NEAR(integral, 0.02 * f0 + impulse, 1e-12);
  }
}

// Irregular steps (as an adaptive run takes) under a load rising with time, each row holding
// its step's mean a t: the mean over a window can only grow as the window slides later, so the
// peak is the last window's, [end - T, end], whose mean is summed here directly from the
// overlap of each step with it.
TEST(LandingLoad, TheWindowMeanIsExactOnIrregularSteps) {
  const double a = 40.0, window = 0.01;
  std::vector<double> time;
  double t = 0.0;
  for (int k = 0; t < 0.3; ++k) {
    t += 0.0003 + 0.0007 * (0.5 + 0.5 * std::sin(1.7 * k));  // 0.3 to 1 ms
    time.push_back(t);
  }
  const std::vector<double> bounds = cli::step_bounds(time);
  std::vector<double> load(time.size());
  for (std::size_t k = 0; k < time.size(); ++k) load[k] = a * 0.5 * (bounds[k] + bounds[k + 1]);
  const double end = bounds.back(), start = end - window;
  double expected = 0.0;
  for (std::size_t k = 0; k < load.size(); ++k)
    expected += load[k] * std::max(0.0, bounds[k + 1] - std::max(bounds[k], start)) / window;
  const cli::WindowedPeak peak = cli::windowed_peak(bounds, load, 1, 0, window);
  std::printf("%zu rows: windowed peak %.12f N at %.6f s (expected %.12f N at %.6f s)\n",
              time.size(), peak.value, peak.time, expected, end - 0.5 * window);
  EXPECT_NEAR(peak.value, expected, 1e-9);
  EXPECT_NEAR(peak.time, end - 0.5 * window, 1e-12);
}

// A 2D body (y up, g = 10 m/s^2, M = 2 kg/m, buoyancy 5 N/m) sinks from rest, reaches
// v_L = -(g - F_b / M) 0.1 s = -0.75 m/s at t = 0.1 s and lands: in one step the floor stops it
// and the water it carries (added mass m_a = 1 kg/m), so the fluid pushes it down by
// m_a |v_L| / dt and the contact holds (M + m_a) |v_L| / dt, as in the sinking box
// (docs/stability.md). Whatever dt, the report must give: the landing at 0.1 s + dt, the
// landing velocity -0.75 m/s, the fluid impulse F_b D - m_a |v_L| over the landing duration D,
// the windowed vertical peak F_b - m_a |v_L| / T over the load window T, and impulses that
// balance the momentum: J_fluid + J_contact - W D = M (v_after - v_L).
TEST(LandingLoad, TheReportGivesTheLandingsImpulseAndABoundedPeak) {
  const double mass = 2.0, g = 10.0, buoyancy = 5.0, added = 1.0, t_land = 0.1;
  const double weight = mass * g, v_land = -(g - buoyancy / mass) * t_land;
  double raw_coarse = 0, raw_fine = 0;
  for (double dt : {0.00025, 0.0005, 0.001}) {
    cli::BodyTrack track;
    track.name = "box";
    track.dim = 2;
    track.mass = mass;
    track.time = uniform_times(dt, 0.3);
    const std::size_t landing = std::lround(t_land / dt);  // the step from 0.1 s
    for (std::size_t k = 0; k < track.rows(); ++k) {
      double fluid = buoyancy, contact = 0.0, v = v_land * (k + 1) * dt / t_land;
      if (k == landing) {
        fluid -= added * std::abs(v_land) / dt;
        contact = (mass + added) * std::abs(v_land) / dt + weight - buoyancy;
        v = 0.0;
      } else if (k > landing) {
        contact = weight - buoyancy;
        v = 0.0;
      }
      track.position.insert(track.position.end(), {0.0, 0.5, 0.0});
      track.angle.push_back(0.0);
      track.force_fluid.insert(track.force_fluid.end(), {0.0, fluid, 0.0});
      track.force_contact.insert(track.force_contact.end(), {0.0, contact, 0.0});
      track.velocity.insert(track.velocity.end(), {0.0, v, 0.0});
    }
    const cli::BodyReportSettings settings;  // load_window 0.01 s, landing_duration 0.05 s
    const double window = settings.load_window, duration = settings.landing_duration;
    const cli::BodySummary s = cli::summarize_body(track, Vec3(0, -g, 0), settings);
    const double j_fluid = buoyancy * duration - added * std::abs(v_land);
    const double balance = s.landing_impulse_fluid[1] + s.landing_impulse_contact[1] -
                           weight * duration - mass * (0.0 - s.landing_velocity[1]);
    std::printf(
        "dt %.2e s: landing %.5f s, v %.4f m/s, J_fluid %.6f N s/m (expected %.6f), momentum "
        "balance residual %.2e N s/m, raw one-step peak %.1f W, windowed %.4f W (expected "
        "%.4f W)\n",
        dt, s.landing_time, s.landing_velocity[1], s.landing_impulse_fluid[1], j_fluid, balance,
        s.peak_force_vertical_one_step / weight, s.peak_force_vertical_windowed / weight,
        (buoyancy - added * std::abs(v_land) / window) / weight);
    EXPECT_NEAR(s.landing_time, t_land + dt, 1e-12);
    EXPECT_NEAR(s.landing_velocity[1], v_land, 1e-12);
    EXPECT_NEAR(s.landing_impulse_fluid[1], j_fluid, 1e-9);
    EXPECT_NEAR(balance, 0.0, 1e-9);
    EXPECT_NEAR(s.peak_force_vertical_windowed, buoyancy - added * std::abs(v_land) / window, 1e-9);
    EXPECT_NEAR(s.peak_force_vertical_one_step, buoyancy - added * std::abs(v_land) / dt, 1e-9);
    EXPECT_EQ(s.load_spikes, 1);  // the one-step load is still flagged as a spike
    if (dt == 0.00025) raw_fine = s.peak_force_vertical_one_step;
    if (dt == 0.001) raw_coarse = s.peak_force_vertical_one_step;
  }
  // The raw peak grows as 1/dt: four times the step, about a quarter of the peak.
  std::printf("raw one-step peak at dt = 0.25 ms / at 1 ms: %.3f\n", raw_fine / raw_coarse);
  EXPECT_NEAR(raw_fine / raw_coarse, 4.0, 0.05);
}

// A body that never touches anything has no landing; one resting from the start lands only
// after it has been free for release_hold.
TEST(LandingLoad, NoLandingWithoutAFreeStretchFirst) {
  const std::vector<double> time = uniform_times(0.001, 0.2);
  const std::vector<double> bounds = cli::step_bounds(time);
  std::vector<double> contact(time.size(), 0.0);
  EXPECT_EQ(cli::first_landing(bounds, contact, 0.1, 0.05), time.size());
  for (std::size_t k = 0; k < 50; ++k) contact[k] = 1.0;     // on its support for 0.05 s
  for (std::size_t k = 80; k < 90; ++k) contact[k] = 1.0;    // a touch after 0.03 s free: no
  for (std::size_t k = 150; k < 200; ++k) contact[k] = 1.0;  // after 0.06 s free: landing
  EXPECT_EQ(cli::first_landing(bounds, contact, 0.1, 0.05), 150u);
}

}  // namespace
}  // namespace washout
