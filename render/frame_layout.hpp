#pragma once
// Where things go in a frame: the scene on the left, the colour bar with its labels on the
// right, the time label and the bar's title in a strip along the top. Sizes scale with the
// image height so that text stays readable from 360p to 4K.
namespace washout::render {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;  // top-left corner, y downwards
};

struct FrameLayout {
  int width = 0, height = 0;  // the whole image
  int font_scale = 1;         // pixels per font pixel
  int margin = 8;
  PixelRect plot;  // the scene is fitted into this area
  PixelRect
      color_bar;  // the gradient itself: the high end on the top row, the low end at the bottom
  bool has_overlay = true;  // false for images too small to hold the bar beside the scene

  static FrameLayout for_image(int width, int height);
};

}  // namespace washout::render
