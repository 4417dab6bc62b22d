// The Lua side of rigid bodies (docs/bodies.md): washout.body / material / friction / contact and
// the `material` key of walls build the model; mistakes are refused with the scene's file and
// line; /bodies/NAME and /stats/substeps are written; callbacks read state.bodies; prescribed
// motion is followed; a scene without bodies builds none of it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include "engine/cli/run_command.hpp"
#include "engine/io/run_file_reader.hpp"
#include "engine/lua/lua_scene.hpp"
#include "engine/sim/rigid_body_system.hpp"

namespace washout {
namespace {

namespace fs = std::filesystem;

fs::path scene_dir() {
  const fs::path dir = fs::path(WASHOUT_TEST_OUTPUT_DIR) / "body_scene_api";
  fs::create_directories(dir);
  return dir;
}

std::FILE* quiet_log() {
  static std::FILE* sink = std::fopen("/dev/null", "w");
  return sink;
}

std::string write_scene(const std::string& name, const std::string& text) {
  const fs::path path = scene_dir() / (name + ".lua");
  std::ofstream(path) << text;
  return path.string();
}

// A small 2D tank (0.2 x 0.1 m of water, d0 = 1 cm) and whatever the test adds.
const char* kTank = R"(local tank = require("tank")
local P = washout.parameters { dim = 2, d0 = 0.01, end_time = 0.01, output_interval = 0.005 }
washout.fluid { washout.box { min = { 0, 0 }, max = { 0.2, 0.1 } } }
)";

std::string scene_error(const std::string& text) {
  const std::string path = write_scene("bad", kTank + text);
  try {
    lua::LuaScene scene(path, {});
    Simulation sim(scene.model());
  } catch (const SceneError& e) {
    return std::string(e.where()) + " | " + e.what();
  }
  return "";
}

TEST(BodySceneApi, BuildsBodiesMaterialsAndFriction) {
  const std::string path = write_scene("build", std::string(kTank) + R"(
local glass = washout.material { name = "glass", E = 7e10, nu = 0.22, eps = 0.9 }
local pla = washout.material { name = "pla", E = 5e9, nu = 0.28, eps = 0.8 }
washout.friction { "pla", "glass", 0.05 }
washout.friction { pla, pla, mu = 0.3, eps = 0.5 }
washout.contact { law = "linear", steps_per_contact = 25 }
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.2, 0.2 } }), name = "tank",
               material = glass }
washout.body { washout.box { min = { 0.05, 0.08 }, max = { 0.09, 0.12 } }, name = "a",
               density = 500, material = pla }
washout.body { washout.box { min = { 0.11, 0.08 }, max = { 0.15, 0.10 } }, name = "b",
               mass = 0.2, material = "pla", motion = "fixed" }
)");
  lua::LuaScene scene(path, {});
  const Simulation sim(scene.model());
  const RigidBodySystem* bodies = sim.bodies();
  ASSERT_NE(bodies, nullptr);
  ASSERT_EQ(bodies->size(), 2u);
  EXPECT_EQ(bodies->name(0), "a");
  EXPECT_NEAR(bodies->model(0).mass, 500 * 0.04 * 0.04, 1e-12);
  EXPECT_NEAR(bodies->model(1).mass, 0.2, 1e-12);
  EXPECT_EQ(bodies->model(1).motion, rigid::MotionKind::kFixed);
  const contact::ContactScene& contact = bodies->contact_scene();
  const int g = contact.materials.find("glass"), p = contact.materials.find("pla");
  EXPECT_DOUBLE_EQ(contact.materials.friction(p, g), 0.05);
  EXPECT_DOUBLE_EQ(contact.materials.friction(p, p), 0.3);
  EXPECT_DOUBLE_EQ(contact.materials.restitution(p, p), 0.5);
  EXPECT_DOUBLE_EQ(contact.materials.restitution(p, g), std::sqrt(0.8 * 0.9));
  EXPECT_DOUBLE_EQ(contact.settings.steps_per_contact, 25.0);
  ASSERT_EQ(contact.walls.size(), 1u);
  EXPECT_EQ(contact.walls[0].material, g);
  EXPECT_EQ(bodies->model(0).material, p);
  // Fluid was cleared from the bodies: no fluid particle inside either of them.
  for (std::size_t i = 0; i < sim.particles().fluid_count; ++i)
    for (std::size_t b = 0; b < 2; ++b) EXPECT_FALSE(bodies->contains(b, sim.particles().x(i)));
}

