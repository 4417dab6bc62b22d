#include "render/sphere_impostor_pass.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <string>

#include "render/gl_api.hpp"
#include "render/render_error.hpp"
#include "render/sphere_shading.hpp"

namespace washout::render {
namespace {

static_assert(kSphereShading.shininess == 32.0, "the fragment shader squares five times");

// The quad faces the camera and sits at the front of the sphere, so that in perspective it
// still covers the whole silhouette.
// One quad (two triangles, six vertices) per sphere, generated from gl_VertexID: the sphere's
// data is fetched from a buffer texture. This avoids instanced drawing, which llvmpipe runs
// one instance at a time. The quad faces the camera and sits at the front of the sphere, so
// that in perspective it still covers the whole silhouette. Each shader is compiled twice,
// with PERSPECTIVE 0 and 1, so that no fragment pays for a branch on the camera kind.
constexpr const char* kVertexShader = R"(
uniform usamplerBuffer spheres;  // per sphere: center x, y, z as float bits, then RGBA8
uniform mat4 view;
uniform mat4 projection;
uniform float radius;
out vec3 quad_position;
out vec3 sphere_center;
out vec2 corner_offset;
flat out vec3 base_color;
const vec2 corners[6] = vec2[6](vec2(-1.0, -1.0), vec2(1.0, -1.0), vec2(-1.0, 1.0),
                                vec2(-1.0, 1.0), vec2(1.0, -1.0), vec2(1.0, 1.0));
void main() {
  uvec4 data = texelFetch(spheres, gl_VertexID / 6);
  vec2 corner = corners[gl_VertexID % 6];
  vec3 c = (view * vec4(uintBitsToFloat(data.xyz), 1.0)).xyz;
#if PERSPECTIVE
  // An off-axis sphere projects to an ellipse stretched by 1/cos(angle): grow the quad.
  float depth = max(-c.z - radius, 1e-6 * radius);
  float grow = 1.05 * length(c) / max(-c.z, 1e-6 * radius) + 2.0 * radius / depth;
#else
  float grow = 1.0;
#endif
  corner_offset = corner;
  quad_position = c + vec3(corner * radius * grow, radius);
  sphere_center = c;
  base_color = vec3(uvec3(data.w, data.w >> 8u, data.w >> 16u) & 255u) / 255.0;
  gl_Position = projection * vec4(quad_position, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(
in vec3 quad_position;
in vec3 sphere_center;
in vec2 corner_offset;
flat in vec3 base_color;
uniform float radius;
uniform vec2 depth_transform;  // NDC depth = (a z + b) / w, w = 1 or -z (projection row 3)
uniform vec3 light_direction;
uniform float ambient;
uniform float diffuse;
uniform float specular;
out vec4 frag_color;
void main() {
#if PERSPECTIVE
  // Cast the view ray through this fragment at the sphere (camera space, eye at the origin).
  vec3 dir = normalize(quad_position);
  float b = dot(sphere_center, dir);
  float disc = b * b - (dot(sphere_center, sphere_center) - radius * radius);
  if (disc < 0.0) discard;
  vec3 hit = (b - sqrt(disc)) * dir;
  vec3 n = (hit - sphere_center) / radius;
  vec3 to_viewer = -dir;
  float w = -hit.z;
#else
  // Parallel rays: the quad offset is the normal's x, y directly.
  float r2 = dot(corner_offset, corner_offset);
  if (r2 > 1.0) discard;
  vec3 n = vec3(corner_offset, sqrt(1.0 - r2));
  vec3 hit = sphere_center + radius * n;
  vec3 to_viewer = vec3(0.0, 0.0, 1.0);
  float w = 1.0;
#endif
  gl_FragDepth = clamp(0.5 * (depth_transform.x * hit.z + depth_transform.y) / w + 0.5, 0.0, 1.0);
  vec3 half_vector = normalize(light_direction + to_viewer);
  float lambert = max(dot(n, light_direction), 0.0);
  // x^32 by five squarings: much cheaper than pow() in llvmpipe (see the static_assert).
  float h = max(dot(n, half_vector), 0.0);
  h *= h; h *= h; h *= h; h *= h; h *= h;
  float highlight = specular * h;
  frag_color = vec4(clamp(base_color * (ambient + diffuse * lambert) + highlight, 0.0, 1.0), 1.0);
}
)";

unsigned compile(GLenum stage, const char* source, bool perspective) {
  const GLuint shader = gl().glCreateShader(stage);
  const char* parts[] = {"#version 330 core\n",
                         perspective ? "#define PERSPECTIVE 1\n" : "#define PERSPECTIVE 0\n",
                         source};
  gl().glShaderSource(shader, 3, parts, nullptr);
  gl().glCompileShader(shader);
  GLint ok = GL_FALSE;
  gl().glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    gl().glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    gl().glDeleteShader(shader);
    throw ContextError(std::string("sphere shader does not compile: ") + log);
  }
  return shader;
}

void set_matrix(int location, const Eigen::Matrix4d& m) {
  const Eigen::Matrix4f f = m.cast<float>();  // Eigen is column-major, as OpenGL expects
  gl().glUniformMatrix4fv(location, 1, GL_FALSE, f.data());
}

// Compiles and links one variant; the uniforms that never change are set here.
unsigned link_program(bool perspective) {
  const GLuint vs = compile(GL_VERTEX_SHADER, kVertexShader, perspective);
  const GLuint fs = compile(GL_FRAGMENT_SHADER, kFragmentShader, perspective);
  const GLuint program = gl().glCreateProgram();
  gl().glAttachShader(program, vs);
  gl().glAttachShader(program, fs);
  gl().glLinkProgram(program);
  gl().glDeleteShader(vs);
  gl().glDeleteShader(fs);
  GLint ok = GL_FALSE;
  gl().glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    char log[2048] = {0};
    gl().glGetProgramInfoLog(program, sizeof(log), nullptr, log);
    gl().glDeleteProgram(program);
    throw ContextError(std::string("sphere shaders do not link: ") + log);
  }
  gl().glUseProgram(program);
  gl().glUniform1i(gl().glGetUniformLocation(program, "spheres"), 0);
  const SphereShading& s = kSphereShading;
  const Eigen::Vector3f light =
      Eigen::Vector3d(s.light_direction[0], s.light_direction[1], s.light_direction[2])
          .normalized()
          .cast<float>();
  gl().glUniform3f(gl().glGetUniformLocation(program, "light_direction"), light.x(), light.y(),
                   light.z());
  gl().glUniform1f(gl().glGetUniformLocation(program, "ambient"), static_cast<float>(s.ambient));
  gl().glUniform1f(gl().glGetUniformLocation(program, "diffuse"), static_cast<float>(s.diffuse));
  gl().glUniform1f(gl().glGetUniformLocation(program, "specular"), static_cast<float>(s.specular));
  return program;
}

}  // namespace

SphereImpostorPass::SphereImpostorPass() {
  orthographic_program_ = link_program(false);
  perspective_program_ = link_program(true);
  // No vertex attributes: everything comes from the buffer texture.
  gl().glGenVertexArrays(1, &vertex_array_);
  gl().glGenBuffers(1, &instance_buffer_);
  gl().glGenTextures(1, &instance_texture_);
  gl().glBindBuffer(GL_TEXTURE_BUFFER, instance_buffer_);
  gl().glBindTexture(GL_TEXTURE_BUFFER, instance_texture_);
  gl().glTexBuffer(GL_TEXTURE_BUFFER, GL_RGBA32UI, instance_buffer_);
  gl().glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &max_spheres_);
}

