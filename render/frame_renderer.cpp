#include "render/frame_renderer.hpp"

#define GL_GLEXT_PROTOTYPES
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "render/camera.hpp"
#include "render/camera_fit.hpp"
#include "render/color_map.hpp"
#include "render/downsample.hpp"
#include "render/gl_api.hpp"
#include "render/occlusion_culling.hpp"
#include "render/osmesa_context.hpp"
#include "render/overlay.hpp"
#include "render/palette.hpp"
#include "render/scene_bounds.hpp"
#include "render/sphere_impostor_pass.hpp"
#include "render/wall_cutaway.hpp"

namespace washout::render {
namespace {

constexpr int kMinSize = 16;  // tiny frames are allowed; they only lose the overlay
constexpr int kMaxSize = 8192;

void validate(const RenderOptions& o) {
  if (o.width < kMinSize || o.height < kMinSize || o.width > kMaxSize || o.height > kMaxSize) {
    throw RenderError("frame size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                      " is outside " + std::to_string(kMinSize) + ".." + std::to_string(kMaxSize) +
                      " pixels");
  }
  if (o.supersample < 1 || o.supersample > 4) {
    throw RenderError("supersample must be 1, 2, 3 or 4, not " + std::to_string(o.supersample));
  }
  if (static_cast<long long>(o.width) * o.supersample > kMaxSize ||
      static_cast<long long>(o.height) * o.supersample > kMaxSize) {
    throw RenderError("frame size times supersample exceeds " + std::to_string(kMaxSize) +
                      " pixels; lower --supersample or the size");
  }
  if (o.fixed_range && !(o.range_max > o.range_min)) {
    throw RenderError("colour range maximum must be greater than its minimum");
  }
  parse_color_field(o.color_field);
  validate_camera_spec(o.camera);
}

Rgb8 kind_color(std::uint8_t kind) {
  switch (static_cast<ParticleKind>(kind)) {
    case ParticleKind::FixedWall:
    case ParticleKind::MovingWall:
      return kWallColor;
    case ParticleKind::RigidBody:
      return kRigidBodyColor;
    default:
      return kWallColor;  // an unknown kind is drawn like a wall, not like fluid
  }
}

}  // namespace

struct FrameRenderer::State {
  RenderOptions options;
  ColorField field = ColorField::Speed;
  FrameLayout layout;
  std::optional<Camera> camera;
  WallCutaway cutaway;                     // chosen with the camera
  std::optional<ValueRange> locked_range;  // auto range, once a frame showed a spread
  std::optional<ValueRange> last_range;
  std::unique_ptr<OsmesaContext> context;
  std::unique_ptr<SphereImpostorPass> spheres;  // destroyed before the context
  std::vector<SphereInstance> instances;
  OcclusionCuller culler;

  ~State() {
    // The shader objects belong to this context: free them while it is current.
    if (!context) return;
    try {
      context->make_current();
      spheres.reset();
    } catch (const ContextError&) {
      spheres.release();  // the context goes away with its objects anyway
    }
  }

  ValueRange range_for(const ParticleView& view) {
    if (options.fixed_range) return {options.range_min, options.range_max};
    if (locked_range) return *locked_range;
    const ValueRange r = fluid_range(view, field);
    if (!r.degenerate()) {
      locked_range = r;
      return r;
    }
    // Nothing moves yet (e.g. the initial state): show the value at the low end, keep waiting.
    return {r.min, r.min + 1.0};
  }

  void build_instances(const ParticleView& view, const ValueRange& range) {
    const Eigen::Vector3d origin = camera->origin();
    instances.resize(view.count);
    const auto n = static_cast<long long>(view.count);
    long long left_out = 0;
#pragma omp parallel for schedule(static) reduction(+ : left_out)
    for (long long k = 0; k < n; ++k) {
      const auto i = static_cast<std::size_t>(k);
      SphereInstance& s = instances[i];
      Eigen::Vector3d p = Eigen::Vector3d::Zero();
      for (int axis = 0; axis < view.dim; ++axis) p[axis] = view.position(i, axis);
      for (int axis = 0; axis < 3; ++axis)
        s.center[axis] = static_cast<float>(p[axis] - origin[axis]);
      const std::uint8_t kind = view.kind ? view.kind[i] : 0;
      const bool fluid = kind == static_cast<std::uint8_t>(ParticleKind::Fluid);
      const Rgb8 c = fluid ? color_map(normalized(range, color_field_value(view, i, field)))
                           : kind_color(kind);
      // A diverged particle (NaN or inf position) is left out rather than drawn anywhere.
      const bool wall = kind == static_cast<std::uint8_t>(ParticleKind::FixedWall) ||
                        kind == static_cast<std::uint8_t>(ParticleKind::MovingWall);
      const bool retired = kind == static_cast<std::uint8_t>(ParticleKind::Retired);
      const bool drawn = p.allFinite() && !retired && !(wall && cutaway.hides(p));
      s.color[0] = c.r;
      s.color[1] = c.g;
      s.color[2] = c.b;
      s.color[3] = drawn ? 255 : 0;
      left_out += drawn ? 0 : 1;
    }
    if (left_out > 0) {
      std::erase_if(instances, [](const SphereInstance& s) { return s.color[3] == 0; });
    }
  }

