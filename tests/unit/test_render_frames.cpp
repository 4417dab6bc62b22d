// Renders small known scenes offscreen and checks the pixels: background, fluid colour from the
// colour map, walls grey, rigid bodies magenta, the colour bar's ends, the time label, a fixed
// camera and colour range across frames, identical bytes for identical input, and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/bitmap_font.hpp"
#include "render/color_map.hpp"
#include "render/frame_renderer.hpp"
#include "render/overlay.hpp"
#include "render/palette.hpp"
#include "render/sphere_shading.hpp"

namespace washout::render {
namespace {

// Particle arrays owned by the test, viewed like the engine's structure of arrays.
struct SyntheticFrame {
  int dim = 2;
  double d0 = 0.01;
  double time = 0.25;
  std::vector<double> x, y, z, vx, vy, vz, pressure;
  std::vector<std::uint8_t> kind;
  std::vector<std::int32_t> body;

  std::size_t add(ParticleKind k, double px, double py, double pz = 0.0, double ux = 0.0,
                  double uy = 0.0, double uz = 0.0, double p = 0.0) {
    x.push_back(px);
    y.push_back(py);
    z.push_back(pz);
    vx.push_back(ux);
    vy.push_back(uy);
    vz.push_back(uz);
    pressure.push_back(p);
    kind.push_back(static_cast<std::uint8_t>(k));
    body.push_back(k == ParticleKind::RigidBody ? 0 : -1);
    return x.size() - 1;
  }

  ParticleView view() const {
    ParticleView v;
    v.dim = dim;
    v.count = x.size();
    v.time = time;
    v.d0 = d0;
    v.position.component[0] = x.data();
    v.position.component[1] = y.data();
    v.position.component[2] = dim == 3 ? z.data() : nullptr;
    v.velocity.component[0] = vx.data();
    v.velocity.component[1] = vy.data();
    v.velocity.component[2] = dim == 3 ? vz.data() : nullptr;
    v.pressure = pressure.data();
    v.kind = kind.data();
    v.body = body.data();
    return v;
  }
};

// A 2D tank: a 20x10 fluid block whose horizontal speed grows with x (0 .. 1.9 m/s), a
// two-row floor of walls and a 4x4 rigid body to the right of the water.
SyntheticFrame tank_2d() {
  SyntheticFrame f;
  const double d = f.d0;
  for (int i = 0; i < 20; ++i) {
    for (int j = 0; j < 10; ++j) {
      f.add(ParticleKind::Fluid, (i + 0.5) * d, (j + 0.5) * d, 0.0, i * 0.1, 0.0, 0.0,
            1000.0 * 9.81 * (10 - j) * d);
    }
  }
  for (int i = -5; i < 35; ++i) {
    for (int j = 1; j <= 2; ++j) f.add(ParticleKind::FixedWall, (i + 0.5) * d, -(j - 0.5) * d);
  }
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) f.add(ParticleKind::RigidBody, 0.25 + i * d, 0.05 + j * d);
  }
  return f;
}

// A 3D tank (gravity along -z): a 10x6x8 fluid block whose vertical velocity grows with x,
// a one-layer floor of walls and a 3x3x3 rigid cube downstream of the water.
SyntheticFrame tank_3d() {
  SyntheticFrame f;
  f.dim = 3;
  f.d0 = 0.02;
  const double d = f.d0;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 6; ++j) {
      for (int k = 0; k < 8; ++k) {
        f.add(ParticleKind::Fluid, (i + 0.5) * d, (j + 0.5) * d, (k + 0.5) * d, 0.0, 0.0,
              -0.5 + 0.1 * i);
      }
    }
  }
  for (int i = -2; i < 20; ++i) {
    for (int j = -2; j < 8; ++j)
      f.add(ParticleKind::FixedWall, (i + 0.5) * d, (j + 0.5) * d, -0.5 * d);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) {
        f.add(ParticleKind::RigidBody, 0.28 + i * d, 0.04 + j * d, 0.03 + k * d);
      }
    }
  }
  return f;
}

