// A scene moved to its local origin (local_origin.h). Spaces: world and local.
#include "scene/local_origin.h"

#include <cmath>

namespace gs {

glm::vec3 local_origin(const Scene &scene) {
  const glm::vec3 cells = scene.camera.position / kLocalOriginGrid;
  const glm::vec3 origin(std::round(cells.x), std::round(cells.y), std::round(cells.z));
  // A camera off every grid (not finite) keeps the world's origin: nothing to move by.
  if (!std::isfinite(origin.x) || !std::isfinite(origin.y) || !std::isfinite(origin.z))
    return glm::vec3(0.0f);
  return origin * kLocalOriginGrid;
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
