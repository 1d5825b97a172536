// A scene moved to its local origin (local_origin.h). Spaces: world and local.
#include "scene/local_origin.h"

#include <algorithm>
#include <cmath>

namespace gs {

glm::vec3 local_origin(const Scene &scene) {
  glm::vec3 low(INFINITY), high(-INFINITY);  // world
  auto take = [&](const glm::vec3 &p) {
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
      low = glm::min(low, p), high = glm::max(high, p);
  };
  take(scene.camera.position);
  for (const SceneObject &object : scene.objects) {
    for (const glm::vec3 &p : object.mesh.positions)
      take(glm::vec3(object.model_to_world * glm::vec4(p, 1.0f)));
  }
  const glm::vec3 sides = high - low;
  const float widest = std::max({sides.x, sides.y, sides.z});
  if (!(widest > 0.0f) || !std::isfinite(widest)) return glm::vec3(0.0f);
  const float grid = std::exp2(std::ceil(std::log2(2.0f * widest)));  // metres
  if (!std::isfinite(grid)) return glm::vec3(0.0f);
  const glm::vec3 cells = (0.5f * (low + high)) / grid;
  const glm::vec3 origin(std::round(cells.x), std::round(cells.y), std::round(cells.z));
  return origin * grid;
}

const Scene &in_local_coordinates(const Scene &scene, Scene &storage) {
  const glm::vec3 origin = local_origin(scene);
  if (origin == glm::vec3(0.0f)) return scene;
  storage = scene;
  for (SceneObject &object : storage.objects) {
    // The translation column: model to local is model to world, then minus the origin.
    object.model_to_world[3] -= glm::vec4(origin, 0.0f);
  }
  for (SpotLight &light : storage.lights) {
    light.position -= origin;
    light.target -= origin;
  }
  storage.camera.position -= origin;
  storage.camera.target -= origin;
  return storage;
}

}  // namespace gs