  void ensure_context() {
    if (context) {
      context->make_current();
      return;
    }
    const int s = options.supersample;
    context = std::make_unique<OsmesaContext>(options.width * s, options.height * s);
    spheres = std::make_unique<SphereImpostorPass>();
  }

  void draw(double radius) {
    ensure_context();
    const int s = options.supersample;
    const PixelRect& plot = layout.plot;
    gl().glViewport(plot.x * s, (options.height - plot.y - plot.height) * s, plot.width * s,
                    plot.height * s);
    gl().glClearColor(kBackgroundColor.r / 255.0f, kBackgroundColor.g / 255.0f,
                      kBackgroundColor.b / 255.0f, 1.0f);
    gl().glClearDepth(1.0);
    gl().glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl().glEnable(GL_DEPTH_TEST);
    gl().glDepthFunc(GL_LESS);
    spheres->draw(instances, *camera, radius);
    gl().glFinish();
  }
};

FrameRenderer::FrameRenderer(RenderOptions options) : state_(std::make_unique<State>()) {
  validate(options);
  state_->options = std::move(options);
  state_->field = parse_color_field(state_->options.color_field);
  state_->layout = FrameLayout::for_image(state_->options.width, state_->options.height);
}

FrameRenderer::~FrameRenderer() = default;
FrameRenderer::FrameRenderer(FrameRenderer&&) noexcept = default;
FrameRenderer& FrameRenderer::operator=(FrameRenderer&&) noexcept = default;

Image FrameRenderer::render(const ParticleView& view) {
  State& st = *state_;
  if (view.count == 0) throw RenderError("cannot render an empty frame (it has no particles)");
  if (view.dim != 2 && view.dim != 3) {
    throw RenderError("cannot render a frame of dimension " + std::to_string(view.dim));
  }
  if (!view.position.component[0] || !view.position.component[1] ||
      (view.dim == 3 && !view.position.component[2])) {
    throw RenderError("cannot render a frame without particle positions");
  }
  if (st.field == ColorField::Pressure && !view.pressure) {
    throw RenderError("cannot colour by pressure: the frame has no pressure data");
  }
  const double radius = particle_radius(view);
  if (!st.camera) {
    const double aspect =
        static_cast<double>(st.layout.plot.width) / static_cast<double>(st.layout.plot.height);
    st.camera = fit_camera(st.options.camera, view.dim, particle_bounds(view, radius), aspect);
    if (st.options.cutaway_walls && view.dim == 3) {
      st.cutaway = WallCutaway(*st.camera, fluid_bounds(view, 0.0), radius);
    }
  }
  const ValueRange range = st.range_for(view);
  st.last_range = range;
  st.build_instances(view, range);
  if (st.options.occlusion_culling && view.dim == 3) {  // in a plane nothing hides
    st.culler.cull(st.instances, *st.camera, radius, st.layout.plot.width, st.layout.plot.height);
  }
  st.draw(radius);
  Image image = downsample_rgba(st.context->rgba(), st.options.width, st.options.height,
                                st.options.supersample);
  draw_color_bar(image, st.layout, range, color_field_title(st.field));
  draw_time_label(image, st.layout, view.time);
  return image;
}

void FrameRenderer::render_png(const ParticleView& view, const std::string& path) {
  render(view).write_png(path);
}

std::optional<std::array<double, 2>> FrameRenderer::project_to_pixel(double x, double y,
                                                                     double z) const {
  const State& st = *state_;
  if (!st.camera) return std::nullopt;
  const auto ndc = st.camera->to_ndc(Eigen::Vector3d(x, y, z));
  if (!ndc) return std::nullopt;
  const PixelRect& plot = st.layout.plot;
  return std::array<double, 2>{plot.x + 0.5 * (ndc->x() + 1.0) * plot.width,
                               plot.y + 0.5 * (1.0 - ndc->y()) * plot.height};
}

const RenderOptions& FrameRenderer::options() const { return state_->options; }
const FrameLayout& FrameRenderer::layout() const { return state_->layout; }
std::optional<ValueRange> FrameRenderer::color_range() const { return state_->last_range; }
std::size_t FrameRenderer::drawn_spheres() const { return state_->instances.size(); }

}  // namespace washout::render