RenderOptions small_options() {
  RenderOptions o;
  o.width = 640;
  o.height = 360;
  return o;
}

int channel_distance(Rgb8 a, Rgb8 b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

std::string describe(Rgb8 c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

// The colour where a world point lands (the renderer must have drawn a frame already),
// interpolated bilinearly between the four nearest pixel centres so that the sub-pixel
// position of a sphere's centre does not shift its lighting.
Rgb8 pixel_at(const FrameRenderer& renderer, const Image& image, double x, double y,
              double z = 0.0) {
  const auto p = renderer.project_to_pixel(x, y, z);
  EXPECT_TRUE(p.has_value());
  if (!p) return {};
  const double fx = (*p)[0] - 0.5, fy = (*p)[1] - 0.5;
  const int i = static_cast<int>(std::floor(fx)), j = static_cast<int>(std::floor(fy));
  EXPECT_TRUE(image.contains(i, j) && image.contains(i + 1, j + 1))
      << "projected to " << (*p)[0] << ", " << (*p)[1];
  if (!image.contains(i, j) || !image.contains(i + 1, j + 1)) return {};
  const double wx = fx - i, wy = fy - j;
  auto channel = [&](std::uint8_t Rgb8::*c) {
    const double top = (1 - wx) * (image.pixel(i, j).*c) + wx * (image.pixel(i + 1, j).*c);
    const double bottom =
        (1 - wx) * (image.pixel(i, j + 1).*c) + wx * (image.pixel(i + 1, j + 1).*c);
    return static_cast<std::uint8_t>(std::lround((1 - wy) * top + wy * bottom));
  };
  return {channel(&Rgb8::r), channel(&Rgb8::g), channel(&Rgb8::b)};
}

std::string output_path(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(WASHOUT_TEST_OUTPUT_DIR) / "render";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

// Speed-coloured pixel expected at the front of a fluid sphere: the map colour of its value,
// lit as the shader lights a sphere's centre.
Rgb8 expected_fluid(double value, const ValueRange& range) {
  return shade_sphere_center(color_map(normalized(range, value)));
}

// Supersampling averages the lighting over a pixel, and the highlight varies fast near the centre.
constexpr int kShadingTolerance = 10;

TEST(RenderFrames, TwoDimensionalTankHasTheExpectedPixels) {
  const SyntheticFrame frame = tank_2d();
  FrameRenderer renderer(small_options());
  const Image image = renderer.render(frame.view());
  image.write_png(output_path("tank_2d.png"));
  ASSERT_EQ(image.width(), 640);
  ASSERT_EQ(image.height(), 360);

  const auto range = renderer.color_range();
  ASSERT_TRUE(range.has_value());
  std::printf("2D speed range: [%g, %g]\n", range->min, range->max);
  EXPECT_NEAR(range->min, 0.0, 1e-12);
  EXPECT_NEAR(range->max, 1.9, 1e-12);

  // Empty space between the water and the body, above the floor.
  const Rgb8 empty = pixel_at(renderer, image, 0.225, 0.03);
  std::printf("background at (0.225, 0.03): %s\n", describe(empty).c_str());
  EXPECT_EQ(empty, kBackgroundColor);

  // Slowest and fastest fluid columns (i = 0 and i = 19, row j = 5).
  for (const int i : {0, 10, 19}) {
    const double speed = i * 0.1;
    const Rgb8 seen = pixel_at(renderer, image, (i + 0.5) * frame.d0, 5.5 * frame.d0);
    const Rgb8 want = expected_fluid(speed, *range);
    std::printf("fluid speed %.1f: pixel %s, expected %s\n", speed, describe(seen).c_str(),
                describe(want).c_str());
    EXPECT_LE(channel_distance(seen, want), kShadingTolerance);
  }

  const Rgb8 wall = pixel_at(renderer, image, 0.305, -0.005);
  std::printf("wall pixel %s, expected %s\n", describe(wall).c_str(),
              describe(shade_sphere_center(kWallColor)).c_str());
  EXPECT_LE(channel_distance(wall, shade_sphere_center(kWallColor)), kShadingTolerance);
  EXPECT_LE(std::abs(wall.r - wall.g) + std::abs(wall.g - wall.b), 2) << "walls are grey";

  const Rgb8 body = pixel_at(renderer, image, 0.26, 0.06);
  std::printf("rigid body pixel %s, expected %s\n", describe(body).c_str(),
              describe(shade_sphere_center(kRigidBodyColor)).c_str());
  EXPECT_LE(channel_distance(body, shade_sphere_center(kRigidBodyColor)), kShadingTolerance);
}

TEST(RenderFrames, ColorBarEndsAreTheColorMapEnds) {
  const SyntheticFrame frame = tank_2d();
  FrameRenderer renderer(small_options());
  const Image image = renderer.render(frame.view());
  const PixelRect bar = renderer.layout().color_bar;
  ASSERT_GT(bar.height, 10);
  const int x = bar.x + bar.width / 2;
  const Rgb8 top = image.pixel(x, bar.y), bottom = image.pixel(x, bar.y + bar.height - 1);
  std::printf("colour bar at x=%d: top %s (map high %s), bottom %s (map low %s)\n", x,
              describe(top).c_str(), describe(color_map_high()).c_str(), describe(bottom).c_str(),
              describe(color_map_low()).c_str());
  EXPECT_EQ(top, color_map_high());
  EXPECT_EQ(bottom, color_map_low());
}

TEST(RenderFrames, TimeLabelIsDrawnInTheTopStrip) {
  SyntheticFrame frame = tank_2d();
  frame.time = 0.25;
  FrameRenderer renderer(small_options());
  const Image image = renderer.render(frame.view());
  const FrameLayout& layout = renderer.layout();
  const std::string label = format_time_label(frame.time);
  EXPECT_EQ(label, "t = 0.250 s");
  // Draw the same label on an empty frame; the rendered top-left corner must match it exactly.
  Image expected(layout.width, layout.height, kBackgroundColor);
  draw_text(expected, layout.margin, layout.margin, label, kTextColor, layout.font_scale);
  int ink = 0, mismatches = 0;
  for (int j = 0; j < layout.plot.y; ++j) {
    for (int i = 0; i < layout.margin + text_width(label, layout.font_scale); ++i) {
      ink += expected.pixel(i, j) == kTextColor;
      mismatches += !(image.pixel(i, j) == expected.pixel(i, j));
    }
  }
  std::printf("time label: %d ink pixels, %d mismatches\n", ink, mismatches);
  EXPECT_GT(ink, 50);
  EXPECT_EQ(mismatches, 0);
}

TEST(RenderFrames, SameInputGivesIdenticalBytes) {
  const SyntheticFrame frame = tank_2d();
  FrameRenderer first(small_options()), second(small_options());
  const Image a = first.render(frame.view());
  const Image b = second.render(frame.view());
  const Image c = first.render(frame.view());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.bytes().size(); ++i) differing += a.bytes()[i] != b.bytes()[i];
  std::printf("bytes differing between two renderers: %zu of %zu\n", differing, a.bytes().size());
  EXPECT_EQ(differing, 0u);
  EXPECT_TRUE(a.bytes() == c.bytes());
}

TEST(RenderFrames, CameraAndAutoRangeStayFixedAcrossFrames) {
  SyntheticFrame frame = tank_2d();
  for (double& u : frame.vx) u = 0.0;  // at rest: the speed shows no spread yet
  FrameRenderer renderer(small_options());
  renderer.render(frame.view());
  const auto at_rest = renderer.color_range();
  const auto anchor = renderer.project_to_pixel(0.1, 0.05);
  ASSERT_TRUE(at_rest && anchor);
  std::printf("range at rest: [%g, %g]\n", at_rest->min, at_rest->max);
  EXPECT_EQ(at_rest->min, 0.0);

  SyntheticFrame moving = tank_2d();  // speeds 0 .. 1.9: this range is kept from now on
  renderer.render(moving.view());
  SyntheticFrame faster = tank_2d();
  for (double& u : faster.vx) u *= 2.0;
  for (double& x : faster.x) x += 0.05;  // moved particles must not move the camera
  renderer.render(faster.view());
  const auto kept = renderer.color_range();
  const auto anchor_after = renderer.project_to_pixel(0.1, 0.05);
  std::printf("range after three frames: [%g, %g]; anchor pixel (%.2f, %.2f) -> (%.2f, %.2f)\n",
              kept->min, kept->max, (*anchor)[0], (*anchor)[1], (*anchor_after)[0],
              (*anchor_after)[1]);
  EXPECT_NEAR(kept->max, 1.9, 1e-12);
  EXPECT_EQ((*anchor)[0], (*anchor_after)[0]);
  EXPECT_EQ((*anchor)[1], (*anchor_after)[1]);
}

TEST(RenderFrames, FixedRangeColoursByTheGivenRange) {
  const SyntheticFrame frame = tank_2d();
  RenderOptions options = small_options();
  options.color_field = "pressure";
  options.fixed_range = true;
  options.range_min = 0.0;
  options.range_max = 2000.0;
  FrameRenderer renderer(options);
  const Image image = renderer.render(frame.view());
  const ValueRange range{0.0, 2000.0};
  // Bottom fluid row (j = 0) has pressure 981 Pa, about the middle of the fixed range.
  const Rgb8 seen = pixel_at(renderer, image, 0.105, 0.005);
  const Rgb8 want = expected_fluid(981.0, range);
  std::printf("pressure 981 Pa in [0, 2000]: pixel %s, expected %s\n", describe(seen).c_str(),
              describe(want).c_str());
  EXPECT_LE(channel_distance(seen, want), kShadingTolerance);
}

TEST(RenderFrames, ThreeDimensionalSideViewHasTheExpectedPixels) {
  const SyntheticFrame frame = tank_3d();
  RenderOptions options = small_options();
  options.color_field = "vertical_velocity";
  options.camera.preset = "side";
  FrameRenderer renderer(options);
  const Image image = renderer.render(frame.view());
  image.write_png(output_path("tank_3d_side.png"));
  const auto range = renderer.color_range();
  ASSERT_TRUE(range.has_value());
  std::printf("3D vertical velocity range: [%g, %g]\n", range->min, range->max);
  EXPECT_NEAR(range->min, -0.5, 1e-12);
  EXPECT_NEAR(range->max, 0.4, 1e-12);

  const double d = frame.d0;
  // Front face (j = 0, nearest the camera on the -y side) of the fluid: columns i = 0 and 9.
  for (const int i : {0, 9}) {
    const double w = -0.5 + 0.1 * i;
    const Rgb8 seen = pixel_at(renderer, image, (i + 0.5) * d, 0.5 * d, 4.5 * d);
    const Rgb8 want = expected_fluid(w, *range);
    std::printf("fluid w %.1f: pixel %s, expected %s\n", w, describe(seen).c_str(),
                describe(want).c_str());
    EXPECT_LE(channel_distance(seen, want), kShadingTolerance);
  }
  const Rgb8 body = pixel_at(renderer, image, 0.30, 0.04, 0.05);
  std::printf("rigid body pixel %s\n", describe(body).c_str());
  EXPECT_LE(channel_distance(body, shade_sphere_center(kRigidBodyColor)), kShadingTolerance);
  const Rgb8 wall = pixel_at(renderer, image, 0.37, -0.03, -0.01);
  std::printf("floor pixel %s\n", describe(wall).c_str());
  EXPECT_LE(channel_distance(wall, shade_sphere_center(kWallColor)), kShadingTolerance);
  const Rgb8 empty = pixel_at(renderer, image, 0.33, 0.0, 0.15);  // above the body
  std::printf("background above the water %s\n", describe(empty).c_str());
  EXPECT_EQ(empty, kBackgroundColor);
}

// A flume's near side wall stands between a side camera and the water: it is cut away,
// unless the options keep every wall.
TEST(RenderFrames, NearSideWallIsCutAway) {
  SyntheticFrame frame = tank_3d();
  const double d = frame.d0;
  for (int i = -2; i < 20; ++i) {
    for (int k = 0; k < 10; ++k) {
      frame.add(ParticleKind::FixedWall, (i + 0.5) * d, -0.5 * d, (k + 0.5) * d);
    }
  }
  RenderOptions options = small_options();
  options.camera.preset = "side";
  options.color_field = "vertical_velocity";
  FrameRenderer cut(options);
  options.cutaway_walls = false;
  FrameRenderer kept(options);
  const Image with_cutaway = cut.render(frame.view());
  const Image without = kept.render(frame.view());
  const auto range = cut.color_range();
  const Rgb8 water = pixel_at(cut, with_cutaway, 9.5 * d, 0.5 * d, 4.5 * d);
  const Rgb8 wall = pixel_at(kept, without, 9.5 * d, 0.5 * d, 4.5 * d);
  std::printf("behind the near wall: %s with the cutaway, %s without\n", describe(water).c_str(),
              describe(wall).c_str());
  EXPECT_LE(channel_distance(water, expected_fluid(0.4, *range)), kShadingTolerance);
  EXPECT_LE(channel_distance(wall, shade_sphere_center(kWallColor)), kShadingTolerance);
}

TEST(RenderFrames, ThreeDimensionalPerspectiveShowsWaterBodyAndFloor) {
  const SyntheticFrame frame = tank_3d();
  FrameRenderer renderer(small_options());  // 3D default: the perspective 3/4 view
  const Image image = renderer.render(frame.view());
  image.write_png(output_path("tank_3d_perspective.png"));
  const double d = frame.d0;
  // The rigid cube's corner nearest the camera (-x, -y, +z side) faces the viewer.
  const Rgb8 body = pixel_at(renderer, image, 0.28, 0.04, 0.07);
  // The top front fluid particle of the first column (|w| = 0.5, the fastest) is in full view.
  const Rgb8 water = pixel_at(renderer, image, 0.5 * d, 0.5 * d, 7.5 * d);
  const Rgb8 corner = image.pixel(renderer.layout().plot.x + 2, renderer.layout().plot.y + 2);
  std::printf("perspective: body %s, fastest water %s, plot corner %s\n", describe(body).c_str(),
              describe(water).c_str(), describe(corner).c_str());
  EXPECT_LE(channel_distance(body, shade_sphere_center(kRigidBodyColor)), 40);
  EXPECT_LE(channel_distance(water, shade_sphere_center(color_map_high())), 40);
  EXPECT_EQ(corner, kBackgroundColor);
  // Every point of the scene's box lands inside the drawing area.
  const PixelRect plot = renderer.layout().plot;
  for (const double x : {-0.05, 0.4}) {
    for (const double y : {-0.05, 0.16}) {
      for (const double z : {-0.02, 0.17}) {
        const auto p = renderer.project_to_pixel(x, y, z);
        ASSERT_TRUE(p.has_value());
        EXPECT_GE((*p)[0], plot.x);
        EXPECT_LE((*p)[0], plot.x + plot.width);
        EXPECT_GE((*p)[1], plot.y);
        EXPECT_LE((*p)[1], plot.y + plot.height);
      }
    }
  }
}

// Hidden spheres are left out before drawing; the picture must not change. A jittered block
// (no two spheres at exactly the same depth) is drawn with and without the culling.
TEST(RenderFrames, OcclusionCullingDoesNotChangeThePicture) {
  SyntheticFrame frame;
  frame.dim = 3;
  frame.d0 = 0.02;
  std::uint64_t state = 7;
  auto jitter = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return 0.004 * (static_cast<double>(state >> 11) / 9007199254740992.0 - 0.5);
  };
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 12; ++j) {
      for (int k = 0; k < 12; ++k) {
        frame.add(ParticleKind::Fluid, 0.02 * i + jitter(), 0.02 * j + jitter(),
                  0.02 * k + jitter(), 0.1 * k, 0.0, 0.05 * i);
      }
    }
  }
  for (const char* preset : {"perspective", "side", "top"}) {
    RenderOptions options = small_options();
    options.camera.preset = preset;
    FrameRenderer culled(options);
    options.occlusion_culling = false;
    FrameRenderer everything(options);
    const Image a = culled.render(frame.view());
    const Image b = everything.render(frame.view());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.bytes().size(); ++i) differing += a.bytes()[i] != b.bytes()[i];
    std::printf("%s: %zu of %zu spheres drawn after culling; %zu bytes differ\n", preset,
                culled.drawn_spheres(), everything.drawn_spheres(), differing);
    EXPECT_LT(culled.drawn_spheres(), everything.drawn_spheres());
    EXPECT_EQ(differing, 0u);
  }
}

