// Internal to the stencil-volume technique: a closed caster in world space and the builder of
// its shadow volumes (stencil_volume_geometry.cpp), which the passes in stencil_volume_shadow.cpp
// count. Spaces: world (the casters' positions, the light); homogeneous world relative to an
// origin, w = 0 for points at infinity (the volumes' vertices).
#pragma once

#include "techniques/geometry/edge_mesh.h"
#include "techniques/stencil_volume/stencil_volume_shadow.h"

#include <glm/glm.hpp>

#include <vector>

namespace gs::stencil_volume {

// A closed caster, welded, in world space.
struct Caster {
  EdgeMesh mesh;
  std::vector<glm::vec3> world;  // per EdgeMesh position
};

// Every caster's shadow volume from a point light at `light`, as outward-facing triangles in
// homogeneous world coordinates relative to `origin`: the silhouette extruded to infinity and,
// for z-fail, closed by the triangles facing away from the light, turned round where they are
// (near cap) and sent to infinity (far cap).
void build_volumes(const std::vector<Caster> &casters, const glm::vec3 &light,
                   const glm::vec3 &origin, bool caps, std::vector<glm::vec4> &out);

}  // namespace gs::stencil_volume
