#pragma once
// An offscreen OpenGL 3.3 core context (OSMesa, software rendering through llvmpipe) that
// draws into a buffer we own. OSMesa contexts are current per thread: call make_current()
// before drawing from whichever thread renders.
#include <cstdint>
#include <vector>

namespace washout::render {

class OsmesaContext {
 public:
  // Throws ContextError if no context can be created.
  OsmesaContext(int width, int height);
  ~OsmesaContext();
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  void make_current();
  int width() const { return width_; }
  int height() const { return height_; }
  // RGBA bytes, bottom row first (OpenGL order); complete after glFinish().
  const std::uint8_t* rgba() const { return buffer_.data(); }

 private:
  void* context_ = nullptr;  // OSMesaContext, kept opaque so GL headers stay in the .cpp
  int width_ = 0, height_ = 0;
  std::vector<std::uint8_t> buffer_;
};

}  // namespace washout::render