TEST(RenderFrames, TopViewSeesTheWaterSurface) {
  const SyntheticFrame frame = tank_3d();
  RenderOptions options = small_options();
  options.camera.preset = "top";
  options.color_field = "vertical_velocity";
  FrameRenderer renderer(options);
  const Image image = renderer.render(frame.view());
  const double d = frame.d0;
  const auto range = renderer.color_range();
  const Rgb8 seen = pixel_at(renderer, image, 9.5 * d, 2.5 * d, 7.5 * d);
  const Rgb8 want = expected_fluid(0.4, *range);
  std::printf("top view, fastest column: pixel %s, expected %s\n", describe(seen).c_str(),
              describe(want).c_str());
  EXPECT_LE(channel_distance(seen, want), kShadingTolerance);
}

TEST(RenderFrames, ExplicitCameraLooksWhereItIsTold) {
  const SyntheticFrame frame = tank_3d();
  RenderOptions options = small_options();
  options.camera.explicit_pose = true;
  const double position[3] = {0.1, -1.0, 0.08}, target[3] = {0.1, 0.06, 0.08};
  std::copy(position, position + 3, options.camera.position);
  std::copy(target, target + 3, options.camera.target);
  options.camera.fov_deg = 30.0;
  FrameRenderer renderer(options);
  renderer.render(frame.view());
  const auto p = renderer.project_to_pixel(target[0], target[1], target[2]);
  const PixelRect plot = renderer.layout().plot;
  std::printf("target projects to (%.2f, %.2f); plot centre (%.2f, %.2f)\n", (*p)[0], (*p)[1],
              plot.x + 0.5 * plot.width, plot.y + 0.5 * plot.height);
  EXPECT_NEAR((*p)[0], plot.x + 0.5 * plot.width, 1e-6);
  EXPECT_NEAR((*p)[1], plot.y + 0.5 * plot.height, 1e-6);
}

