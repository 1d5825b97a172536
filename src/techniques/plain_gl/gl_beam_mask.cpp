// The footprint and q-gate units of the plain-GL shadow masks. See gl_beam_mask.h.
#include "techniques/plain_gl/gl_beam_mask.h"

#include "scene/spotlight.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace gs {
namespace {

// The footprint: kFootprintSide texels across the beam plane's [-kFootprintReach, kFootprintReach],
// so that kFootprintMargin texels on each side lie beyond the plane's [-1, 1], where no beam
// shines: the lit region's edge is then the texels' own, never the clamped border's.
constexpr int kFootprintSide = 1024;
constexpr int kFootprintMargin = 4;
constexpr float kFootprintReach =
    static_cast<float>(kFootprintSide) / static_cast<float>(kFootprintSide - 2 * kFootprintMargin);
// A texel holds 1/2 + kDistanceSlope times the signed distance (texels, positive where lit) from
// its centre to the lit region's edge, clamped to [0, 1]. Bilinear filtering reproduces a linear
// function, and the distance to a straight edge is one, so the alpha test at 1/2 cuts on the edge
// itself and not halfway between texel centres:
// that put a gobo bar's edge up to half a texel off, 5 to 6 mm on dunes 4 m away under a
// 163-degree cone, 4 pixels from a camera 28 cm above them (the sixteenth audit's
// near-camera-near-edge_23361, stencil volume 0.629%). A bilinear footprint's texels lie within
// sqrt 2 texels of any point of its cell, so the slope keeps them unclamped up to 1.5 texels.
// 16-bit texels: in 8 bits the cut still fell up to 2 pixels past the edge at 480x360 under a
// 40-degree camera there (beam23_gobo_bar_edge_close_zoomed), in 16 bits 1, about 1/100 of a
// texel (a 2048-texel footprint leaves none, for four times the texels to make).
constexpr float kDistanceSlope = 1.0f / 3.0f;
constexpr int kDistanceReach = 2;  // texels: the neighbours searched for the edge
constexpr int kBisections = 10;    // the edge found to 1/1024 of the way to a neighbour

// The gate's s = kGateSlope q (light-view depth, metres) in a two-texel step texture: open where
// q > 0.5 / kGateSlope, 50 um in front of the light's plane.
constexpr float kGateSlope = 1e4f;

// An alpha texture of 8 or 16-bit texels (`format` GL_ALPHA8 with GL_UNSIGNED_BYTE texels, or
// GL_ALPHA16 with GL_UNSIGNED_SHORT).
GLuint make_alpha_texture(const GlApi &gl, int width, int height, GLint format, GLenum type,
                          const void *texels, GLint filter, GLint wrap) {
  GLuint texture = 0;
  gl.glGenTextures(1, &texture);
  gl.glBindTexture(GL_TEXTURE_2D, texture);
  gl.glTexImage2D(GL_TEXTURE_2D, 0, format, width, height, 0, GL_ALPHA, type, texels);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
  const GLfloat none[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  gl.glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, none);
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

// Where the beam shines at (u, v) on its plane.
bool lit_at(const SpotLight &light, const glm::vec2 &uv) {
  return light.has_beam_map() ? beam_intensity(light, uv) > 0.0f : glm::dot(uv, uv) < 1.0f;
}

// The footprint's texels, GL's rows from t = 0 (the plane's v = -kFootprintReach), each
// 1/2 + kDistanceSlope times its centre's signed distance to the lit region's edge. The distance
// is the nearest crossing of that edge on the segments to the neighbours within kDistanceReach
// texels whose side differs, each found by bisection: for a straight edge at most 3% long (the
// widest angle between two neighbours' directions is 26.6 degrees), so within 0.05 texel where
// the slope is not clamped. Texels with no neighbour across the edge are 0 or 65535.
std::vector<std::uint16_t> footprint_texels(const SpotLight &light) {
  const int side = kFootprintSide;
  const float texel = 2.0f * kFootprintReach / static_cast<float>(side);  // beam plane units
  const auto centre = [&](int column, int row) {
    return glm::vec2((static_cast<float>(column) + 0.5f) * texel - kFootprintReach,
                     (static_cast<float>(row) + 0.5f) * texel - kFootprintReach);
  };
  std::vector<std::uint8_t> lit(static_cast<std::size_t>(side) * side);
  for (int row = 0; row < side; ++row) {
    for (int column = 0; column < side; ++column) {
      lit[static_cast<std::size_t>(row) * side + column] = lit_at(light, centre(column, row));
    }
  }
  std::vector<std::uint16_t> texels(lit.size());
  for (int row = 0; row < side; ++row) {
    for (int column = 0; column < side; ++column) {
      const bool here = lit[static_cast<std::size_t>(row) * side + column] != 0;
      const glm::vec2 from = centre(column, row);
      float distance = static_cast<float>(kDistanceReach);  // texels to the edge, at most this
      for (int dy = -kDistanceReach; dy <= kDistanceReach; ++dy) {
        for (int dx = -kDistanceReach; dx <= kDistanceReach; ++dx) {
          const int x = column + dx, y = row + dy;
          const float length = std::sqrt(static_cast<float>(dx * dx + dy * dy));
          if (x < 0 || y < 0 || x >= side || y >= side || length > kDistanceReach) continue;
          if ((lit[static_cast<std::size_t>(y) * side + x] != 0) == here) continue;
          if (length >= distance) continue;  // cannot come nearer than the nearest so far
          const glm::vec2 to = centre(x, y);
          float near = 0.0f, far = 1.0f;  // shares of the way to the neighbour: here's side, its
          for (int step = 0; step < kBisections; ++step) {
            const float middle = 0.5f * (near + far);
            (lit_at(light, from + (to - from) * middle) == here ? near : far) = middle;
          }
          distance = std::min(distance, 0.5f * (near + far) * length);
        }
      }
      const float signed_distance = here ? distance : -distance;
      texels[static_cast<std::size_t>(row) * side + column] = static_cast<std::uint16_t>(
          std::lround(std::clamp(0.5f + kDistanceSlope * signed_distance, 0.0f, 1.0f) * 65535.0f));
    }
  }
  return texels;
}

}  // namespace

GlBeamMask::GlBeamMask(const GlApi &gl, const SpotLight &light, int first, const glm::vec3 &origin)
    : gl_(gl), light_(light), first_(first), origin_(origin) {
  gl.glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + first));
  const std::vector<std::uint16_t> footprint = footprint_texels(light);
  footprint_ = make_alpha_texture(gl, kFootprintSide, kFootprintSide, GL_ALPHA16, GL_UNSIGNED_SHORT,
                                  footprint.data(), GL_LINEAR, GL_CLAMP_TO_BORDER);
  const std::uint8_t step[2] = {0, 255};
  gate_ = make_alpha_texture(gl, 2, 1, GL_ALPHA8, GL_UNSIGNED_BYTE, step, GL_NEAREST,
                             GL_CLAMP_TO_EDGE);
  gl.glActiveTexture(GL_TEXTURE0);
}

GlBeamMask::~GlBeamMask() {
  const GLuint textures[2] = {footprint_, gate_};
  gl_.glDeleteTextures(2, textures);
}

void GlBeamMask::bind() {
  const glm::mat4 light_clip = light_projection(light_) * light_view(light_) *
                               glm::translate(glm::mat4(1.0f), origin_);
  // The beam plane's [-kFootprintReach, kFootprintReach] onto the texture's [0, 1].
  const float scale = 0.5f / kFootprintReach;
  const glm::mat4 to_footprint = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 0.0f)) *
                                 glm::scale(glm::mat4(1.0f), glm::vec3(scale, scale, 1.0f)) *
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
