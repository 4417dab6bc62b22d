#pragma once
// A tiny built-in 5x7 pixel font for the labels drawn into frames (digits, lower-case letters,
// "P" and the punctuation of numbers and units), so that no font library is needed.
// Upper-case letters without their own glyph are drawn lower-case; other characters as a box.
#include <string_view>

#include "render/image.hpp"

namespace washout::render {

inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 7;
inline constexpr int kGlyphAdvance = 6;  // glyph plus one column of space

// Width and height in pixels of text drawn at the given integer scale.
int text_width(std::string_view text, int scale);
inline int text_height(int scale) { return kGlyphHeight * scale; }

// Draws text with its top-left corner at (x, y); pixels outside the image are skipped.
void draw_text(Image& image, int x, int y, std::string_view text, Rgb8 color, int scale);

}  // namespace washout::render
