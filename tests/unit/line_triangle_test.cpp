// line_meets_triangle (geometry/line_triangle.h): hits inside, on the edges and corners, misses
// outside and along the plane, the parameter t on either side of the origin, the side a, a + e1
// left out by a least weight of a + e2, and a millimetre triangle met where an absolute
// determinant bound (glm::intersectRayTriangle's) would call the line parallel.
#include "techniques/geometry/line_triangle.h"

#define GLM_ENABLE_EXPERIMENTAL  // glm/gtx: GLM's own test, for the comparison below
#include <glm/glm.hpp>
#include <glm/gtx/intersect.hpp>
#include <gtest/gtest.h>

namespace {

// The triangle (0,0,0), (1,0,0), (0,1,0) in the plane z = 0, crossed by vertical lines.
const glm::vec3 kA(0.0f), kE1(1.0f, 0.0f, 0.0f), kE2(0.0f, 1.0f, 0.0f);

bool down_through(float x, float y, float &t) {
  return gs::line_meets_triangle(glm::vec3(x, y, 2.0f), glm::vec3(0.0f, 0.0f, -1.0f), kA, kE1,
                                 kE2, t);
}

TEST(LineTriangle, MeetsInsideAtTheParameterOfThePlane) {
  float t = 0.0f;
  ASSERT_TRUE(down_through(0.25f, 0.25f, t));
  EXPECT_FLOAT_EQ(t, 2.0f);
  // Pointed away: the same line, so a hit behind the origin, t < 0 for the caller to bound.
  ASSERT_TRUE(gs::line_meets_triangle(glm::vec3(0.25f, 0.25f, 2.0f), glm::vec3(0.0f, 0.0f, 1.0f),
                                      kA, kE1, kE2, t));
  EXPECT_FLOAT_EQ(t, -2.0f);
}

TEST(LineTriangle, EdgesAndCornersAreIncludedAndOutsideIsMissed) {
  float t = 0.0f;
  EXPECT_TRUE(down_through(0.0f, 0.0f, t));    // corner a
  EXPECT_TRUE(down_through(0.5f, 0.0f, t));    // side a, a + e1
  EXPECT_TRUE(down_through(0.5f, 0.5f, t));    // side a + e1, a + e2
  EXPECT_FALSE(down_through(-0.01f, 0.5f, t));
  EXPECT_FALSE(down_through(0.6f, 0.6f, t));
  EXPECT_FALSE(down_through(0.5f, -0.01f, t));
}

TEST(LineTriangle, ALineInOrAlongThePlaneMeetsNothing) {
  float t = 0.0f;
  EXPECT_FALSE(gs::line_meets_triangle(glm::vec3(0.2f, 0.2f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f),
                                       kA, kE1, kE2, t));
  EXPECT_FALSE(gs::line_meets_triangle(glm::vec3(0.2f, 0.2f, 1.0f), glm::vec3(0.0f, 1.0f, 0.0f),
                                       kA, kE1, kE2, t));
  // A nearly parallel line meets it unless the caller's bound calls it parallel.
  const glm::vec3 origin(0.25f, 0.25f - 1e3f, 1e-3f), grazing(0.0f, 1.0f, -1e-6f);
  EXPECT_TRUE(gs::line_meets_triangle(origin, grazing, kA, kE1, kE2, t));
  EXPECT_FALSE(gs::line_meets_triangle(origin, grazing, kA, kE1, kE2, t, 1e-5f));
}

TEST(LineTriangle, ALeastWeightOfTheThirdCornerLeavesOutTheFirstSide) {
  float t = 0.0f;
  const glm::vec3 down(0.0f, 0.0f, -1.0f);
  EXPECT_FALSE(gs::line_meets_triangle(glm::vec3(0.5f, 0.0005f, 1.0f), down, kA, kE1, kE2, t,
                                       0.0f, 1e-3f));
  EXPECT_TRUE(gs::line_meets_triangle(glm::vec3(0.5f, 0.002f, 1.0f), down, kA, kE1, kE2, t, 0.0f,
                                      1e-3f));
}

TEST(LineTriangle, DoubleAgreesWithFloatOnTheSameLine) {
  double td = 0.0;
  float tf = 0.0f;
  ASSERT_TRUE(gs::line_meets_triangle(glm::dvec3(0.3, 0.1, -4.0), glm::dvec3(0.0, 0.0, 2.0),
                                      glm::dvec3(kA), glm::dvec3(kE1), glm::dvec3(kE2), td));
  ASSERT_TRUE(gs::line_meets_triangle(glm::vec3(0.3f, 0.1f, -4.0f), glm::vec3(0.0f, 0.0f, 2.0f),
                                      kA, kE1, kE2, tf));
  EXPECT_DOUBLE_EQ(td, 2.0);
  EXPECT_FLOAT_EQ(tf, 2.0f);
}

// Why the test is written out: a face of a millimetre on a side, seen from a metre, has a
// determinant of about 1e-6 * 1 m, under float's epsilon; GLM's test calls that parallel.
TEST(LineTriangle, AMillimetreTriangleIsMetWhereGlmCallsItParallel) {
  const glm::vec3 a(0.0f), e1(1e-3f, 0.0f, 0.0f), e2(0.0f, 1e-3f, 0.0f);
  const glm::vec3 origin(2.5e-4f, 2.5e-4f, 0.1f), direction(0.0f, 0.0f, -0.1f);
  float t = 0.0f;
  ASSERT_TRUE(gs::line_meets_triangle(origin, direction, a, e1, e2, t));
  EXPECT_FLOAT_EQ(t, 1.0f);
  glm::vec2 weights(0.0f);
  float distance = 0.0f;
  EXPECT_FALSE(glm::intersectRayTriangle(origin, direction, a, a + e1, a + e2, weights, distance));
}

}  // namespace
