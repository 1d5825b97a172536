// Planar receivers a caster reaches through (a post through a floor, a ball sunk into it): the
// part of the caster beyond the receiver's plane, seen from the light, is behind the receiver
// and casts nothing on it, but a texture of the whole caster would project it onto the receiver
// all the same. The projected technique gives each such pair a texture of the caster clipped to
// the light's side of the plane (projected_shadow.cpp); docs/results.md measures its cost.
#pragma once

#include "techniques/scene_pass.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <vector>

namespace gs {

struct PiercedReceiver {
  std::size_t receiver = 0;  // index into scene.objects
  glm::vec4 plane{0.0f};     // world space, dot(plane, (p, 1)) > 0 on the light's side
  bool casts = false;        // some of the caster lies on the light's side of the plane
};

// The receivers of `caster`'s shadow from the light at `light_position` (world) whose vertices
// all lie in one plane (within 1e-5 of their extent) with the light off it, and which the
// caster reaches beyond by more than 1e-4 of its own size: a vertex of it on the far side of
// the plane from the light.
std::vector<PiercedReceiver> pierced_planar_receivers(const Scene &scene, const FrameGeometry &frame,
                                                      std::size_t caster,
                                                      const glm::vec3 &light_position);

}  // namespace gs
