// The distance from a point to a triangle: to its plane when the point's foot falls inside it,
// otherwise to the nearest of its three edges. Space: whatever the caller's (world).
#include "techniques/planar/triangle_distance.h"

#include <algorithm>
#include <cmath>

namespace gs {
namespace {

float distance_to_segment(const glm::vec3 &p, const glm::vec3 &a, const glm::vec3 &b) {
  const glm::vec3 ab = b - a;
  const float length2 = glm::dot(ab, ab);
  const float t = length2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / length2, 0.0f, 1.0f) : 0.0f;
  return glm::length(p - (a + ab * t));
}

}  // namespace

float distance_to_triangle(const glm::vec3 &point, const glm::vec3 &a, const glm::vec3 &b,
                           const glm::vec3 &c) {
  const glm::vec3 normal = glm::cross(b - a, c - a);
  const float area2 = glm::dot(normal, normal);
  if (area2 > 0.0f) {
    // The foot is inside when it lies on the inner side of all three edges (seen along normal).
    const bool inside = glm::dot(glm::cross(b - a, point - a), normal) >= 0.0f &&
                        glm::dot(glm::cross(c - b, point - b), normal) >= 0.0f &&
                        glm::dot(glm::cross(a - c, point - c), normal) >= 0.0f;
    if (inside) return std::abs(glm::dot(point - a, normal)) / std::sqrt(area2);
  }
  return std::min({distance_to_segment(point, a, b), distance_to_segment(point, b, c),
                   distance_to_segment(point, c, a)});
}

}  // namespace gs
