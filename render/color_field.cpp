#include "render/color_field.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "render/render_error.hpp"

namespace washout::render {

ColorField parse_color_field(const std::string& name) {
  if (name == "speed") return ColorField::Speed;
  if (name == "pressure") return ColorField::Pressure;
  if (name == "vertical_velocity") return ColorField::VerticalVelocity;
  throw RenderError("unknown colour field '" + name +
                    "' (choose speed, pressure or vertical_velocity)");
}

std::string color_field_name(ColorField field) {
  switch (field) {
    case ColorField::Speed:
      return "speed";
    case ColorField::Pressure:
      return "pressure";
    case ColorField::VerticalVelocity:
      return "vertical_velocity";
  }
  return "speed";
}

std::string color_field_title(ColorField field) {
  switch (field) {
    case ColorField::Speed:
      return "speed [m/s]";
    case ColorField::Pressure:
      return "pressure [Pa]";
    case ColorField::VerticalVelocity:
      return "vertical velocity [m/s]";
  }
  return "";
}

double color_field_value(const ParticleView& view, std::size_t i, ColorField field) {
  switch (field) {
    case ColorField::Speed: {
      double sum = 0.0;
      for (int axis = 0; axis < view.dim; ++axis) {
        const double v = view.velocity(i, axis);
        sum += v * v;
      }
      return std::sqrt(sum);
    }
    case ColorField::Pressure:
      return view.pressure ? view.pressure[i] : 0.0;
    case ColorField::VerticalVelocity:
      return view.velocity(i, view.dim == 3 ? 2 : 1);
  }
  return 0.0;
}

bool ValueRange::degenerate() const {
  const double scale = std::max({1.0, std::abs(min), std::abs(max)});
  return !(max - min > 1e-12 * scale);
}

ValueRange fluid_range(const ParticleView& view, ColorField field) {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (std::size_t i = 0; i < view.count; ++i) {
    if (view.kind && view.kind[i] != static_cast<std::uint8_t>(ParticleKind::Fluid)) continue;
    const double v = color_field_value(view, i, field);
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  if (lo > hi) return {0.0, 0.0};
  return {lo, hi};
}

double normalized(const ValueRange& range, double value) {
  if (range.degenerate()) return 0.0;
  return std::clamp((value - range.min) / (range.max - range.min), 0.0, 1.0);
}

}  // namespace washout::render
