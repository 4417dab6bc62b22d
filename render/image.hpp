#pragma once
// An 8-bit RGB image in memory, rows top to bottom, that can be saved as PNG.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace washout::render {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

class Image {
 public:
  Image() = default;
  Image(int width, int height, Rgb8 fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  // (x, y) with x to the right and y downwards from the top-left corner.
  Rgb8 pixel(int x, int y) const;
  void set_pixel(int x, int y, Rgb8 color);
  void fill_rect(int x, int y, int width, int height, Rgb8 color);  // clipped to the image

  // Packed RGB bytes, row-major from the top row.
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::vector<std::uint8_t>& bytes() { return bytes_; }

  // Throws ImageWriteError with the path and the reason if the file cannot be written.
  void write_png(const std::string& path) const;

 private:
  std::size_t offset(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
            static_cast<std::size_t>(x)) *
           3;
  }
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> bytes_;
};

}  // namespace washout::render
