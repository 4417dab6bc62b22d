#include "render/frame_layout.hpp"

#include <algorithm>
#include <cmath>

#include "render/bitmap_font.hpp"

namespace washout::render {

FrameLayout FrameLayout::for_image(int width, int height) {
  FrameLayout l;
  l.width = width;
  l.height = height;
  l.font_scale = std::max(1, static_cast<int>(std::lround(height / 360.0)));
  const int s = l.font_scale;
  l.margin = 8 * s;
  const int top_strip = 2 * l.margin + text_height(s);
  const int bar_width = 10 * s;
  const int label_width = text_width("-1.23e+05", s) + s;  // the longest value label, and a gap
  const int panel = l.margin + bar_width + l.margin / 2 + label_width + l.margin;
  if (panel > width / 2 || top_strip > height / 3) {
    l.has_overlay = false;
    l.plot = {0, 0, width, height};
    return l;
  }
  l.plot = {0, top_strip, width - panel, height - top_strip};
  const int bar_top = top_strip + text_height(s);
  const int bar_height = std::min(height - bar_top - 2 * l.margin, (height * 3) / 5);
  l.color_bar = {width - panel + l.margin, bar_top, bar_width, bar_height};
  return l;
}

}  // namespace washout::render
