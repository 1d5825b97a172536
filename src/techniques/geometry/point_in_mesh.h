// Whether a closed mesh surrounds a point (the generalised winding number: the solid angle its
// triangles subtend at the point, over 4 pi). The planar technique asks it of a light inside a
// closed caster, whose light-facing triangles are then none of its shadow.
#pragma once

#include <glm/glm.hpp>

#include <vector>

namespace gs {

// `positions` and `point` in one space (world); triangles counter-clockwise seen from outside.
// True when the winding number is above 1/2: the point is inside the closed surface. A point on
// the surface counts as inside or outside by rounding; for an open surface the answer is whether
// it mostly wraps the point. Triangles with an index out of range are left out.
bool mesh_surrounds(const std::vector<glm::vec3> &positions,
                    const std::vector<glm::uvec3> &triangles, const glm::vec3 &point);

}  // namespace gs
