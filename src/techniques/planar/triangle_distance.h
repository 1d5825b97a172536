// The distance from a point to a triangle (its nearest point on the face, an edge or a corner).
// The planar technique asks it of the light and each caster triangle: a caster passing a
// millimetre from the light throws its shadow to a thousand times its distance, and the shadow
// polygons keep those parts only when they know how near it passes.
#pragma once

#include <glm/glm.hpp>

namespace gs {

// All four in one space (world); the triangle may be degenerate (then the nearest of its edges).
float distance_to_triangle(const glm::vec3 &point, const glm::vec3 &a, const glm::vec3 &b,
                           const glm::vec3 &c);

}  // namespace gs
