// Spotlight shading: Lambert diffuse times the beam (a cone factor that falls from 1 to 0 over the
// outer tenth of the cone's half-angle, or the light's beam map) times the distance attenuation.
#include "scene/lighting.h"

#include "scene/spotlight.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace gs {

float spot_factor(const SpotLight &light, const glm::vec3 &world) {
  if (light.has_beam_map()) {
    glm::vec2 uv;
    return beam_coordinates(light, world, uv) ? beam_intensity(light, uv) : 0.0f;
  }
  const glm::vec3 axis = glm::normalize(light.target - light.position);
  const glm::vec3 to_point = world - light.position;
  const float distance = glm::length(to_point);
  if (distance <= 0.0f) return 0.0f;
  const float cos_angle = glm::dot(axis, to_point / distance);
  const float half_angle = glm::radians(light.cone_degrees) * 0.5f;
  const float outer = std::cos(half_angle), inner = std::cos(half_angle * 0.9f);
  return std::clamp((cos_angle - outer) / std::max(inner - outer, 1e-6f), 0.0f, 1.0f);
}

glm::vec3 vertex_light_term(const SpotLight &light, const glm::vec3 &world, const glm::vec3 &normal,
                            bool attenuation_per_pixel) {
  const float facing = glm::dot(normal, glm::normalize(light.position - world));
  // A slide adds its colour where the projector sees the surface, whatever the angle.
  if (light.is_projector()) return facing > 0.0f ? light.color : glm::vec3(0.0f);
  const float diffuse = std::max(0.0f, facing);
  const float beam = light.has_beam_map() ? 1.0f : spot_factor(light, world);
  const float attenuation =
      attenuation_per_pixel ? 1.0f : distance_attenuation(light, axial_distance(light, world));
  return light.color * (diffuse * beam * attenuation);
}

glm::vec3 shade_vertex(const Scene &scene, const glm::vec3 &world, const glm::vec3 &normal,
                       const glm::vec3 &albedo) {
  glm::vec3 light_sum = scene.ambient;
  for (const SpotLight &light : scene.lights) {
    if (light.is_projector()) continue;  // it lights through its slide pass only
    const glm::vec3 to_light = glm::normalize(light.position - world);
    const float diffuse = std::max(0.0f, glm::dot(normal, to_light));
    light_sum += light.color * (diffuse * spot_factor(light, world) *
                                distance_attenuation(light, axial_distance(light, world)));
  }
  return glm::min(albedo * light_sum, glm::vec3(1.0f));
}

}  // namespace gs
