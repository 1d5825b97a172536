// The beam and attenuation texture units of the plain-GL lit passes. See gl_light_units.h.
#include "techniques/plain_gl/gl_light_units.h"

#include "techniques/light_passes/slide_projector.h"
#include "scene/spotlight.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace gs {
namespace {

// A texture of `width` x `height` texels of `channels` bytes (1: luminance, 3: RGB), row 0 first.
// Every row used here is a multiple of 4 bytes, GL's default unpack alignment.
GLuint make_texture(const GlApi &gl, int width, int height, int channels, const std::uint8_t *texels) {
  GLuint texture = 0;
  gl.glGenTextures(1, &texture);
  gl.glBindTexture(GL_TEXTURE_2D, texture);
  gl.glTexImage2D(GL_TEXTURE_2D, 0, channels == 3 ? GL_RGB8 : GL_LUMINANCE8, width, height, 0,
                  channels == 3 ? GL_RGB : GL_LUMINANCE, GL_UNSIGNED_BYTE, texels);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl.glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  gl.glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

}  // namespace

GlLightUnits::GlLightUnits(const GlApi &gl, const SpotLight &light, float farthest,
                           const glm::vec3 &origin)
    : gl_(gl), light_(light), nearest_(kLightNearPlane),
      farthest_(std::max(farthest, kLightNearPlane * 2.0f)), origin_(origin) {
  // Made on unit 2, so whatever the caller has bound on units 0 and 1 stays bound.
  gl.glActiveTexture(GL_TEXTURE2);
  // The projected texture's rows go up the beam: GL's t = 0 is the first row uploaded.
  int side = kBeamMapSide, channels = 1;
  std::vector<std::uint8_t> top_first;
  if (light.is_projector()) {
    const ProjectedImage slide = slide_image(light);
    side = slide.side, channels = 3;
    for (const glm::vec3 &c : slide.rgb)
      for (int k = 0; k < 3; ++k) top_first.push_back(static_cast<std::uint8_t>(std::lround(c[k] * 255.0f)));
  } else {
    top_first = beam_texels(light, kBeamMapSide);
  }
  const std::size_t row_bytes = static_cast<std::size_t>(side * channels);
  std::vector<std::uint8_t> bottom_first(top_first.size());
  for (int row = 0; row < side; ++row)
    std::copy_n(top_first.begin() + static_cast<std::ptrdiff_t>((side - 1 - row) * row_bytes), row_bytes,
                bottom_first.begin() + static_cast<std::ptrdiff_t>(row * row_bytes));
  beam_ = make_texture(gl, side, side, channels, bottom_first.data());
  // Texel 0 black covers depths before the near plane; the others the function over the range
  // (all 1 unless the attenuation is exact, when the vertex colours carry it).
  SpotLight function = light;
  if (light.attenuation.mode != AttenuationMode::PerPixel)
    function.attenuation.mode = AttenuationMode::None;
  std::vector<std::uint8_t> ramp =
      attenuation_texels(function, nearest_, farthest_, kAttenuationMapWidth - 1);
  ramp.insert(ramp.begin(), 0);
  attenuation_ = make_texture(gl, kAttenuationMapWidth, 1, 1, ramp.data());
  gl.glActiveTexture(GL_TEXTURE0);
}

GlLightUnits::~GlLightUnits() {
  const GLuint textures[2] = {beam_, attenuation_};
  gl_.glDeleteTextures(2, textures);
}

void GlLightUnits::bind() {
  // The arrays' coordinates to world, then world to the light.
  const glm::mat4 to_world = glm::translate(glm::mat4(1.0f), origin_);
  const glm::mat4 view = light_view(light_) * to_world;
  const glm::mat4 light_clip = light_projection(light_) * view;
  const glm::mat4 to_beam = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 0.0f)) *
                            glm::scale(glm::mat4(1.0f), glm::vec3(0.5f, 0.5f, 1.0f)) * light_clip;
  // s: the depth's place in the texture: texel 0 centred before the near plane, the ramp's
  // texel i at near + (i + 0.5) / 255 of the range, i.e. s = (1 + (d - near) / range * 255) / 256.
  const float width = static_cast<float>(kAttenuationMapWidth);
  const float per_metre = (width - 1.0f) / (farthest_ - nearest_) / width;
  glm::mat4 to_attenuation(0.0f);
  for (int column = 0; column < 4; ++column) to_attenuation[column][0] = -view[column][2] * per_metre;
  to_attenuation[3][0] += 1.0f / width - nearest_ * per_metre;
  to_attenuation[3][1] = 0.5f;
  to_attenuation[3][3] = 1.0f;

  const GLuint textures[2] = {beam_, attenuation_};
  const glm::mat4 *const planes[2] = {&to_beam, &to_attenuation};
  bind_projected_pair(gl_, 2, textures, planes);
}

void GlLightUnits::release() {
  release_projected_pair(gl_, 2);
}

}  // namespace gs
