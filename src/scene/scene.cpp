// Small queries on scene objects shared by the techniques.
#include "scene/scene.h"

#include <algorithm>
#include <cmath>

namespace gs {

const Mesh &caster_mesh(const SceneObject &object) {
  return object.shadow_mesh.triangles.empty() ? object.mesh : object.shadow_mesh;
}

Sphere caster_bounds(const SceneObject &object) {
  const Mesh &mesh = caster_mesh(object);
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (const glm::vec3 &p : mesh.positions) {
    const glm::vec3 world = glm::vec3(object.model_to_world * glm::vec4(p, 1.0f));
    low = glm::min(low, world);
    high = glm::max(high, world);
  }
  Sphere sphere{(low + high) * 0.5f, 0.0f};
  for (const glm::vec3 &p : mesh.positions) {
    const glm::vec3 world = glm::vec3(object.model_to_world * glm::vec4(p, 1.0f));
    sphere.radius = std::max(sphere.radius, glm::length(world - sphere.centre));
  }
  return sphere;
}

}  // namespace gs
