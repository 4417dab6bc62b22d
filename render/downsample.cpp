#include "render/downsample.hpp"

#include <cstddef>

namespace washout::render {

Image downsample_rgba(const std::uint8_t* rgba, int width, int height, int factor) {
  Image image(width, height);
  const std::size_t source_width = static_cast<std::size_t>(width) * factor;
  const int samples = factor * factor;
  std::uint8_t* out = image.bytes().data();
#pragma omp parallel for schedule(static)
  for (int y = 0; y < height; ++y) {
    const int source_row0 = (height - 1 - y) * factor;  // GL rows count from the bottom
    for (int x = 0; x < width; ++x) {
      int sum[3] = {0, 0, 0};
      for (int dy = 0; dy < factor; ++dy) {
        const std::uint8_t* row =
            rgba + ((source_row0 + dy) * source_width + static_cast<std::size_t>(x) * factor) * 4;
        for (int dx = 0; dx < factor; ++dx) {
          for (int c = 0; c < 3; ++c) sum[c] += row[dx * 4 + c];
        }
      }
      std::uint8_t* pixel = out + (static_cast<std::size_t>(y) * width + x) * 3;
      for (int c = 0; c < 3; ++c)
        pixel[c] = static_cast<std::uint8_t>((sum[c] + samples / 2) / samples);
    }
  }
  return image;
}

}  // namespace washout::render
