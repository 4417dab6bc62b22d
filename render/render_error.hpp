#pragma once
// Errors of the offscreen renderer. Subclasses let the command line map a failure to the
// documented exit status (1 bad input, 3 output could not be produced).
#include <stdexcept>

namespace washout::render {

// Bad input: unknown colour field or camera preset, empty view, invalid options.
class RenderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The image could not be written (missing folder, no permission, full disk).
class ImageWriteError : public RenderError {
 public:
  using RenderError::RenderError;
};

// No offscreen OpenGL context could be created (OSMesa missing or out of memory).
class ContextError : public RenderError {
 public:
  using RenderError::RenderError;
};

}  // namespace washout::render
