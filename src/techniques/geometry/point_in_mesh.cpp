// The generalised winding number of a mesh at a point (point_in_mesh.h): each triangle's signed
// solid angle by Van Oosterom and Strackee's formula, summed in double. Space: the caller's
// (world): only directions from the point are used.
#include "techniques/geometry/point_in_mesh.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace gs {

bool mesh_surrounds(const std::vector<glm::vec3> &positions,
                    const std::vector<glm::uvec3> &triangles, const glm::vec3 &point) {
  const std::size_t n = positions.size();
  const glm::dvec3 origin(point);
  double solid_angle = 0.0;
  for (const glm::uvec3 &t : triangles) {
    if (t.x >= n || t.y >= n || t.z >= n) continue;
    // Corners relative to the point; a triangle whose outward normal points away from the point
    // (the point behind it, as inside a closed surface) counts positive.
    const glm::dvec3 a = glm::dvec3(positions[t.x]) - origin;
    const glm::dvec3 b = glm::dvec3(positions[t.y]) - origin;
    const glm::dvec3 c = glm::dvec3(positions[t.z]) - origin;
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double numerator = glm::dot(a, glm::cross(b, c));
    const double denominator =
        la * lb * lc + glm::dot(a, b) * lc + glm::dot(b, c) * la + glm::dot(c, a) * lb;
    solid_angle += 2.0 * std::atan2(numerator, denominator);
  }
  return solid_angle / (4.0 * glm::pi<double>()) > 0.5;
}

}  // namespace gs
