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

constexpr int kNeighbourRings = 2;

std::vector<std::uint8_t> hidden_marked(const ProjectedObject &receiver, const LightView &view,
                                        CasterSurfacesFromLight &surfaces,
                                        const std::vector<std::uint8_t> &marks) {
  const glm::mat4 light_clip = view.projection * view.view;
  const SceneObject &object = *receiver.object;
  const std::vector<glm::uvec3> &triangles = object.mesh.triangles;
  const float nearest_w = std::max(view.caster_front, 1e-6f);
  const CasterSurfaceFromLight *own = nullptr;  // asked as step 3 asks (receiver_coords.cpp)
  std::vector<std::uint8_t> layers;
  Mesh left;  // the marked hidden triangles not yet in a layer, the receiver's model space
  std::vector<glm::vec4> corners;  // light clip, three per triangle in `left`
  std::vector<std::size_t> numbers;  // theirs in the mesh
  for (std::size_t k = 0; k < triangles.size() && k < marks.size(); ++k) {
    if (marks[k] == 0) continue;
    const glm::uvec3 &t = triangles[k];
    const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
    if (glm::dot(glm::cross(b - a, c - a), view.position - a) <= 0.0f) continue;  // faces away
    const glm::vec4 clip[3] = {light_clip * glm::vec4(a, 1.0f), light_clip * glm::vec4(b, 1.0f),
                               light_clip * glm::vec4(c, 1.0f)};
    if (!own) own = &surfaces.receiver_at(object, light_clip, nearest_w);
    if (!own->may_shadow_triangle(object, k, clip)) continue;
    layers.resize(triangles.size(), 0);
    left.triangles.push_back(t);
    corners.insert(corners.end(), clip, clip + 3);
    numbers.push_back(k);
  }
  if (numbers.empty()) return layers;
  left.positions = object.mesh.positions;
  for (std::uint8_t layer = 1; !numbers.empty(); ++layer) {
    if (layer == kMarkedLayers) {
      for (std::size_t k : numbers) layers[k] = layer;
      break;
    }
    // Those of the rest that none of the rest hides (the surface's answers are its own: a
    // fresh surface per layer).
    const CasterSurfaceFromLight hiding(left, object.model_to_world, light_clip, nearest_w);
    Mesh still;
    std::vector<glm::vec4> still_corners;
    std::vector<std::size_t> still_numbers;
    for (std::size_t i = 0; i < numbers.size(); ++i) {
      const glm::vec4 clip[3] = {corners[3 * i], corners[3 * i + 1], corners[3 * i + 2]};
      if (hiding.may_shadow_triangle(object, numbers[i], clip)) {
        still.triangles.push_back(left.triangles[i]);
        still_corners.insert(still_corners.end(), clip, clip + 3);
        still_numbers.push_back(numbers[i]);
      } else {
        layers[numbers[i]] = layer;
      }
    }
    // All hide one another (the surface's answers are unsure): the rest take this layer.
    if (still_numbers.size() == numbers.size()) {
      for (std::size_t k : numbers) layers[k] = layer;
      break;
    }
    left.triangles = std::move(still.triangles);
    corners = std::move(still_corners);
    numbers = std::move(still_numbers);
  }
  // Their neighbours (a corner shared) and theirs, light-facing and in no layer, join every
  // layer's mask.
  std::vector<std::uint8_t> touched(object.mesh.positions.size(), 0);
  for (int ring = 0; ring < kNeighbourRings; ++ring) {
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      if (layers[k] == 0) continue;
      touched[triangles[k].x] = touched[triangles[k].y] = touched[triangles[k].z] = 1;
    }
    for (std::size_t k = 0; k < triangles.size(); ++k) {
      const glm::uvec3 &t = triangles[k];
      if (layers[k] != 0 || (touched[t.x] | touched[t.y] | touched[t.z]) == 0) continue;
      const glm::vec3 &a = receiver.world[t.x], &b = receiver.world[t.y], &c = receiver.world[t.z];
      if (glm::dot(glm::cross(b - a, c - a), view.position - a) <= 0.0f) continue;  // faces away
      layers[k] = kMarkedNeighbour;
    }
  }
  return layers;
}

MarkedPasses marked_passes(const ProjectedObject &receiver, const LightView &view,
                           CasterSurfacesFromLight &surfaces,
                           const std::vector<std::uint8_t> &marks) {
  MarkedPasses passes;
  passes.marked = hidden_marked(receiver, view, surfaces, marks);
  if (passes.marked.empty()) return passes;
  passes.band_one_marks = marks;
  for (std::size_t k = 0; k < passes.marked.size() && k < marks.size(); ++k) {
    const std::uint8_t layer = passes.marked[k];
    if (layer == 0 || layer == kMarkedNeighbour) continue;
    passes.band_one_marks[k] = 0;
    passes.layers = std::max(passes.layers, static_cast<int>(layer));
  }
  return passes;
}

void MarkedPasses::layer_pass(int layer) {
  taken.assign(marked.size(), 0), masking.assign(marked.size(), 0);
  for (std::size_t k = 0; k < marked.size(); ++k) {
    taken[k] = marked[k] == layer;
    masking[k] = marked[k] >= layer;  // kMarkedNeighbour's too
  }
}

}  // namespace gs
