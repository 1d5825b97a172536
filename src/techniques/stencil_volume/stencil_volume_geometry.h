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
  // The camera may see inside it (interior_may_be_seen): the camera within it, or the near
  // plane cutting into it.
  bool inside_seen = false;
};

// Whether the camera may see the inside of a closed caster bounded by `bounds` (world): its
// sphere meets a sphere around the camera position and the near-plane rectangle. Elsewhere back
// faces are culled and the caster's own front faces hide all it holds.
bool interior_may_be_seen(const Scene &scene, const Sphere &bounds);

// Every caster's shadow volume from a point light at `light`, as outward-facing triangles in
// homogeneous world coordinates relative to `origin`: the silhouette extruded to infinity and,
// for z-fail, closed by a near cap and, at infinity, the triangles facing away from the light
// (far cap). The near cap is those triangles turned round where they are, so the volume starts
// at the caster's dark side; but for a caster whose inside is seen and which does not surround
// the light, it is the light-facing triangles, so the volume holds the caster's inside too.
void build_volumes(const std::vector<Caster> &casters, const glm::vec3 &light,
                   const glm::vec3 &origin, bool caps, std::vector<glm::vec4> &out);

}  // namespace gs::stencil_volume
