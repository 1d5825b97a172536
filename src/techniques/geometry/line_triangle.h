// Where a line meets a triangle (Möller and Trumbore, 1997): the one test behind the techniques'
// occlusion rays (a shadow edge hidden from the camera by its caster, a point seen through a
// caster's face, the depth map's replay). Any common space; the techniques call it in world
// space, in float or in double.
//
// Written out rather than taken from glm::intersectRayTriangle: GLM calls a triangle parallel
// to the line when the determinant is under the type's epsilon, an absolute bound, so a small
// triangle in a small scene (millimetre-sized faces, the scale sweep's scenes) would never be
// met. Here the caller says what counts as parallel.
#pragma once

#include <glm/glm.hpp>

#include <cmath>

namespace gs {

// Whether the line origin + t * direction meets the triangle a, a + e1, a + e2, its edges
// included, and if so `t`, in units of `direction` (either sign: the caller bounds it).
// - `parallel_at_most`: a determinant (the volume of direction, e1 and e2) of at most this size
//   is a line in the triangle's plane or parallel to it, which meets nothing.
// - `least_e2_weight`: the least barycentric weight of the corner a + e2 a hit may have; above 0
//   it leaves out hits along the side a, a + e1 (a shadow edge seen along its caster's face).
template <typename T>
bool line_meets_triangle(const glm::vec<3, T> &origin, const glm::vec<3, T> &direction,
                         const glm::vec<3, T> &a, const glm::vec<3, T> &e1,
                         const glm::vec<3, T> &e2, T &t, T parallel_at_most = T(0),
                         T least_e2_weight = T(0)) {
  const glm::vec<3, T> p = glm::cross(direction, e2);
  const T det = glm::dot(e1, p);
  if (std::abs(det) <= parallel_at_most) return false;
  const glm::vec<3, T> s = origin - a;
  const T u = glm::dot(s, p) / det;  // the weight of a + e1
  if (u < T(0) || u > T(1)) return false;
  const glm::vec<3, T> q = glm::cross(s, e1);
  const T v = glm::dot(direction, q) / det;  // the weight of a + e2
  if (v < least_e2_weight || u + v > T(1)) return false;
  t = glm::dot(e2, q) / det;
  return true;
}

}  // namespace gs
