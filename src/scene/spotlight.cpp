// Beam patterns, distance attenuation and their textures. See spotlight.h for the spaces.
#include "scene/spotlight.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The built-in cross-sections, (u, v) on the beam plane. Each is 0 at and beyond the beam
// plane's edge, so nothing is lit outside the cone.
float round_beam(const glm::vec2 &uv) { return 1.0f - smoothstep(0.8f, 1.0f, glm::length(uv)); }

float square_beam(const glm::vec2 &uv) {
  return 1.0f - smoothstep(0.85f, 1.0f, std::max(std::abs(uv.x), std::abs(uv.y)));
}

// A window gobo: the round beam cut by a cross of bars 0.1 wide, four panes of light.
float gobo_beam(const glm::vec2 &uv) {
  const float bar_half_width = 0.05f;
  if (std::abs(uv.x) < bar_half_width || std::abs(uv.y) < bar_half_width) return 0.0f;
  return round_beam(uv);
}

// A lens's barrel distortion seen on concentric rings: ring radius r maps to r (1 + 0.4 r^2),
// so the rings crowd towards the rim, inside the round beam.
float lens_beam(const glm::vec2 &uv) {
  const float r = glm::length(uv);
  const float distorted = r * (1.0f + 0.4f * r * r);
  return round_beam(uv) * (0.6f + 0.4f * std::cos(glm::two_pi<float>() * 3.0f * distorted));
}

std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

}  // namespace

glm::vec3 sample_projected_image(const ProjectedImage &image, const glm::vec2 &uv) {
  const float side = static_cast<float>(image.side);
  const float x = (uv.x * 0.5f + 0.5f) * side - 0.5f;  // texels, from the left
  const float y = (0.5f - uv.y * 0.5f) * side - 0.5f;  // texels, from the top
  const float x0 = std::floor(x), y0 = std::floor(y);
  const float fx = x - x0, fy = y - y0;
  auto texel = [&](float tx, float ty) {
    const int ix = std::clamp(static_cast<int>(tx), 0, image.side - 1);
    const int iy = std::clamp(static_cast<int>(ty), 0, image.side - 1);
    return image.rgb[static_cast<std::size_t>(iy * image.side + ix)];
  };
  const glm::vec3 top = texel(x0, y0) * (1.0f - fx) + texel(x0 + 1.0f, y0) * fx;
  const glm::vec3 bottom = texel(x0, y0 + 1.0f) * (1.0f - fx) + texel(x0 + 1.0f, y0 + 1.0f) * fx;
  return top * (1.0f - fy) + bottom * fy;
}

glm::mat4 light_view(const SpotLight &light) {
  // A light looking straight up or down takes +z as its up, where the default +y is degenerate.
  const glm::vec3 axis = glm::normalize(light.target - light.position);
  const glm::vec3 up = std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  return glm::lookAt(light.position, light.target, up);
}

glm::mat4 light_projection(const SpotLight &light) {
  return glm::perspective(glm::radians(light.cone_degrees), 1.0f, kLightNearPlane, kLightFarPlane);
}

bool beam_coordinates(const SpotLight &light, const glm::vec3 &world, glm::vec2 &uv) {
  const glm::vec4 view = light_view(light) * glm::vec4(world, 1.0f);
  if (-view.z < kLightNearPlane) return false;
  const glm::vec4 clip = light_projection(light) * view;
  uv = glm::vec2(clip) / clip.w;
  return true;
}

bool is_beam_pattern(const std::string &name) {
  return name == "round" || name == "square" || name == "gobo" || name == "lens";
}

float beam_intensity(const SpotLight &light, const glm::vec2 &uv) {
  if (std::abs(uv.x) >= 1.0f || std::abs(uv.y) >= 1.0f) return 0.0f;
  if (light.beam_image) {
    const glm::vec3 c = sample_projected_image(*light.beam_image, uv);
    return std::clamp(0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b, 0.0f, 1.0f);
  }
  if (light.beam == "round") return round_beam(uv);
  if (light.beam == "square") return square_beam(uv);
  if (light.beam == "gobo") return gobo_beam(uv);
  if (light.beam == "lens") return lens_beam(uv);
  return 0.0f;
}

float axial_distance(const SpotLight &light, const glm::vec3 &world) {
  return -(light_view(light) * glm::vec4(world, 1.0f)).z;
}

float distance_attenuation(const SpotLight &light, float distance) {
  const DistanceAttenuation &a = light.attenuation;
  if (a.mode == AttenuationMode::None) return 1.0f;
  const float d = std::max(distance, 0.0f);
  const float denominator = a.constant + a.linear * d + a.quadratic * d * d;
  return denominator <= 1.0f ? 1.0f : 1.0f / denominator;
}

std::vector<std::uint8_t> beam_texels(const SpotLight &light, int side) {
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(side * side), 0);
  const float size = static_cast<float>(side);
  for (int y = 1; y < side - 1; ++y) {
    for (int x = 1; x < side - 1; ++x) {
      const glm::vec2 uv((static_cast<float>(x) + 0.5f) / size * 2.0f - 1.0f,
                         1.0f - (static_cast<float>(y) + 0.5f) / size * 2.0f);
      texels[static_cast<std::size_t>(y * side + x)] = to_byte(beam_intensity(light, uv));
    }
  }
  return texels;
}

std::vector<std::uint8_t> attenuation_texels(const SpotLight &light, float near_distance,
                                             float far_distance, int width) {
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width));
  for (int i = 0; i < width; ++i) {
    const float d = near_distance + (static_cast<float>(i) + 0.5f) / static_cast<float>(width) *
                                        (far_distance - near_distance);
    texels[static_cast<std::size_t>(i)] = to_byte(distance_attenuation(light, d));
  }
  return texels;
}

}  // namespace gs
