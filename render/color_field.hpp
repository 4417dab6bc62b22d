#pragma once
// The scalar a fluid particle is coloured by, and its range over a frame.
#include <cstddef>
#include <string>

#include "engine/core/particle_view.hpp"

namespace washout::render {

enum class ColorField { Speed, Pressure, VerticalVelocity };

// "speed", "pressure" or "vertical_velocity"; throws RenderError naming the valid choices.
ColorField parse_color_field(const std::string& name);
std::string color_field_name(ColorField field);
// Title of the colour bar, with the unit, e.g. "speed [m/s]".
std::string color_field_title(ColorField field);

// Vertical velocity is along the axis opposite to gravity: y in 2D, z in 3D.
double color_field_value(const ParticleView& view, std::size_t i, ColorField field);

struct ValueRange {
  double min = 0.0;
  double max = 1.0;
  // True when all values are (nearly) equal, so the range says nothing about the flow.
  bool degenerate() const;
};

// Range of the field over the fluid particles (kind 0) of a view. With no fluid particle
// the range is [0, 0], degenerate.
ValueRange fluid_range(const ParticleView& view, ColorField field);

// Where value lies in range, in [0, 1] (clamped). A degenerate range maps to 0.
double normalized(const ValueRange& range, double value);

}  // namespace washout::render
