// The pieces drawn without OpenGL: colour map, value labels, bitmap text, frame layout, and
// PNG files written by Image.
#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "render/bitmap_font.hpp"
#include "render/color_map.hpp"
#include "render/frame_layout.hpp"
#include "render/image.hpp"
#include "render/overlay.hpp"
#include "render/render_error.hpp"

namespace washout::render {
namespace {

TEST(RenderOverlay, ColorMapRunsFromBlueToRed) {
  const Rgb8 low = color_map(0.0), mid = color_map(0.5), high = color_map(1.0);
  std::printf("map: low (%d, %d, %d), middle (%d, %d, %d), high (%d, %d, %d)\n", low.r, low.g,
              low.b, mid.r, mid.g, mid.b, high.r, high.g, high.b);
  EXPECT_GT(low.b, low.r);    // blue end
  EXPECT_GT(high.r, high.b);  // red end
  EXPECT_EQ(color_map(-3.0), low);
  EXPECT_EQ(color_map(7.0), high);
  EXPECT_EQ(color_map(std::nan("")), low);
  // Neighbouring values give neighbouring colours: no jumps along the map.
  int largest_step = 0;
  for (int i = 1; i <= 1000; ++i) {
    const Rgb8 a = color_map((i - 1) / 1000.0), b = color_map(i / 1000.0);
    largest_step =
        std::max({largest_step, std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
  }
  std::printf("largest channel step over 1/1000 of the map: %d\n", largest_step);
  EXPECT_LE(largest_step, 2);
}

TEST(RenderOverlay, LabelsShareTheirDecimals) {
  const ValueRange speed{0.0, 1.9}, pressure{0.0, 9810.0}, signed_range{-0.5, 0.4},
      huge{0.0, 2.5e6};
  const std::string labels[] = {
      format_label_value(0.0, speed),          format_label_value(0.95, speed),
      format_label_value(1.9, speed),          format_label_value(4905.0, pressure),
      format_label_value(-0.05, signed_range), format_label_value(2.8e-17, signed_range),
      format_label_value(1.25e6, huge)};
  for (const auto& l : labels) std::printf("label '%s'\n", l.c_str());
  EXPECT_EQ(labels[0], "0.00");
  EXPECT_EQ(labels[1], "0.95");
  EXPECT_EQ(labels[2], "1.90");
  EXPECT_EQ(labels[3], "4905");
  EXPECT_EQ(labels[4], "-0.050");
  EXPECT_EQ(labels[5], "0.000");  // round-off is not printed as a tiny number
  EXPECT_EQ(labels[6], "1.25e+06");
  EXPECT_EQ(format_time_label(0.25), "t = 0.250 s");
}

TEST(RenderOverlay, TextIsDrawnWithTheBuiltInFont) {
  Image image(80, 20, {255, 255, 255});
  draw_text(image, 1, 1, "t = 0.5 s", {0, 0, 0}, 1);
  int ink = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) ink += image.pixel(x, y) == Rgb8{0, 0, 0};
  }
  std::printf("'t = 0.5 s' at scale 1: %d ink pixels, width %d\n", ink, text_width("t = 0.5 s", 1));
  EXPECT_EQ(text_width("t = 0.5 s", 1), 9 * kGlyphAdvance - 1);
  EXPECT_EQ(text_width("ab", 3), (2 * kGlyphAdvance - 1) * 3);
  EXPECT_GT(ink, 30);
  EXPECT_EQ(image.pixel(79, 19), (Rgb8{255, 255, 255})) << "nothing beyond the text";
}

TEST(RenderOverlay, LayoutKeepsBarAndSceneApart) {
  const FrameLayout l = FrameLayout::for_image(1280, 720);
  std::printf("1280x720: font scale %d, plot %dx%d at (%d, %d), bar %dx%d at (%d, %d)\n",
              l.font_scale, l.plot.width, l.plot.height, l.plot.x, l.plot.y, l.color_bar.width,
              l.color_bar.height, l.color_bar.x, l.color_bar.y);
  EXPECT_TRUE(l.has_overlay);
  EXPECT_EQ(l.font_scale, 2);
  EXPECT_LE(l.plot.x + l.plot.width, l.color_bar.x);
  EXPECT_LE(l.color_bar.x + l.color_bar.width, 1280);
  EXPECT_LE(l.color_bar.y + l.color_bar.height, 720);
  EXPECT_GT(l.plot.width, 1000);
  const FrameLayout tiny = FrameLayout::for_image(64, 48);
  std::printf("64x48: overlay %d, plot %dx%d\n", tiny.has_overlay, tiny.plot.width,
              tiny.plot.height);
  EXPECT_FALSE(tiny.has_overlay);
  EXPECT_EQ(tiny.plot.width, 64);
}

TEST(RenderOverlay, PngRoundTripsAndBadPathsThrow) {
  Image image(7, 5, {10, 20, 30});
  image.set_pixel(3, 2, {200, 100, 50});
  const std::filesystem::path dir = std::filesystem::path(WASHOUT_TEST_OUTPUT_DIR) / "render";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "round_trip.png").string();
  image.write_png(path);
  png_image read;
  std::memset(&read, 0, sizeof(read));
  read.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&read, path.c_str()));
  read.format = PNG_FORMAT_RGB;
  std::vector<std::uint8_t> bytes(PNG_IMAGE_SIZE(read));
  ASSERT_TRUE(png_image_finish_read(&read, nullptr, bytes.data(), 0, nullptr));
  std::printf("read back %ux%u, %zu bytes\n", read.width, read.height, bytes.size());
  EXPECT_EQ(read.width, 7u);
  EXPECT_EQ(read.height, 5u);
  EXPECT_TRUE(bytes == image.bytes());
  EXPECT_THROW(image.write_png("/nonexistent-washout-dir/x.png"), ImageWriteError);
  EXPECT_THROW(Image().write_png(path), ImageWriteError);
}

}  // namespace
}  // namespace washout::render
