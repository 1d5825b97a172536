// clip_to_beam (light_beam.h) against the plain algorithm it must equal: every vertex tested
// against all of the beam's outer planes and the margin plane, and every triangle not wholly
// inside clipped by all of them in order. clip_to_beam leaves out the planes the mesh's bounding
// sphere clears; these meshes inside, across, beside and in front of the beam check that doing
// so gives the very same points (world space), bit for bit.
#include "scene/mesh.h"
#include "scene/scene.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

std::vector<glm::vec3> every_plane_clip(const std::vector<glm::vec3> &world,
                                        const std::vector<glm::uvec3> &triangles,
                                        const gs::LightBeam &beam, float margin, bool &whole) {
  std::vector<glm::vec4> planes = beam.outer;
  planes.emplace_back(beam.axis, -glm::dot(beam.axis, beam.position) - margin);
  std::vector<bool> inside(world.size());
  whole = true;
  for (std::size_t i = 0; i < world.size(); ++i) {
    inside[i] = gs::inside_planes(planes, world[i]);
    whole = whole && inside[i];
  }
  if (whole) return world;
  std::vector<glm::vec3> points;
  std::vector<gs::ClipVertex> polygon, scratch;
  for (const glm::uvec3 &t : triangles) {
    if (inside[t.x] && inside[t.y] && inside[t.z]) {
      points.insert(points.end(), {world[t.x], world[t.y], world[t.z]});
      continue;
    }
    polygon.clear();
    for (unsigned i : {t.x, t.y, t.z}) polygon.push_back({glm::vec4(world[i], 1.0f), world[i], {}});
    for (const glm::vec4 &plane : planes) {
      gs::clip_polygon(polygon, plane, scratch);
      if (polygon.size() < 3) break;
    }
    if (polygon.size() < 3) continue;
    for (const gs::ClipVertex &v : polygon) points.push_back(v.world);
  }
  return points;
}

// A sphere of `radius` around `centre` (world), as a caster's vertices and triangles.
void expect_same_as_every_plane(const gs::SpotLight &light, const glm::vec3 &centre, float radius,
                                float margin, const std::string &what, bool expect_whole) {
  const gs::Mesh sphere = gs::make_sphere(radius, 24, 12);
  std::vector<glm::vec3> world;
  for (const glm::vec3 &p : sphere.positions) world.push_back(p + centre);
  const gs::LightBeam beam = gs::light_beam(light);
  bool whole = false, expected_whole = false;
  const std::vector<glm::vec3> points = gs::clip_to_beam(world, sphere.triangles, beam, margin, whole);
  const std::vector<glm::vec3> expected =
      every_plane_clip(world, sphere.triangles, beam, margin, expected_whole);
  EXPECT_EQ(whole, expected_whole) << what;
  EXPECT_EQ(whole, expect_whole) << what << ": the case no longer tests what it names";
  ASSERT_EQ(points.size(), expected.size()) << what;
  std::size_t differing = 0;
  for (std::size_t i = 0; i < points.size(); ++i) differing += points[i] != expected[i];
  EXPECT_EQ(differing, 0u) << what << ": points that differ";
}

gs::SpotLight light_looking_down(const std::string &beam) {
  gs::SpotLight light;
  light.position = {0.0f, 5.0f, 0.0f};
  light.target = {0.0f, 0.0f, 0.0f};
  light.cone_degrees = 60.0f;  // the beam's edge at 45% of the height: 2.89 wide at y = 0
  light.beam = beam;
  return light;
}

TEST(ClipToBeam, EqualsTestingEveryPlane) {
  for (const std::string beam : {"", "square", "gobo"}) {
    const gs::SpotLight light = light_looking_down(beam);
    const std::string name = beam.empty() ? "round" : beam;
    expect_same_as_every_plane(light, {0.2f, 1.0f, -0.1f}, 0.5f, 0.05f, name + ", inside", true);
    expect_same_as_every_plane(light, {2.6f, 0.5f, 0.3f}, 0.6f, 0.05f, name + ", across the side", false);
    expect_same_as_every_plane(light, {2.3f, 0.0f, 2.3f}, 0.8f, 0.05f, name + ", across a corner", false);
    expect_same_as_every_plane(light, {9.0f, 0.5f, 0.0f}, 0.5f, 0.05f, name + ", beside", false);
    expect_same_as_every_plane(light, {0.0f, 4.8f, 0.0f}, 0.5f, 0.05f, name + ", around the light", false);
    expect_same_as_every_plane(light, {0.1f, 3.0f, 0.0f}, 0.5f, 2.2f, name + ", across the margin", false);
  }
}

// surely_holds_triangle: a triangle lies in one lit piece of the beam only when its three corners
// share one. Light 5 m up looking down, 60 degrees: the beam plane's half side is 2.89 m at y = 0
// and a gobo's bars are 0.29 m wide there, along x = 0 and z = 0 (world).
TEST(LightBeamPieces, ATriangleIsSurelyInsideOnlyWithItsCornersInOnePiece) {
  const gs::LightBeam round = gs::light_beam(light_looking_down(""));
  const gs::LightBeam gobo = gs::light_beam(light_looking_down("gobo"));
  const glm::vec3 a(0.5f, 0.0f, 0.5f), b(1.5f, 0.0f, 0.6f), c(0.7f, 0.0f, 1.4f);  // one pane
  const glm::vec3 across(-1.0f, 0.0f, 0.8f);  // the pane beside it, over the bar x = 0
  EXPECT_TRUE(round.surely_holds_triangle(a, b, c));
  EXPECT_TRUE(round.surely_holds_triangle(a, b, across));
  EXPECT_TRUE(gobo.surely_holds_triangle(a, b, c));
  EXPECT_GE(gobo.region_holding(across), 0);
  EXPECT_NE(gobo.region_holding(across), gobo.region_holding(a));
  EXPECT_FALSE(gobo.surely_holds_triangle(a, b, across)) << "the bar between two panes is unlit";
  EXPECT_EQ(gobo.region_holding({0.0f, 0.0f, 1.0f}), -1) << "a point on the bar";
  EXPECT_EQ(round.region_holding({4.0f, 0.0f, 0.0f}), -1) << "a point beyond the cone";
}

TEST(ClipToBeam, AnEmptyMeshIsWhole) {
  bool whole = false;
  const gs::LightBeam beam = gs::light_beam(light_looking_down(""));
  EXPECT_TRUE(gs::clip_to_beam({}, {}, beam, 0.05f, whole).empty());
  EXPECT_TRUE(whole);
}

}  // namespace
