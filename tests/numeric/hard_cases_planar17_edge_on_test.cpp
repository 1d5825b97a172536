// Issue 14: the planar technique's projection onto a plane passing by the light. A fighter
// triangle whose plane passes 0.14 mm from a light 4.7 m away (the eleventh audit's near_17030,
// light 2) got a NaN vertex from the cut below the light and the projection in float, and the
// shim dropped the triangle; both now run in double on an exact plane (planar_casting.cpp).
// Scene in tests/hard_cases/audit (planar17_fighter_edge_on_to_light; tests/hard_cases/README.md).
#include "hard_case_checks.h"

#include <gtest/gtest.h>

#include <string>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// No non-finite vertex reaches the shim, and the frame is right.
TEST(HardCases, PlanarOnATriangleEdgeOnToTheLightSendsFiniteVertices) {
  const std::string file = "audit/planar17_fighter_edge_on_to_light.json";
  const gs::Scene scene = load(file);
  const Truth truth = truth_of(scene);
  const Outcome o = run("planar", scene, truth);
  report(file + " planar", o);
  expect_clean_glide("planar", o);
  EXPECT_TRUE(o.refusals.empty());
  EXPECT_LE(o.errors.false_shadow_interior + o.errors.false_light_interior, kInteriorBudget);
}

}  // namespace
