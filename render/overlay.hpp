#pragma once
// The 2D annotations drawn on the finished frame: the colour bar with its numeric range and
// title, and the simulated time.
#include <string>

#include "render/color_field.hpp"
#include "render/frame_layout.hpp"
#include "render/image.hpp"

namespace washout::render {

// A colour bar label. All labels of one bar share the number of decimals, chosen so the
// range's span shows about three significant digits: [0, 1.9] gives "0.00", "0.95", "1.90";
// [0, 9810] gives "0", "4905", "9810"; very large or small values use exponents ("1.23e+05").
std::string format_label_value(double value, const ValueRange& range);

// "t = 0.250 s"
std::string format_time_label(double time);

void draw_color_bar(Image& image, const FrameLayout& layout, const ValueRange& range,
                    const std::string& title);
void draw_time_label(Image& image, const FrameLayout& layout, double time);

}  // namespace washout::render