// Each mistake names the scene line (the script's line numbers: kTank has 3 lines).
TEST(BodySceneApi, MistakesNameTheSceneLine) {
  const std::string box = "washout.box { min = { 0.05, 0.05 }, max = { 0.09, 0.09 } }";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"washout.body { " + box + ", density = 500, densty = 3 }",
       "bad.lua:4: washout.body: unknown key 'densty' (did you mean 'density'?)"},
      {"washout.body { " + box + " }", "bad.lua:4: washout.body 'body_0': give a positive"},
      {"washout.body { " + box + ", density = 500, mass = 1 }", "not both"},
      {"washout.body { " + box + ", density = 500, material = \"steel\" }",
       "bad.lua:4: washout.body 'body_0': unknown material 'steel'"},
      {"washout.body { " + box + ", density = 500, motion = \"floating\" }",
       "motion must be \"dynamic\", \"fixed\" or a function of time"},
      {"washout.body { " + box + ", density = 500, name = \"a/b\" }", "without '/'"},
      {"washout.body { " + box + ", density = 500, name = \"x\" }\nwashout.body { " + box +
           ", density = 500, name = \"x\" }",
       "bad.lua:5: washout.body: a body named 'x' exists already"},
      {"washout.friction { \"pla\", \"default\", 0.1 }", "unknown material 'pla'"},
      {"washout.material { name = \"m\", nu = 0.7 }", "nu must lie in [0, 0.5)"},
      {"washout.contact { law = \"soft\" }", "law must be \"linear\" or \"hertz\""},
      {"washout.wall { " + box + ", material = \"glass\" }", "unknown material 'glass'"},
      // Overlaps are found when the particles are built, and name the body's line.
      {"washout.wall { washout.box { min = { 0, 0.06 }, max = { 0.2, 0.07 } }, name = \"shelf\" }"
       "\nwashout.body { " +
           box + ", density = 500, name = \"cube\" }",
       "bad.lua:5 | body 'cube' overlaps wall 'shelf'"},
      {"washout.body { " + box +
           ", density = 500, name = \"one\" }\nwashout.body { "
           "washout.box { min = { 0.08, 0.05 }, max = { 0.12, 0.09 } }, density = 500, name = "
           "\"two\" }",
       "body 'one' overlaps body 'two'"},
  };
  for (const Case& c : cases) {
    const std::string message = scene_error(c.text);
    std::printf("%s\n", message.c_str());
    EXPECT_NE(message.find(c.expected), std::string::npos)
        << "scene: " << c.text << "\nmessage: " << message;
  }
}

// /bodies/NAME: one row per step with the documented columns and attributes; /stats/substeps
// counts the contact sub-steps (1 per step when nothing touches). A callback reads the body's
// state and stops the run.
TEST(BodySceneApi, WritesBodySeriesAndFeedsCallbacks) {
  const std::string path = write_scene("series", std::string(kTank) + R"(
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.2, 0.2 } }), name = "tank" }
washout.body { washout.box { min = { 0.06, 0.12 }, max = { 0.14, 0.16 } }, name = "lid",
               density = 800, angular_velocity = 0.5 }
seen = 0
washout.on_step(function(state)
  local b = state.bodies.lid
  assert(#b.position == 2 and #b.velocity == 2 and #b.quaternion == 4)
  assert(type(b.angle) == "number" and type(b.angular_velocity) == "number")
  seen = seen + 1
  if seen == 7 then washout.stop("seen seven steps, lid at y = " .. b.position[2]) end
end)
)");
  cli::RunRequest request;
  request.scene_path = path;
  request.out_dir = (scene_dir() / "series_out").string();
  request.log = quiet_log();
  request.render_frames = false;
  const cli::RunOutcome outcome = cli::run_scene(request);
  ASSERT_EQ(outcome.exit_code, cli::kSuccess) << outcome.error;
  EXPECT_EQ(outcome.summary.status, RunStatus::StoppedByScene);
  EXPECT_NE(outcome.summary.message.find("seen seven steps"), std::string::npos);
  io::RunFileReader file(outcome.h5_path);
  ASSERT_TRUE(file.has("/bodies/lid"));
  const std::size_t rows = 7;
  EXPECT_EQ(file.shape("/bodies/lid/time"), (std::vector<std::size_t>{rows}));
  for (const char* name : {"position", "velocity", "omega", "force_fluid", "force_contact",
                           "torque_fluid", "torque_contact"})
    EXPECT_EQ(file.shape(std::string("/bodies/lid/") + name), (std::vector<std::size_t>{rows, 3}))
        << name;
  EXPECT_EQ(file.shape("/bodies/lid/quaternion"), (std::vector<std::size_t>{rows, 4}));
  EXPECT_EQ(file.shape("/bodies/lid/angle"), (std::vector<std::size_t>{rows}));
  EXPECT_EQ(file.shape("/stats/substeps"), (std::vector<std::size_t>{rows}));
  for (double s : file.read_doubles("/stats/substeps")) EXPECT_EQ(s, 1.0);
  // The body turns at 0.5 rad/s about z: the angle follows, the quaternion stays a z rotation.
  const auto time = file.read_doubles("/bodies/lid/time");
  const auto angle = file.read_doubles("/bodies/lid/angle");
  const auto q = file.read_doubles("/bodies/lid/quaternion");
  const auto x = file.read_doubles("/bodies/lid/position");
  EXPECT_NEAR(angle.back(), 2.0 * std::atan2(q[4 * rows - 1], q[4 * rows - 4]), 1e-12);
  EXPECT_NEAR(angle.back(), 0.5 * time.back(), 0.02 * 0.5 * time.back());
  EXPECT_EQ(x[3 * rows - 1], 0.0);  // z = 0 in 2D
}

