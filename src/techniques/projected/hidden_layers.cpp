// The hidden layers of a masked receiver (hidden_layers.h). Light clip space throughout: the
// receiver's world vertices times the texture's LightView::projection * view.
#include "techniques/projected/hidden_layers.h"

#include "techniques/projected/caster_surface_from_light.h"

#include <algorithm>

namespace gs {

std::vector<std::uint8_t> hidden_layers(const ProjectedObject &receiver, const LightView &view,
                                        CasterSurfacesFromLight &surfaces) {
  const glm::mat4 light_clip = view.projection * view.view;
  const SceneObject &object = *receiver.object;
  const std::vector<glm::uvec3> &triangles = object.mesh.triangles;
  // The same surfaces step 3 asks (receiver_coords.cpp): answers are shared.
  const float nearest_w = std::max(view.caster_front, 1e-6f);
  const CasterSurfaceFromLight &own = surfaces.receiver_at(object, light_clip, nearest_w);
  const CasterSurfaceFromLight &caster = surfaces.at(light_clip);
  std::vector<glm::vec4> clip(receiver.world.size());
  std::vector<unsigned> outside(receiver.world.size());
  for (std::size_t i = 0; i < clip.size(); ++i) {
    const glm::vec4 &p = clip[i] = light_clip * glm::vec4(receiver.world[i], 1.0f);
    outside[i] = (p.x < -p.w) | (p.x > p.w) << 1 | (p.y < -p.w) << 2 | (p.y > p.w) << 3 |
                 (p.w < view.caster_front) << 4;
  }
  std::vector<std::uint8_t> layers(triangles.size(), kNotHidden);
  Mesh hidden;  // the hidden triangles alone, the receiver's model space
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    const glm::uvec3 &t = triangles[k];
    if ((outside[t.x] & outside[t.y] & outside[t.z]) != 0) continue;
    const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
    if (glm::dot(glm::cross(b - a, c - a), view.position - a) <= 0.0f) continue;  // faces away
    const glm::vec4 corners[3] = {clip[t.x], clip[t.y], clip[t.z]};
    if (!own.may_shadow_triangle(object, k, corners)) continue;
    layers[k] = kHiddenOnce;
    hidden.triangles.push_back(t);
  }
  if (hidden.triangles.empty()) return {};
  hidden.positions = object.mesh.positions;
  const CasterSurfaceFromLight hiding(hidden, object.model_to_world, light_clip, nearest_w);
  bool twice = false, shaded_once = false;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    if (layers[k] == kNotHidden) continue;
    const glm::uvec3 &t = triangles[k];
    const glm::vec4 corners[3] = {clip[t.x], clip[t.y], clip[t.z]};
    if (hiding.may_shadow_triangle(object, k, corners)) {
      layers[k] = kHiddenTwice, twice = true;
    } else {
      shaded_once = shaded_once || caster.may_shadow_triangle(object, k, corners);
    }
  }
  if (!twice || !shaded_once) return {};
  return layers;
}

}  // namespace gs
