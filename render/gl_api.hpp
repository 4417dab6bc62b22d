#pragma once
// OSMesa and the OpenGL functions the renderer calls, loaded from libOSMesa when the first
// context is made (dlopen), not linked: OSMesa brings LLVM (llvmpipe), about 50 MB of resident
// memory in every process that links it, and a run that draws no frame should not pay for it
// (docs/performance.md, nineteenth session). The headers give the types and constants only.
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

namespace washout::render {

// The GL functions used, each called as gl().glName(...).
// clang-format off
#define WASHOUT_GL_FUNCTIONS(X)                                                                  \
  X(glActiveTexture) X(glAttachShader) X(glBindBuffer) X(glBindTexture) X(glBindVertexArray)     \
  X(glBufferData) X(glBufferSubData) X(glClear) X(glClearColor) X(glClearDepth)                  \
  X(glCompileShader) X(glCreateProgram) X(glCreateShader) X(glDeleteBuffers) X(glDeleteProgram)  \
  X(glDeleteShader) X(glDeleteTextures) X(glDeleteVertexArrays) X(glDepthFunc) X(glDrawArrays)   \
  X(glEnable) X(glFinish) X(glGenBuffers) X(glGenTextures) X(glGenVertexArrays)                  \
  X(glGetIntegerv) X(glGetProgramInfoLog) X(glGetProgramiv) X(glGetShaderInfoLog)                \
  X(glGetShaderiv) X(glGetUniformLocation) X(glLinkProgram) X(glShaderSource) X(glTexBuffer)     \
  X(glUniform1f) X(glUniform1i) X(glUniform2f) X(glUniform3f) X(glUniformMatrix4fv)              \
  X(glUseProgram) X(glViewport)
// clang-format on

struct GlApi {
#define WASHOUT_GL_MEMBER(name) decltype(&::name) name = nullptr;
  WASHOUT_GL_FUNCTIONS(WASHOUT_GL_MEMBER)
#undef WASHOUT_GL_MEMBER
  decltype(&::OSMesaCreateContextAttribs) OSMesaCreateContextAttribs = nullptr;
  decltype(&::OSMesaMakeCurrent) OSMesaMakeCurrent = nullptr;
  decltype(&::OSMesaDestroyContext) OSMesaDestroyContext = nullptr;
};

// The functions, loaded on the first call (thread-safe); throws ContextError when libOSMesa
// or one of them cannot be found.
const GlApi& gl();

}  // namespace washout::render
