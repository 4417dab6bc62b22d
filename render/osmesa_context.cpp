#include "render/osmesa_context.hpp"

#include <string>

#include "render/gl_api.hpp"
#include "render/render_error.hpp"

namespace washout::render {

OsmesaContext::OsmesaContext(int width, int height)
    : width_(width),
      height_(height),
      buffer_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_ACCUM_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  context_ = gl().OSMesaCreateContextAttribs(attributes, nullptr);
  if (!context_) {
    throw ContextError(
        "cannot create an OSMesa OpenGL 3.3 context (is libOSMesa with llvmpipe installed?)");
  }
  make_current();
}

OsmesaContext::~OsmesaContext() {
  if (context_) gl().OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void OsmesaContext::make_current() {
  if (!gl().OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(),
                              GL_UNSIGNED_BYTE, width_, height_)) {
    throw ContextError("cannot make the OSMesa context current for a " + std::to_string(width_) +
                       "x" + std::to_string(height_) + " buffer");
  }
}

}  // namespace washout::render
