// The mask passes' receivers drawn triangle by triangle: each triangle's corners unshared, with
// alpha 1 where the triangle's own plane faces the light and 0 where it faces away. The one
// definition of shadow counts only points whose surface faces the light, and the ground truth
// decides that per face; per-vertex normals, smoothed across a curved body's terminator, would
// call faces that turn away "facing" and let the caster's own far side be reported as shadow.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace gs {

struct FacingTriangles {
  std::vector<glm::vec3> position;  // three per triangle, in the space of the positions given
  std::vector<glm::vec4> color;     // white, alpha 1 (faces the light) or 0
};

// `positions` and `light` in one space (world, or world relative to a camera origin); the
// triangles counter-clockwise seen from outside. Triangles with an index out of range are left out.
FacingTriangles facing_triangles(const std::vector<glm::vec3> &positions,
                                 const std::vector<glm::uvec3> &triangles, const glm::vec3 &light);

}  // namespace gs
