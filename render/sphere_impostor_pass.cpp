#include "render/sphere_impostor_pass.hpp"

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <string>

#include "render/render_error.hpp"
#include "render/sphere_shading.hpp"

namespace washout::render {
namespace {

// The quad faces the camera and sits at the front of the sphere, so that in perspective it
// still covers the whole silhouette.
// One quad (two triangles, six vertices) per sphere, generated from gl_VertexID: the sphere's
// data is fetched from a buffer texture. This avoids instanced drawing, which llvmpipe runs
// one instance at a time. The quad faces the camera and sits at the front of the sphere, so
// that in perspective it still covers the whole silhouette.
constexpr const char* kVertexShader = R"(#version 330 core
uniform usamplerBuffer spheres;  // per sphere: center x, y, z as float bits, then RGBA8
uniform mat4 view;
uniform mat4 projection;
uniform float radius;
uniform bool orthographic;
out vec3 quad_position;
out vec3 sphere_center;
out vec3 base_color;
const vec2 corners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0),
                                vec2(-1.0, 1.0), vec2(1.0, -1.0), vec2(1.0, 1.0));
void main() {
  uvec4 data = texelFetch(spheres, gl_VertexID / 6);
  vec2 corner = corners[gl_VertexID % 6];
  vec3 c = (view * vec4(uintBitsToFloat(data.xyz), 1.0)).xyz;
  // In perspective an off-axis sphere projects to an ellipse stretched by 1/cos(angle).
  float depth = max(-c.z - radius, 1e-6 * radius);
  float grow = orthographic ? 1.0 : 1.05 * length(c) / max(-c.z, 1e-6 * radius) + 2.0 * radius / depth;
  quad_position = c + vec3(corner * radius * grow, radius);
  sphere_center = c;
  base_color = vec3(uvec3(data.w, data.w >> 8u, data.w >> 16u) & 255u) / 255.0;
  gl_Position = projection * vec4(quad_position, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
#extension GL_ARB_conservative_depth : require
layout(depth_greater) out float gl_FragDepth;
in vec3 quad_position;
in vec3 sphere_center;
in vec3 base_color;
uniform mat4 projection;
uniform float radius;
uniform bool orthographic;
uniform vec3 light_direction;
uniform float ambient;
uniform float diffuse;
uniform float specular;
uniform float shininess;
out vec4 frag_color;
void main() {
  // The view ray through this fragment, in camera space.
  vec3 origin = orthographic ? vec3(quad_position.xy, 0.0) : vec3(0.0);
  vec3 dir = orthographic ? vec3(0.0, 0.0, -1.0) : normalize(quad_position);
  vec3 oc = origin - sphere_center;
  float b = dot(oc, dir);
  float disc = b * b - (dot(oc, oc) - radius * radius);
  if (disc < 0.0) discard;
  vec3 hit = origin + (-b - sqrt(disc)) * dir;
  vec3 n = (hit - sphere_center) / radius;
  vec4 clip = projection * vec4(hit, 1.0);
  gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
  vec3 to_viewer = -dir;
  vec3 half_vector = normalize(light_direction + to_viewer);
  float lambert = max(dot(n, light_direction), 0.0);
  float highlight = specular * pow(max(dot(n, half_vector), 0.0), shininess);
  frag_color = vec4(clamp(base_color * (ambient + diffuse * lambert) + highlight, 0.0, 1.0), 1.0);
}
)";

unsigned compile(GLenum stage, const char* source) {
  const GLuint shader = glCreateShader(stage);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    glDeleteShader(shader);
    throw ContextError(std::string("sphere shader does not compile: ") + log);
  }
  return shader;
}

void set_matrix(int location, const Eigen::Matrix4d& m) {
  const Eigen::Matrix4f f = m.cast<float>();  // Eigen is column-major, as OpenGL expects
  glUniformMatrix4fv(location, 1, GL_FALSE, f.data());
}

}  // namespace

SphereImpostorPass::SphereImpostorPass() {
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader);
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    glGetProgramInfoLog(program_, sizeof(log), nullptr, log);
    throw ContextError(std::string("sphere shaders do not link: ") + log);
  }
  view_location_ = glGetUniformLocation(program_, "view");
  projection_location_ = glGetUniformLocation(program_, "projection");
  radius_location_ = glGetUniformLocation(program_, "radius");
  orthographic_location_ = glGetUniformLocation(program_, "orthographic");

  // No vertex attributes: everything comes from the buffer texture.
  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(1, &instance_buffer_);
  glGenTextures(1, &instance_texture_);
  glBindBuffer(GL_TEXTURE_BUFFER, instance_buffer_);
  glBindTexture(GL_TEXTURE_BUFFER, instance_texture_);
  glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, instance_buffer_);
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_spheres_);

  glUseProgram(program_);
  glUniform1i(glGetUniformLocation(program_, "spheres"), 0);
  const SphereShading& s = kSphereShading;
  const Eigen::Vector3f light = Eigen::Vector3d(s.light_direction[0], s.light_direction[1],
                                                s.light_direction[2])
                                    .normalized()
                                    .cast<float>();
  glUniform3f(glGetUniformLocation(program_, "light_direction"), light.x(), light.y(), light.z());
  glUniform1f(glGetUniformLocation(program_, "ambient"), static_cast<float>(s.ambient));
  glUniform1f(glGetUniformLocation(program_, "diffuse"), static_cast<float>(s.diffuse));
  glUniform1f(glGetUniformLocation(program_, "specular"), static_cast<float>(s.specular));
  glUniform1f(glGetUniformLocation(program_, "shininess"), static_cast<float>(s.shininess));
}

SphereImpostorPass::~SphereImpostorPass() {
  glDeleteTextures(1, &instance_texture_);
  glDeleteBuffers(1, &instance_buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(program_);
}

void SphereImpostorPass::draw(const std::vector<SphereInstance>& spheres, const Camera& camera,
                              double radius) {
  if (spheres.empty()) return;
  glUseProgram(program_);
  set_matrix(view_location_, camera.view_matrix());
  set_matrix(projection_location_, camera.projection_matrix());
  glUniform1f(radius_location_, static_cast<float>(radius));
  glUniform1i(orthographic_location_, camera.is_orthographic() ? 1 : 0);

  glBindVertexArray(vertex_array_);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_BUFFER, instance_texture_);
  glBindBuffer(GL_TEXTURE_BUFFER, instance_buffer_);
  // Large frames are drawn in slices that fit the buffer texture's size limit.
  const std::size_t slice = static_cast<std::size_t>(std::max(max_spheres_, 1));
  for (std::size_t first = 0; first < spheres.size(); first += slice) {
    const std::size_t n = std::min(slice, spheres.size() - first);
    // Reuse the buffer's storage from frame to frame: reallocating it costs page faults.
    const auto bytes = static_cast<GLsizeiptr>(n * sizeof(SphereInstance));
    if (bytes > buffer_capacity_) {
      glBufferData(GL_TEXTURE_BUFFER, bytes, nullptr, GL_DYNAMIC_DRAW);
      buffer_capacity_ = bytes;
    }
    glBufferSubData(GL_TEXTURE_BUFFER, 0, bytes, spheres.data() + first);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * n));
  }
  glBindVertexArray(0);
}

}  // namespace washout::render
