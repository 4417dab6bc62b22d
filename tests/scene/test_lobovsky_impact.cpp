// The impact of Lobovsky et al.'s (2014) dam break (H = 0.3 m) on the downstream wall at
// sensor 1, 3 mm above the floor (scenes/validation/lobovsky_2d.lua). An incompressible model
// stops the arriving water within a step or two, so its pressure peak is that impulse divided
// by the step and changes with the step; the impulse itself, the integral of the pressure over
// the impact, is what the water gives a structure and what the experiment can be held to. This
// file recomputes the scene's `pressure_impulse` score independently (trapezoids over the probe's
// samples, the experiment's impact phase read off the median series) and checks that the
// impulse lies inside the experiment's 2.5-97.5 % band at two time steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/scene_runner.hpp"

namespace washout {
namespace {

constexpr double kHeight = 0.3, kGravity = 9.81, kRho = 1000.0;
constexpr double kOnset = 0.5;                        // p* that marks the impact's start
constexpr double kSearchFrom = 1.5, kSearchTo = 3.5;  // tau window of the first impact

struct Series {
  std::vector<double> tau, p;  // tau = t sqrt(g/H), p* = p / (rho g H)
};

// Where p first exceeds the onset level within the search window, between the two samples.
double onset_of(const Series& s) {
  for (std::size_t k = 1; k < s.tau.size(); ++k)
    if (s.tau[k] >= kSearchFrom && s.tau[k] <= kSearchTo && s.p[k] > kOnset)
      return s.tau[k - 1] +
             (s.tau[k] - s.tau[k - 1]) * (kOnset - s.p[k - 1]) / (s.p[k] - s.p[k - 1]);
  ADD_FAILURE() << "the series never exceeds p* = " << kOnset;
  return 0.0;
}

// The integral of p* d tau over [a, b]: trapezoids, the ends interpolated.
double integral(const Series& s, double a, double b) {
  double sum = 0.0;
  for (std::size_t k = 1; k < s.tau.size(); ++k) {
    const double lo = std::max(s.tau[k - 1], a), hi = std::min(s.tau[k], b);
    if (hi > lo)
      sum += 0.5 * (testing::interpolate(s.tau, s.p, lo) + testing::interpolate(s.tau, s.p, hi)) *
             (hi - lo);
  }
  return sum;
}

double impulse(const Series& s, double phase) {
  const double start = onset_of(s);
  return integral(s, start, start + phase);
}

Series measured(const std::string& column) {
  const auto csv = testing::read_csv(testing::refdata("lobovsky2014_H300_pressure_s1.csv"));
  Series s;
  for (std::size_t k = 0; k < csv.at("tau").size(); ++k) {
    s.tau.push_back(std::stod(csv.at("tau")[k]));
    s.p.push_back(std::stod(csv.at(column)[k]));
  }
  return s;
}

// The experiment's impact phase: from the median's onset until it has fallen to half its peak.
double impact_phase(const Series& median) {
  std::size_t peak = 0;
  for (std::size_t k = 0; k < median.tau.size() && median.tau[k] <= kSearchTo; ++k)
    if (median.p[k] > median.p[peak]) peak = k;
  for (std::size_t k = peak; k < median.tau.size(); ++k)
    if (median.p[k] < 0.5 * median.p[peak]) return median.tau[k] - onset_of(median);
  ADD_FAILURE() << "the median never falls to half its peak";
  return 0.0;
}

struct Impact {
  double impulse, peak, score;
  long steps;
};

Impact run_impact(const std::string& test_name, const lua::Overrides& overrides, double phase) {
  const auto out = testing::run_scene("validation/lobovsky_2d.lua", test_name, overrides);
  if (out.exit_code != 0) return {0, 0, 1e9, 0};
  io::RunFileReader run(out.h5_path);
  const auto t = run.read_doubles("/probes/sensor1/time");
  const auto p = run.read_doubles("/probes/sensor1/value");
  Series s;
  Impact r{0, 0, run.double_attribute("error_pressure_impulse"), out.summary.steps};
  for (std::size_t k = 0; k < t.size(); ++k) {
    s.tau.push_back(t[k] * std::sqrt(kGravity / kHeight));
    s.p.push_back(p[k] / (kRho * kGravity * kHeight));
    if (s.tau.back() >= kSearchFrom && s.tau.back() <= kSearchTo)
      r.peak = std::max(r.peak, s.p.back());
  }
  r.impulse = impulse(s, phase);
  return r;
}

TEST(LobovskyImpact, ImpulseInsideTheMeasuredBandWhateverTheStep) {
  const Series median = measured("s1_median");
  const double phase = impact_phase(median);
  const double reference = impulse(median, phase);
  const double low = impulse(measured("s1_p025"), phase);
  const double high = impulse(measured("s1_p975"), phase);
  std::printf("experiment: impact phase %.3f in tau, impulse %.3f (band %.3f-%.3f)\n", phase,
              reference, low, high);
  ASSERT_GT(phase, 0.2);  // the median's impact lasts about 0.37 in tau (64 ms)
  ASSERT_LT(low, reference);
  ASSERT_GT(high, reference);

  // d0 = H/30 at the default Courant number (0.3 since the forty-fifth session: 600 steps, dt_max
  // sets nearly all of them) and at 0.1. At the small step the impact is chaotic: the
  // solver's tolerance alone (1e-6 to 1e-9) or another solver moves the impulse over 0.61-0.71
  // (docs/method.md, the twenty-fourth session), where at the default step it converges with the
  // tolerance (at cfl 0.2: 0.621 at 1e-6, 0.629 from 1e-7). So the small step is a small ensemble:
  // the same run at three tolerances, each held to the band, their mean to the step's claim below.
  const Impact coarse_step = run_impact("lobovsky_impact_default_step", {{"d0", "0.01"}}, phase);
  std::vector<Impact> fine_steps;
  for (const char* tolerance : {"1e-6", "1e-7", "1e-8"})
    fine_steps.push_back(
        run_impact(std::string("lobovsky_impact_cfl01_tol") + tolerance,
                   {{"d0", "0.01"}, {"cfl", "0.1"}, {"solver_tolerance", tolerance}}, phase));
  double fine_mean = 0.0;
  std::vector<const Impact*> runs{&coarse_step};
  for (const Impact& r : fine_steps) {
    runs.push_back(&r);
    fine_mean += r.impulse / double(fine_steps.size());
  }
  for (const Impact* r : runs) {
    const double edge = r->impulse >= reference ? high : low;
    const double fraction = (r->impulse - reference) / (edge - reference);
    std::printf(
        "%ld steps: impulse %.3f (%+.1f %% of the median, %.2f of the band's half-width), "
        "peak p* %.2f (median peak 2.65)\n",
        r->steps, r->impulse, 100 * (r->impulse / reference - 1), fraction, r->peak);
    EXPECT_NEAR(r->score, fraction, 1e-6);  // the scene's own score is the same number
    EXPECT_LT(fraction, 1.0);               // inside the experiment's band
  }
  // The step moves the impulse less than the experiment's repeats scatter: half the width of
  // the band (0.117, 17 % of the median). With alpha per unit time (docs/method.md, the
  // thirty-fourth session) the cfl 0.1 runs agree (0.717-0.738) and sat 0.104 above the default
  // step's 0.626 while the default was 0.2 (alpha at half the rate); with the default at 0.3 (alpha
  // at a third) 0.663-0.683 against 0.672, their mean +0.3 % (forty-fifth session); single runs at
  // a quarter and an eighth of the 0.2 step gave 0.701 and 0.577 (with alpha per step 0.709 at the
  // half step, 0.541 at the quarter): the impact's impulse scatters with the step over about the
  // band's width, around the median.
  std::printf("cfl 0.1, mean of the three: impulse %.3f (%+.1f %% from the default step's)\n",
              fine_mean, 100 * (fine_mean / coarse_step.impulse - 1));
  EXPECT_LT(std::abs(fine_mean - coarse_step.impulse), 0.5 * (high - low));
}

}  // namespace
}  // namespace washout
