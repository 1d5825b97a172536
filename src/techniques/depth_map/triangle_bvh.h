// Internal to the depth map's replay beside casters' feet (depth_map_contacts.cpp): triangles
// (world, double) in a bounding-volume hierarchy, so that a ray or segment tests only the
// triangles whose boxes it passes near, with the same Möller–Trumbore test in double it made
// against every triangle before (so every hit, and every decision made from hits, is unchanged).
#pragma once

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gs::depth_map {

// Whether the ray o + t d meets the triangle a, b, c (both sides; world, any common space); `t`:
// the parameter of the hit, in units of d. The test the replay always made (Möller–Trumbore in
// double, corners inclusive), so the BVH and a plain loop agree hit for hit.
bool ray_meets_triangle(const glm::dvec3 &o, const glm::dvec3 &d, const glm::dvec3 &a,
                        const glm::dvec3 &b, const glm::dvec3 &c, double &t);

// Written by hand rather than with Embree (a dependency of measure/, whose BVH the truth uses):
// the replay's decisions (the depth map's refusals) hang on hits at the very edges of triangles
// (a caster's foot on its receiver), which Embree's single-precision watertight test places
// otherwise than the double test above; used only to find candidates, Embree would need its
// rays in float and padded user-geometry bounds, and would bring a dependency into techniques/,
// which uses only scene and the shim (src/README.md).
class TriangleBvh {
 public:
  TriangleBvh() = default;
  // `corners`: three a triangle (world); triangle k is corners 3k .. 3k + 2.
  explicit TriangleBvh(std::vector<glm::dvec3> corners);

  // The nearest hit with a parameter in (low, high), as a loop over the triangles in order finds
  // it (the first triangle of those at the least parameter); `high` becomes its parameter and
  // `hit` its triangle. False (both untouched) when there is none.
  bool nearest(const glm::dvec3 &o, const glm::dvec3 &d, double low, double &high,
               std::size_t &hit) const;
  // Whether any triangle is met with a parameter in (low, high); with `facing_only`, only one
  // whose winding faces back along d (cross(b - a, c - a) . d < 0): what a camera at the ray's
  // origin sees, as the scene pass culls back faces and the truth's camera rays drop them.
  bool any(const glm::dvec3 &o, const glm::dvec3 &d, double low, double high,
           bool facing_only = false) const;

 private:
  // A node's box (world, padded by pad_); a leaf holds order_[first .. first + count), an inner
  // node (count 0) has its children at the next index and at `first`.
  struct Node {
    glm::dvec3 low, high;
    std::uint32_t first = 0, count = 0;
  };
  std::uint32_t build(std::uint32_t begin, std::uint32_t end);
  // Whether the ray o + t d (1 / d given, per axis) passes the node's box for some t in
  // [from, to]; `entry`: the least such t.
  bool passes(const Node &node, const glm::dvec3 &o, const glm::dvec3 &d,
              const glm::dvec3 &inverse, double from, double to, double &entry) const;
  bool meets(std::uint32_t triangle, const glm::dvec3 &o, const glm::dvec3 &d, double &t) const;

  std::vector<glm::dvec3> corners_;
  std::vector<glm::dvec3> centres_;  // each triangle's box centre (world), for the build
  std::vector<std::uint32_t> order_;
  std::vector<Node> nodes_;
  double pad_ = 0.0;  // metres (world)
};

}  // namespace gs::depth_map
