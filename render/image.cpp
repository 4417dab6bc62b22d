#include "render/image.hpp"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "render/render_error.hpp"

namespace washout::render {

Image::Image(int width, int height, Rgb8 fill)
    : width_(std::max(width, 0)),
      height_(std::max(height, 0)),
      bytes_(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_) * 3) {
  for (std::size_t i = 0; i < bytes_.size(); i += 3) {
    bytes_[i] = fill.r;
    bytes_[i + 1] = fill.g;
    bytes_[i + 2] = fill.b;
  }
}

Rgb8 Image::pixel(int x, int y) const {
  const std::size_t o = offset(x, y);
  return {bytes_[o], bytes_[o + 1], bytes_[o + 2]};
}

void Image::set_pixel(int x, int y, Rgb8 color) {
  if (!contains(x, y)) return;
  const std::size_t o = offset(x, y);
  bytes_[o] = color.r;
  bytes_[o + 1] = color.g;
  bytes_[o + 2] = color.b;
}

void Image::fill_rect(int x, int y, int width, int height, Rgb8 color) {
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = std::min(x + width, width_), y1 = std::min(y + height, height_);
  for (int j = y0; j < y1; ++j) {
    for (int i = x0; i < x1; ++i) set_pixel(i, j, color);
  }
}

void Image::write_png(const std::string& path) const {
  if (width_ == 0 || height_ == 0) throw ImageWriteError("cannot write an empty image to " + path);
  // Open the file ourselves so that the error names the system's reason (errno).
  std::unique_ptr<FILE, int (*)(FILE*)> file(std::fopen(path.c_str(), "wb"), &std::fclose);
  if (!file) {
    throw ImageWriteError("cannot write image " + path + ": " + std::strerror(errno));
  }
  png_image image;
  std::memset(&image, 0, sizeof(image));
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(width_);
  image.height = static_cast<png_uint_32>(height_);
  image.format = PNG_FORMAT_RGB;
  const int ok =
      png_image_write_to_stdio(&image, file.get(), 0, bytes_.data(), width_ * 3, nullptr);
  const std::string message = image.message;
  png_image_free(&image);
  if (!ok) throw ImageWriteError("cannot write image " + path + ": " + message);
  FILE* raw = file.release();
  if (std::fclose(raw) != 0) {
    throw ImageWriteError("cannot write image " + path + ": " + std::strerror(errno));
  }
}

}  // namespace washout::render