// A prescribed body follows its function: displacement and angle, at every step.
TEST(BodySceneApi, PrescribedMotionIsFollowed) {
  const std::string path = write_scene("prescribed", std::string(kTank) + R"(
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.2, 0.2 } }), name = "tank" }
washout.body { washout.box { min = { 0.06, 0.12 }, max = { 0.14, 0.16 } }, name = "paddle",
               density = 800,
               motion = function(t) return { 0.1 * t, -0.2 * t * t }, 3.0 * t end }
)");
  cli::RunRequest request;
  request.scene_path = path;
  request.out_dir = (scene_dir() / "prescribed_out").string();
  request.log = quiet_log();
  request.render_frames = false;
  const cli::RunOutcome outcome = cli::run_scene(request);
  ASSERT_EQ(outcome.exit_code, cli::kSuccess) << outcome.error;
  io::RunFileReader file(outcome.h5_path);
  const auto time = file.read_doubles("/bodies/paddle/time");
  const auto x = file.read_doubles("/bodies/paddle/position");
  const auto v = file.read_doubles("/bodies/paddle/velocity");
  const auto angle = file.read_doubles("/bodies/paddle/angle");
  const auto omega = file.read_doubles("/bodies/paddle/omega");
  ASSERT_GT(time.size(), 5u);
  for (std::size_t r = 0; r < time.size(); ++r) {
    const double t = time[r];
    EXPECT_NEAR(x[3 * r], 0.1 + 0.1 * t, 1e-12);
    EXPECT_NEAR(x[3 * r + 1], 0.14 - 0.2 * t * t, 1e-12);
    EXPECT_NEAR(angle[r], 3.0 * t, 1e-12);
    EXPECT_NEAR(v[3 * r + 1], -0.4 * t, 1e-6);  // central differences over 2e-6 s
    EXPECT_NEAR(omega[3 * r + 2], 3.0, 1e-6);
  }
}

// The first example of docs/bodies.md is a whole scene: it runs (briefly) and writes its body.
TEST(BodySceneApi, DocumentationExampleRuns) {
  std::ifstream doc(fs::path(WASHOUT_SOURCE_DIR) / "docs" / "bodies.md");
  ASSERT_TRUE(doc) << "docs/bodies.md not found";
  std::stringstream text;
  text << doc.rdbuf();
  const std::string all = text.str();
  const std::size_t begin = all.find("```lua\n");
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = all.find("```", begin + 7);
  const std::string path = write_scene("doc_example", all.substr(begin + 7, end - begin - 7));
  cli::RunRequest request;
  request.scene_path = path;
  request.out_dir = (scene_dir() / "doc_example_out").string();
  request.overrides = {{"end_time", "0.02"}};
  request.log = quiet_log();
  request.render_frames = false;
  const cli::RunOutcome outcome = cli::run_scene(request);
  ASSERT_EQ(outcome.exit_code, cli::kSuccess) << outcome.error;
  io::RunFileReader file(outcome.h5_path);
  EXPECT_TRUE(file.has("/bodies/block/position"));
}

TEST(BodySceneApi, SceneWithoutBodiesBuildsNone) {
  const std::string path = write_scene("plain", std::string(kTank) + R"(
washout.wall { tank.open_box(P, { min = { 0, 0 }, max = { 0.2, 0.2 } }), name = "tank" }
)");
  cli::RunRequest request;
  request.scene_path = path;
  request.out_dir = (scene_dir() / "plain_out").string();
  request.log = quiet_log();
  request.render_frames = false;
  const cli::RunOutcome outcome = cli::run_scene(request);
  ASSERT_EQ(outcome.exit_code, cli::kSuccess) << outcome.error;
  io::RunFileReader file(outcome.h5_path);
  EXPECT_FALSE(file.has("/bodies"));
  for (double s : file.read_doubles("/stats/substeps")) EXPECT_EQ(s, 0.0);
  for (const auto& [stage, seconds] : outcome.summary.stage_seconds)
    EXPECT_TRUE(stage != "bodies" && stage != "body_loads") << stage;
}

}  // namespace
}  // namespace washout
