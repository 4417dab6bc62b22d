#include "render/color_map.hpp"

#include <array>
#include <cmath>

namespace washout::render {
namespace {

// Evenly spaced anchors from t = 0 to t = 1.
constexpr std::array<Rgb8, 7> kAnchors = {{
    {40, 45, 140},   // deep blue
    {40, 100, 220},  // blue
    {40, 180, 225},  // cyan
    {90, 205, 120},  // green
    {225, 215, 55},  // yellow
    {245, 130, 35},  // orange
    {180, 25, 30},   // dark red
}};

std::uint8_t mix(std::uint8_t a, std::uint8_t b, double f) {
  return static_cast<std::uint8_t>(std::lround(a + (static_cast<double>(b) - a) * f));
}

}  // namespace

Rgb8 color_map(double t) {
  if (!(t > 0.0)) return kAnchors.front();  // also catches NaN
  if (t >= 1.0) return kAnchors.back();
  const double scaled = t * static_cast<double>(kAnchors.size() - 1);
  const auto segment = static_cast<std::size_t>(scaled);
  const double f = scaled - static_cast<double>(segment);
  const Rgb8 a = kAnchors[segment], b = kAnchors[segment + 1];
  return {mix(a.r, b.r, f), mix(a.g, b.g, f), mix(a.b, b.b, f)};
}

}  // namespace washout::render
