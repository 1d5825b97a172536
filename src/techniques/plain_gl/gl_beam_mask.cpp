// The footprint and q-gate units of the plain-GL shadow masks. See gl_beam_mask.h.
#include "techniques/plain_gl/gl_beam_mask.h"

#include "scene/spotlight.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdint>
#include <vector>

namespace gs {
namespace {

constexpr int kFootprintSide = 1024;  // texels across the beam plane's [-1, 1]
// The gate's s = kGateSlope q (light-view depth, metres) in a two-texel step texture: open where
// q > 0.5 / kGateSlope, 50 um in front of the light's plane.
constexpr float kGateSlope = 1e4f;

GLuint make_alpha_texture(const GlApi &gl, int width, int height, const std::uint8_t *texels,
                          GLint filter, GLint wrap) {
  GLuint texture = 0;
  gl.glGenTextures(1, &texture);
  gl.glBindTexture(GL_TEXTURE_2D, texture);
  gl.glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA8, width, height, 0, GL_ALPHA, GL_UNSIGNED_BYTE,
                  texels);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  const GLfloat none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  gl.glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, none);
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

}  // namespace

GlBeamMask::GlBeamMask(const GlApi &gl, const SpotLight &light, int first, const glm::vec3 &origin)
    : gl_(gl), light_(light), first_(first), origin_(origin) {
  gl.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + first));
  // GL's rows from t = 0, the beam plane's v = -1; texel centres at (i + 0.5) / side.
  std::vector<std::uint8_t> footprint(static_cast<std::size_t>(kFootprintSide) * kFootprintSide);
  for (int row = 0; row < kFootprintSide; ++row) {
    for (int column = 0; column < kFootprintSide; ++column) {
      const glm::vec2 uv((static_cast<float>(column) + 0.5f) / kFootprintSide * 2.0f - 1.0f,
                         (static_cast<float>(row) + 0.5f) / kFootprintSide * 2.0f - 1.0f);
      const bool lit = light.has_beam_map() ? beam_intensity(light, uv) > 0.0f
                                            : glm::dot(uv, uv) < 1.0f;
      footprint[static_cast<std::size_t>(row) * kFootprintSide + column] = lit ? 255 : 0;
    }
  }
  footprint_ = make_alpha_texture(gl, kFootprintSide, kFootprintSide, footprint.data(), GL_LINEAR,
                                  GL_CLAMP_TO_BORDER);
  const std::uint8_t step[2] = {0, 255};
  gate_ = make_alpha_texture(gl, 2, 1, step, GL_NEAREST, GL_CLAMP_TO_EDGE);
  gl.glActiveTexture(GL_TEXTURE0);
}

GlBeamMask::~GlBeamMask() {
  const GLuint textures[2] = {footprint_, gate_};
  gl_.glDeleteTextures(2, textures);
}

void GlBeamMask::bind() {
  const glm::mat4 light_clip = light_projection(light_) * light_view(light_) *
                               glm::translate(glm::mat4(1.0f), origin_);
  const glm::mat4 to_footprint = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 0.0f)) *
                                 glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 1.0f)) *
                                 light_clip;
  glm::mat4 to_gate(0.0f);  // s = kGateSlope q, t = 0.5, q = 1
  for (int column = 0; column < 4; ++column) to_gate[column][0] = kGateSlope * light_clip[column][3];
  to_gate[3][1] = 0.5f;
  to_gate[3][3] = 1.0f;
  const GLuint textures[2] = {footprint_, gate_};
  const glm::mat4 *const planes[2] = {&to_footprint, &to_gate};
  bind_projected_pair(gl_, first_, textures, planes);
}

void GlBeamMask::release() {
  release_projected_pair(gl_, first_);
}

}  // namespace gs