// A camera region frames that box instead of every particle: a zoom. The 2D tank's left half
// (0 .. 0.1 m, the water's slower half) fills the drawing; its centre projects to the centre of
// the plot, the region's corners lie inside it, and the body at x = 0.25 m is off the image.
TEST(RenderFrames, CameraRegionZoomsTheView) {
  const SyntheticFrame frame = tank_2d();
  RenderOptions options = small_options();
  options.camera.region_components = 2;
  const double lo[2] = {0.0, 0.0}, hi[2] = {0.1, 0.1};
  std::copy(lo, lo + 2, options.camera.region_min);
  std::copy(hi, hi + 2, options.camera.region_max);
  FrameRenderer renderer(options);
  const Image image = renderer.render(frame.view());
  image.write_png(output_path("tank_2d_region.png"));
  const PixelRect plot = renderer.layout().plot;
  const auto centre = renderer.project_to_pixel(0.05, 0.05);
  std::printf("region centre projects to (%.2f, %.2f); plot centre (%.2f, %.2f)\n", (*centre)[0],
              (*centre)[1], plot.x + 0.5 * plot.width, plot.y + 0.5 * plot.height);
  EXPECT_NEAR((*centre)[0], plot.x + 0.5 * plot.width, 1e-6);
  EXPECT_NEAR((*centre)[1], plot.y + 0.5 * plot.height, 1e-6);
  // The region's height fills the plot's height less the fitting margin (kFill = 0.94).
  const auto top = renderer.project_to_pixel(0.05, 0.1),
             bottom = renderer.project_to_pixel(0.05, 0.0);
  const double filled = ((*bottom)[1] - (*top)[1]) / plot.height;
  std::printf("region height fills %.3f of the plot's height\n", filled);
  EXPECT_NEAR(filled, 0.94, 0.01);
  const auto body = renderer.project_to_pixel(0.26, 0.06);
  EXPECT_GT((*body)[0], plot.x + plot.width) << "the body lies outside the zoomed view";
  // Fluid inside the region keeps its colour: column i = 4 (0.4 m/s).
  const auto range = renderer.color_range();
  const Rgb8 seen = pixel_at(renderer, image, 4.5 * frame.d0, 5.5 * frame.d0);
  EXPECT_LE(channel_distance(seen, expected_fluid(0.4, *range)), kShadingTolerance);

  RenderOptions empty = small_options();
  empty.camera.region_components = 2;
  empty.camera.region_max[0] = 1.0;  // max y = min y = 0
  EXPECT_THROW(FrameRenderer{empty}, RenderError);
  RenderOptions wrong_dim = options;
  wrong_dim.camera.region_components = 3;
  wrong_dim.camera.region_max[2] = 1.0;
  FrameRenderer three_components(wrong_dim);
  EXPECT_THROW(three_components.render(frame.view()), RenderError);
}

