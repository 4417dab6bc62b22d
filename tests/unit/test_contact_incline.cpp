// A block on an incline (refdata README section 6): with tan(theta) > mu it slides with
// a = g (sin theta - mu cos theta); with tan(theta) < mu it stays put. The incline is a tilted
// plane (smooth signed distance, no lattice bumps) and the block starts on it, at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "engine/contact/contact_substepper.hpp"
#include "engine/rigid/lattice_body.hpp"

namespace washout::contact {
namespace {

using rigid::BodyModel;
using rigid::BodyState;

constexpr double kG = 9.81;

struct Slide {
  double acceleration = 0.0;   // fitted, down the slope [m/s^2]
  double creep = 0.0;          // largest distance along the slope moved after 0.1 s [m]
  double static_spring = 0.0;  // M g sin(theta) / (N k_s): the tangential springs' stretch [m]
  double rotation = 0.0;       // largest rotation from the start [rad]
};

// A 0.1 x 0.05 x 0.02 m box (d0 = 5 mm; 2D: 0.1 x 0.02) on a plane tilted by theta; E = 1e6 Pa
// (1e8 Pa in 2D, where the mass per metre is 20 times larger, so that the contact settles in
// ~3 ms in both) keeps the test fast (the law does not depend on it). Duration 0.3 s, fluid steps
// of 1 ms. The acceleration is the least-squares quadratic fit of the distance along the slope
// after 20 ms (the initial settling of the normal contact).
Slide incline(int dim, double theta_degrees, double mu, int steps = 300) {
  const double theta = theta_degrees * std::numbers::pi / 180.0;
  const Vec3 size(0.1, dim == 3 ? 0.05 : 0.02, dim == 3 ? 0.02 : 0.0);
  BodyModel model =
      rigid::make_body_model(rigid::lattice_box(dim, 0.005, -0.5 * size, 0.5 * size, 1161.0));
  const Vec3 up = dim == 3 ? Vec3::UnitZ() : Vec3::UnitY();
  // Tilt about the horizontal axis across the slope; the slope rises towards +x.
  const Vec3 across = dim == 3 ? Vec3::UnitY() : Vec3::UnitZ();
  const double sign = dim == 3 ? -1.0 : 1.0;  // so that the plane normal leans towards -x
  const Eigen::Quaterniond tilt(Eigen::AngleAxisd(sign * theta, across));
  const Vec3 normal = tilt * up;
  const Vec3 downhill = -(tilt * Vec3::UnitX());

  ContactScene scene;
  const int pla = scene.materials.add({"pla", dim == 3 ? 1e6 : 1e8, 0.28, 0.8});
  scene.materials.set_friction(pla, pla, mu);
  scene.walls.push_back({"incline", PlaneWall{Vec3::Zero(), normal}, pla});
  model.material = pla;

  std::vector<BodyModel> models{model};
  std::vector<BodyState> states{rigid::initial_state(model)};
  states[0].orientation = tilt;
  states[0].position = 0.5 * size.dot(up) * normal;  // bottom face on the plane
  const Vec3 start = states[0].position;
  std::vector<rigid::BodyLoad> fluid(1);
  ContactWorkspace workspace;

  Slide result;
  double settled = 0.0;
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, y0 = 0, y1 = 0, y2 = 0;
  const double dt = 1e-3;
  int touching = 0;
  for (int n = 0; n < steps; ++n) {
    const SubstepReport report =
        advance_bodies(models, states, fluid, scene, workspace, -kG * up, n * dt, dt);
    touching = std::max(touching, report.most_touching);
    const double t = (n + 1) * dt;
    const double s = (states[0].position - start).dot(downhill);
    result.rotation = std::max(result.rotation, states[0].orientation.angularDistance(tilt));
    if (t < 0.1)
      settled = s;
    else
      result.creep = std::max(result.creep, std::abs(s - settled));
    if (t < 0.02) continue;
    s0 += 1;
    s1 += t;
    s2 += t * t;
    s3 += t * t * t;
    s4 += t * t * t * t;
    y0 += s;
    y1 += s * t;
    y2 += s * t * t;
  }
  Eigen::Matrix3d normal_matrix;
  normal_matrix << s0, s1, s2, s1, s2, s3, s2, s3, s4;
  const Vec3 coefficients = normal_matrix.ldlt().solve(Vec3(y0, y1, y2));
  result.acceleration = 2.0 * coefficients[2];
  result.static_spring =
      model.mass * kG * std::sin(theta) / (touching * workspace.wall_law[0].tangential_stiffness);
  return result;
}

// Sliding: the normal force sums to M g cos(theta) and the slider gives exactly mu times it,
// so only the settling transient and rounding remain: tolerance 0.5 % of a (measured ~1e-4).
TEST(ContactIncline, SlidesWithCoulombAcceleration) {
  for (int dim : {3, 2}) {
    for (const auto& [theta, mu] :
         {std::pair{30.0, 0.2}, std::pair{30.0, 0.0}, std::pair{20.0, 0.05}}) {
      const Slide s = incline(dim, theta, mu);
      const double th = theta * std::numbers::pi / 180.0;
      const double exact = kG * (std::sin(th) - mu * std::cos(th));
      std::printf(
          "%dD, theta %.0f deg, mu %.2f: a = %.5f m/s^2, analytic %.5f, error %+.2e, "
          "rotation %.1e rad\n",
          dim, theta, mu, s.acceleration, exact, s.acceleration / exact - 1, s.rotation);
      EXPECT_NEAR(s.acceleration / exact, 1.0, 5e-3);
      EXPECT_LT(s.rotation, 1e-3);  // it slides flat, without tipping
    }
  }
}

// Sticking (tan theta < mu). The block starts unloaded: it slips for the ~0.5 ms it takes the
// normal force to build up, then its tangential springs hold it with a stretch of
// M g sin(theta)/(N k_s). After 0.1 s (the contact's transients decay within ~3 ms) it must not
// creep along the slope by more than 1 % of that stretch, over 0.2 s and over 0.9 s (sliding at
// even 1e-3 m/s^2 would cover 20 um in 0.2 s).
TEST(ContactIncline, SticksBelowTheFrictionAngle) {
  for (int dim : {3, 2}) {
    const Slide s = incline(dim, 10.0, 0.3);
    const Slide longer = incline(dim, 10.0, 0.3, 1000);
    EXPECT_LT(longer.creep, 0.01 * s.static_spring);
    std::printf(
        "%dD, theta 10 deg, mu 0.30 (tan theta = %.3f): creep after settling %.2e m "
        "(over 0.9 s: %.2e m), spring stretch %.2e m, fitted a = %.1e m/s^2\n",
        dim, std::tan(10.0 * std::numbers::pi / 180.0), s.creep, longer.creep, s.static_spring,
        s.acceleration);
    EXPECT_LT(s.creep, 0.01 * s.static_spring);
  }
}

}  // namespace
}  // namespace washout::contact
