// The depth map replay's triangle hierarchy (techniques/depth_map/triangle_bvh.h) answers as a loop over
// every triangle in order does: the same nearest hit (parameter and triangle, the first of those
// tied), and the same answer to whether a segment meets any. Space: world, metres.
#include "techniques/depth_map/triangle_bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <random>
#include <vector>

namespace {

using glm::dvec3;
using gs::depth_map::TriangleBvh;

struct LoopHit {
  bool found = false;
  double t = 0.0;
  std::size_t triangle = 0;
};

// The replay's loop before the hierarchy: every triangle in order, the first at the least t.
LoopHit loop_nearest(const std::vector<dvec3> &corners, const dvec3 &o, const dvec3 &d,
                     double low, double high) {
  LoopHit hit;
  for (std::size_t k = 0; k + 2 < corners.size(); k += 3) {
    double t = 0.0;
    if (gs::depth_map::ray_meets_triangle(o, d, corners[k], corners[k + 1], corners[k + 2], t) &&
        t > low && t < high) {
      high = t, hit = {true, t, k / 3};
    }
  }
  return hit;
}

// 600 triangles of 0.05 to 1 m in a 10 m box off the origin, every tenth one repeated at the end
// (hits tied in t, won by the earlier copy), and floor-like pairs sharing edges.
std::vector<dvec3> scattered_triangles() {
  std::mt19937 random(14);
  std::uniform_real_distribution<double> place(-5.0, 5.0), size(0.05, 1.0), unit(-1.0, 1.0);
  std::vector<dvec3> corners;
  for (int k = 0; k < 600; ++k) {
    const dvec3 at = dvec3(place(random), place(random), place(random)) + dvec3(20.0, 1.0, -3.0);
    const double s = size(random);
    corners.push_back(at);
    corners.push_back(at + s * dvec3(unit(random), unit(random), unit(random)));
    corners.push_back(at + s * dvec3(unit(random), unit(random), unit(random)));
  }
  for (int x = 0; x < 4; ++x) {  // a 4 x 4 m floor at y = 0, two triangles a square metre
    for (int z = 0; z < 4; ++z) {
      const dvec3 a(18.0 + x, 0.0, -5.0 + z), b = a + dvec3(1, 0, 0), c = a + dvec3(1, 0, 1),
                  e = a + dvec3(0, 0, 1);
      corners.insert(corners.end(), {a, b, c, a, c, e});
    }
  }
  const std::size_t original = corners.size();
  for (std::size_t k = 0; k < original; k += 30) {
    corners.insert(corners.end(), corners.begin() + static_cast<long>(k),
                   corners.begin() + static_cast<long>(k + 3));
  }
  return corners;
}

TEST(TriangleBvh, NearestHitIsTheLoopsOnRandomRaysAndRaysThroughCornersAndEdges) {
  const std::vector<dvec3> corners = scattered_triangles();
  const TriangleBvh bvh(corners);
  std::mt19937 random(41);
  std::uniform_real_distribution<double> place(-8.0, 8.0), weight(0.0, 1.0);
  std::uniform_int_distribution<std::size_t> corner(0, corners.size() - 1);
  int hits = 0, rays = 0;
  for (int k = 0; k < 4000; ++k) {
    const dvec3 o = dvec3(place(random), place(random), place(random)) + dvec3(20.0, 1.0, -3.0);
    // Aimed at a corner, at a point on an edge, or inside a triangle, or nowhere in particular.
    const std::size_t c = corner(random), first = c - c % 3;
    const dvec3 &a = corners[first + (c + 1) % 3], &b = corners[c];
    const double w = weight(random);
    const dvec3 target = k % 4 == 0   ? b
                         : k % 4 == 1 ? a + (b - a) * w
                         : k % 4 == 2 ? (corners[first] + corners[first + 1] + corners[first + 2]) / 3.0
                                      : o + dvec3(place(random), place(random), place(random));
    const dvec3 d = target - o;
    for (const double high : {static_cast<double>(INFINITY), 1.0 - 1e-5}) {
      const LoopHit expected = loop_nearest(corners, o, d, 1e-9, high);
      double t = high;
      std::size_t triangle = 0;
      const bool found = bvh.nearest(o, d, 1e-9, t, triangle);
      ASSERT_EQ(found, expected.found) << "ray " << k;
      ++rays;
      if (!found) continue;
      ++hits;
      EXPECT_EQ(t, expected.t) << "ray " << k;
      EXPECT_EQ(triangle, expected.triangle) << "ray " << k;
      EXPECT_EQ(bvh.any(o, d, 1e-9, high), true) << "ray " << k;
    }
    EXPECT_EQ(bvh.any(o, d, 1e-9, 1.0 - 1e-5), loop_nearest(corners, o, d, 1e-9, 1.0 - 1e-5).found)
        << "ray " << k;
  }
  // The rays are no empty sample: most of those aimed at triangles hit one.
  EXPECT_GT(hits, rays / 3);
}

// Two floor triangles sharing the edge x = 1 (triangle 0 right of it, 1 left), with eight more
// between them by x but 5 m away in z, so that the two fall in different parts of the hierarchy
// and the left one (later in the list) is met first: a ray down through the shared edge meets
// both at t = 0.5, and the loop's answer is the earlier triangle, 0.
TEST(TriangleBvh, TiedHitsGoToTheEarlierTriangle) {
  std::vector<dvec3> corners = {dvec3(1, 0, 0), dvec3(2, 0, 0), dvec3(1, 0, 1),
                                dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(1, 0, 1)};
  for (int k = 0; k < 8; ++k) {
    const dvec3 at(0.6 + 0.1 * k, 0.0, 5.0);
    corners.insert(corners.end(), {at, at + dvec3(0.01, 0, 0), at + dvec3(0, 0, 0.5)});
  }
  const TriangleBvh bvh(corners);
  const dvec3 o(1, 1, 0.25), d(0, -2, 0);
  const LoopHit expected = loop_nearest(corners, o, d, 0.0, INFINITY);
  ASSERT_TRUE(expected.found);
  ASSERT_EQ(expected.triangle, 0u);
  double t = INFINITY;
  std::size_t triangle = 7;
  ASSERT_TRUE(bvh.nearest(o, d, 0.0, t, triangle));
  EXPECT_EQ(t, 0.5);
  EXPECT_EQ(triangle, 0u);
}

TEST(TriangleBvh, NoTrianglesMeansNoHit) {
  const TriangleBvh bvh(std::vector<dvec3>{});
  double t = INFINITY;
  std::size_t triangle = 3;
  EXPECT_FALSE(bvh.nearest(dvec3(0), dvec3(1, 0, 0), 0.0, t, triangle));
  EXPECT_FALSE(bvh.any(dvec3(0), dvec3(1, 0, 0), 0.0, 1.0));
  EXPECT_EQ(t, INFINITY);
  EXPECT_EQ(triangle, 3u);
}

}  // namespace