TEST(RenderFrames, BadInputIsReported) {
  RenderOptions unknown = small_options();
  unknown.color_field = "vorticity";
  try {
    FrameRenderer renderer(unknown);
    FAIL() << "an unknown colour field was accepted";
  } catch (const RenderError& e) {
    std::printf("unknown field: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("vorticity"), std::string::npos);
  }
  RenderOptions preset = small_options();
  preset.camera.preset = "fisheye";
  EXPECT_THROW(FrameRenderer{preset}, RenderError);
  RenderOptions range = small_options();
  range.fixed_range = true;
  range.range_min = range.range_max = 1.0;
  EXPECT_THROW(FrameRenderer{range}, RenderError);

  FrameRenderer renderer(small_options());
  const SyntheticFrame empty;
  try {
    renderer.render(empty.view());
    FAIL() << "an empty view was rendered";
  } catch (const RenderError& e) {
    std::printf("empty view: %s\n", e.what());
  }

  const SyntheticFrame frame = tank_2d();
  try {
    renderer.render_png(frame.view(), "/nonexistent-washout-dir/frame.png");
    FAIL() << "an unwritable path was accepted";
  } catch (const ImageWriteError& e) {
    std::printf("unwritable path: %s\n", e.what());
    EXPECT_NE(std::string(e.what()).find("/nonexistent-washout-dir/frame.png"), std::string::npos);
  }

  RenderOptions by_pressure = small_options();
  by_pressure.color_field = "pressure";
  FrameRenderer pressure_renderer(by_pressure);
  ParticleView no_pressure = frame.view();
  no_pressure.pressure = nullptr;
  EXPECT_THROW(pressure_renderer.render(no_pressure), RenderError);
}

}  // namespace
}  // namespace washout::render
