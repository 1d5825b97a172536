// Receivers unshared per triangle with a per-face facing alpha (facing_triangles.h). Spaces:
// whatever space the caller's positions and light share; only the sign of the facing is used.
#include "techniques/plain_gl/facing_triangles.h"

namespace gs {

FacingTriangles facing_triangles(const std::vector<glm::vec3> &positions,
                                 const std::vector<glm::uvec3> &triangles, const glm::vec3 &light) {
  FacingTriangles out;
  out.position.reserve(triangles.size() * 3);
  out.color.reserve(triangles.size() * 3);
  const std::size_t n = positions.size();
  for (const glm::uvec3 &t : triangles) {
    if (t.x >= n || t.y >= n || t.z >= n) continue;
    const glm::vec3 &a = positions[t.x], &b = positions[t.y], &c = positions[t.z];
    // As the truth decides it: the face's outward normal against the direction to the light
    // (edge-on counts as facing away).
    const bool faces = glm::dot(glm::cross(b - a, c - a), light - a) > 0.0f;
    const glm::vec4 color(1.0f, 1.0f, 1.0f, faces ? 1.0f : 0.0f);
    out.position.insert(out.position.end(), {a, b, c});
    out.color.insert(out.color.end(), {color, color, color});
  }
  return out;
}

}  // namespace gs