SphereImpostorPass::~SphereImpostorPass() {
  gl().glDeleteTextures(1, &instance_texture_);
  gl().glDeleteBuffers(1, &instance_buffer_);
  gl().glDeleteVertexArrays(1, &vertex_array_);
  gl().glDeleteProgram(orthographic_program_);
  gl().glDeleteProgram(perspective_program_);
}

void SphereImpostorPass::draw(const std::vector<SphereInstance>& spheres, const Camera& camera,
                              double radius) {
  if (spheres.empty()) return;
  const GLuint program = camera.is_orthographic() ? orthographic_program_ : perspective_program_;
  gl().glUseProgram(program);
  const Eigen::Matrix4d projection = camera.projection_matrix();
  set_matrix(gl().glGetUniformLocation(program, "view"), camera.view_matrix());
  set_matrix(gl().glGetUniformLocation(program, "projection"), projection);
  gl().glUniform1f(gl().glGetUniformLocation(program, "radius"), static_cast<float>(radius));
  gl().glUniform2f(gl().glGetUniformLocation(program, "depth_transform"),
                   static_cast<float>(projection(2, 2)), static_cast<float>(projection(2, 3)));

  gl().glBindVertexArray(vertex_array_);
  gl().glActiveTexture(GL_TEXTURE0);
  gl().glBindTexture(GL_TEXTURE_BUFFER, instance_texture_);
  gl().glBindBuffer(GL_TEXTURE_BUFFER, instance_buffer_);
  // Large frames are drawn in slices that fit the buffer texture's size limit.
  const std::size_t slice = static_cast<std::size_t>(std::max(max_spheres_, 1));
  for (std::size_t first = 0; first < spheres.size(); first += slice) {
    const std::size_t n = std::min(slice, spheres.size() - first);
    // Reuse the buffer's storage from frame to frame: reallocating it costs page faults.
    const auto bytes = static_cast<GLsizeiptr>(n * sizeof(SphereInstance));
    if (bytes > buffer_capacity_) {
      gl().glBufferData(GL_TEXTURE_BUFFER, bytes, nullptr, GL_DYNAMIC_DRAW);
      buffer_capacity_ = bytes;
    }
    gl().glBufferSubData(GL_TEXTURE_BUFFER, 0, bytes, spheres.data() + first);
    gl().glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * n));
  }
  gl().glBindVertexArray(0);
}

}  // namespace washout::render
