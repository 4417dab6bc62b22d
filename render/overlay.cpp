#include "render/overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/bitmap_font.hpp"
#include "render/color_map.hpp"
#include "render/palette.hpp"

namespace washout::render {
namespace {
constexpr int kMaxLabelChars = 9;  // the panel is sized for "-1.23e+05"
}  // namespace

std::string format_label_value(double value, const ValueRange& range) {
  if (!std::isfinite(value)) return "nan";
  const double largest = std::max(std::abs(range.min), std::abs(range.max));
  const double span = range.max - range.min;
  char text[32];
  if (largest >= 1e5 || (largest > 0.0 && largest < 1e-3) || !(span > 0.0)) {
    std::snprintf(text, sizeof(text), "%.2e", value);
    return text;
  }
  const int decimals = std::max(0, 2 - static_cast<int>(std::floor(std::log10(span))));
  // Round-off such as 2.8e-17 for a zero is printed as 0, never as "-0.00".
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0.0;
  const int length = std::snprintf(text, sizeof(text), "%.*f", decimals, value);
  // A tiny span around a large value would need too many digits for the panel.
  if (length > kMaxLabelChars) std::snprintf(text, sizeof(text), "%.2e", value);
  return text;
}

std::string format_time_label(double time) {
  char text[48];
  std::snprintf(text, sizeof(text), "t = %.3f s", time);
  return text;
}

void draw_color_bar(Image& image, const FrameLayout& layout, const ValueRange& range,
                    const std::string& title) {
  if (!layout.has_overlay) return;
  const PixelRect& bar = layout.color_bar;
  const int s = layout.font_scale;
  // A one-pixel frame just outside the gradient, so the gradient's own pixels are pure.
  image.fill_rect(bar.x - 1, bar.y - 1, bar.width + 2, bar.height + 2, kTextColor);
  for (int row = 0; row < bar.height; ++row) {
    const double t = bar.height > 1 ? 1.0 - static_cast<double>(row) / (bar.height - 1) : 1.0;
    image.fill_rect(bar.x, bar.y + row, bar.width, 1, color_map(t));
  }
  const int label_x = bar.x + bar.width + layout.margin / 2;
  const int half_text = text_height(s) / 2;
  const double mid = 0.5 * (range.min + range.max);
  draw_text(image, label_x, bar.y - half_text, format_label_value(range.max, range), kTextColor, s);
  draw_text(image, label_x, bar.y + bar.height / 2 - half_text, format_label_value(mid, range),
            kTextColor, s);
  draw_text(image, label_x, bar.y + bar.height - 1 - half_text,
            format_label_value(range.min, range), kTextColor, s);
  // Title right-aligned in the top strip, so a long one may extend over the scene's strip.
  draw_text(image, layout.width - layout.margin - text_width(title, s), layout.margin, title,
            kTextColor, s);
}

void draw_time_label(Image& image, const FrameLayout& layout, double time) {
  if (!layout.has_overlay) return;
  draw_text(image, layout.margin, layout.margin, format_time_label(time), kTextColor,
            layout.font_scale);
}

}  // namespace washout::render
