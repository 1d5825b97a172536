// The stencil shadow volume technique on scenes whose answer is known: silhouettes of simple
// shapes, a box's footprint on the floor (against the projected texture's), the camera inside a
// shadow volume (z-fail right, z-pass wrong, the automatic choice z-fail), and an open caster.
#include "scene/fight_scene.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/geometry/edge_mesh.h"
#include "techniques/stencil_volume/stencil_volume_shadow.h"
#include "techniques/technique.h"

#include <glide.h>
#include <glide_shim.h>
#include <gtest/gtest.h>

#include "technique_fixture.h"
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <set>

namespace {


class StencilVolumeShadowTest : public TechniqueTest {
 protected:




  static Mask stencil_mask(const gs::Scene &scene, gs::TechniqueOptions::VolumeMode mode) {
    gs::TechniqueOptions options;
    options.volume_mode = mode;
    return mask_of(*gs::make_stencil_volume_shadow(options), scene);
  }


  static Mask without(const Mask &a, const Mask &b) {
    Mask m(a.size());
    for (std::size_t i = 0; i < a.size(); ++i) m[i] = a[i] && !b[i];
    return m;
  }


};

using Mode = gs::TechniqueOptions::VolumeMode;

TEST(StencilVolumeSilhouette, BoxUnderALightAboveHasTheFourEdgesAroundItsTop) {
  const gs::EdgeMesh box = gs::build_edge_mesh(gs::make_box(glm::vec3(0.5f)));
  ASSERT_TRUE(box.closed);
  EXPECT_EQ(box.positions.size(), 8u) << "the faces' corners are not welded";
  EXPECT_EQ(box.triangles.size(), 12u);
  const std::vector<bool> facing = gs::light_facing(box, box.positions, {0.0f, 8.0f, 0.0f});
  EXPECT_EQ(std::count(facing.begin(), facing.end(), true), 2) << "only the top faces the light";
  const std::vector<gs::SilhouetteEdge> silhouette = gs::find_silhouette(box, facing);
  ASSERT_EQ(silhouette.size(), 4u);
  // One closed loop around the top, walked counter-clockwise seen from the light.
  std::multiset<glm::uint> starts, ends;
  float winding = 0.0f;
  for (const gs::SilhouetteEdge &e : silhouette) {
    EXPECT_EQ(box.positions[e.from].y, 0.5f);
    EXPECT_EQ(box.positions[e.to].y, 0.5f);
    starts.insert(e.from);
    ends.insert(e.to);
    winding += glm::cross(box.positions[e.from], box.positions[e.to]).y;
  }
  EXPECT_EQ(starts, ends);
  EXPECT_EQ(std::set<glm::uint>(starts.begin(), starts.end()).size(), 4u);
  EXPECT_GT(winding, 0.0f);
}

TEST(StencilVolumeSilhouette, SphereUnderAFarLightHasItsEquator) {
  const int slices = 12;
  const gs::EdgeMesh sphere = gs::build_edge_mesh(gs::make_sphere(1.0f, slices, 4));
  ASSERT_TRUE(sphere.closed);
  const std::vector<gs::SilhouetteEdge> silhouette = gs::find_silhouette(
      sphere, gs::light_facing(sphere, sphere.positions, {0.0f, 100.0f, 0.0f}));
  ASSERT_EQ(silhouette.size(), static_cast<std::size_t>(slices));
  for (const gs::SilhouetteEdge &e : silhouette) {
    EXPECT_NEAR(sphere.positions[e.from].y, 0.0f, 1e-6f);
    EXPECT_NEAR(sphere.positions[e.to].y, 0.0f, 1e-6f);
  }
}

TEST(StencilVolumeSilhouette, ClosedAndOpenMeshesAreTold) {
  EXPECT_TRUE(gs::build_edge_mesh(gs::make_cylinder(0.5f, 2.0f, 10, true)).closed);
  EXPECT_FALSE(gs::build_edge_mesh(gs::make_cylinder(0.5f, 2.0f, 10, false)).closed);
  EXPECT_FALSE(gs::build_edge_mesh(gs::make_plane(2.0f, 2)).closed);
  gs::Mesh broken = gs::make_box(glm::vec3(1.0f));
  broken.positions[0].x = NAN;
  EXPECT_FALSE(gs::build_edge_mesh(broken).closed);
  // The fighters' shadow meshes are made of closed parts: none may be skipped.
  gs::FightScene fight(TechniqueTest::kWidth, TechniqueTest::kHeight, 128);
  for (float time : {0.0f, 2.1f, 5.3f}) {
    for (const gs::SceneObject &o : fight.at(time).objects) {
      if (!o.casts_shadow) continue;
      const gs::Mesh &caster = o.shadow_mesh.triangles.empty() ? o.mesh : o.shadow_mesh;
      EXPECT_TRUE(gs::build_edge_mesh(caster).closed) << o.name << " at " << time;
    }
  }
}

// is_closed_surface is build_edge_mesh's `closed` without the edges: the same answer on closed,
// open, degenerate, broken and empty meshes, including a box missing one face and a mesh whose
// only open edge is walked twice the same way.
TEST(StencilVolumeSilhouette, ClosedSurfaceTestAgreesWithTheEdgeMesh) {
  std::vector<gs::Mesh> meshes = {gs::make_box(glm::vec3(0.5f)), gs::make_sphere(1.0f, 9, 5),
                                  gs::make_cylinder(0.5f, 2.0f, 10, true),
                                  gs::make_cylinder(0.5f, 2.0f, 10, false),
                                  gs::make_plane(2.0f, 3), gs::Mesh{}};
  gs::Mesh no_lid = gs::make_box(glm::vec3(1.0f));
  no_lid.triangles.pop_back();
  no_lid.triangles.pop_back();
  gs::Mesh twice_one_way = gs::make_box(glm::vec3(1.0f));
  twice_one_way.triangles.push_back(twice_one_way.triangles.front());
  gs::Mesh not_finite = gs::make_box(glm::vec3(1.0f));
  not_finite.positions[3].y = INFINITY;
  gs::Mesh out_of_range = gs::make_box(glm::vec3(1.0f));
  out_of_range.triangles.back().z = 1000;
  gs::Mesh flat_corner = gs::make_box(glm::vec3(1.0f));
  flat_corner.positions.push_back(flat_corner.positions[0]);
  flat_corner.triangles.push_back({0, 0, static_cast<glm::uint>(flat_corner.positions.size() - 1)});
  for (gs::Mesh *m : {&no_lid, &twice_one_way, &not_finite, &out_of_range, &flat_corner}) {
    meshes.push_back(*m);
  }
  gs::FightScene fight(TechniqueTest::kWidth, TechniqueTest::kHeight, 128);
  for (float time : {0.0f, 1.3f, 4.4f}) {
    for (const gs::SceneObject &o : fight.at(time).objects) meshes.push_back(o.mesh);
  }
  int closed = 0;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const bool expected = gs::build_edge_mesh(meshes[i]).closed;
    EXPECT_EQ(gs::is_closed_surface(meshes[i]), expected) << "mesh " << i;
    closed += expected;
  }
  EXPECT_GT(closed, 0);
  EXPECT_LT(closed, static_cast<int>(meshes.size()));
}

TEST_F(StencilVolumeShadowTest, FootprintOnTheFloorMatchesTheProjectedTexture) {
  const gs::Scene scene = box_over_floor();
  EXPECT_FALSE(gs::near_plane_may_be_in_shadow(scene, scene.lights[0]));
  const Mask floor = without(coverage(scene, 0), coverage(scene, 1));
  const Mask box = coverage(scene, 1);
  std::string error;
  const auto projected = gs::make_technique("projected", {}, error);
  ASSERT_NE(projected, nullptr) << error;
  const Mask reference = both(mask_of(*projected, scene), floor);
  ASSERT_GT(count(reference), 500);

  auto technique = gs::make_stencil_volume_shadow({});
  const gs::FrameReport report = technique->render(scene, true);
  ASSERT_EQ(report.steps.size(), 3u);
  EXPECT_EQ(report.steps[0].first, "1 ambient pass");
  EXPECT_EQ(report.steps[1].first, "2 silhouettes and volumes");
  EXPECT_EQ(report.steps[2].first, "3 lit pass");
  EXPECT_TRUE(report.warnings.empty());
  technique->render_mask(scene);
  const Mask full = white_pixels();
  const Mask stencil = both(full, floor);
  const int overlap = count(both(stencil, reference));
  EXPECT_GE(overlap, 0.9 * count(reference)) << "shadow missing where the projected one is";
  EXPECT_GE(overlap, 0.9 * count(stencil)) << "shadow where the projected one is not";
  // The box's top faces the light and stays lit; its sides get no light to take away.
  EXPECT_EQ(count(both(full, box)), 0) << "the caster's lit face is self-shadowed";

  // The camera is outside every volume, so z-fail must agree with the automatic z-pass.
  const Mask z_fail = stencil_mask(scene, Mode::ZFail);
  EXPECT_EQ(count(both(z_fail, box)), 0) << "z-fail's caps shadow the lit face";
  EXPECT_LE(count(without(z_fail, full)) + count(without(full, z_fail)), 0.01 * count(full));
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(StencilVolumeShadowTest, CameraInsideAVolumeNeedsZFail) {
  // The camera between the box and the floor, looking down: it is inside the box's volume.
  gs::Scene scene = box_over_floor();
  scene.camera.position = {0, 0.7f, 0};
  scene.camera.target = {0, 0, 0.4f};
  EXPECT_TRUE(gs::near_plane_may_be_in_shadow(scene, scene.lights[0]));
  const Mask floor = coverage(scene, 0);
  // The answer on the floor, ray-cast per pixel centre: inside the square |x|, |z| < 2/3.
  const glm::mat4 to_world = glm::inverse(
      gs::camera_projection(scene.camera, kWidth, kHeight) * gs::camera_view(scene.camera));
  Mask expected(floor.size());
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const glm::vec2 ndc((static_cast<float>(x) + 0.5f) / kWidth * 2.0f - 1.0f,
                          1.0f - (static_cast<float>(y) + 0.5f) / kHeight * 2.0f);
      const glm::vec4 near_point = to_world * glm::vec4(ndc, -1.0f, 1.0f);
      const glm::vec4 far_point = to_world * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 from = glm::vec3(near_point) / near_point.w,
                      to = glm::vec3(far_point) / far_point.w;
      if (to.y >= from.y) continue;  // looking up: no floor
      const glm::vec3 hit = from + (to - from) * (from.y / (from.y - to.y));
      const auto i = static_cast<std::size_t>(y * kWidth + x);
      expected[i] = floor[i] && std::abs(hit.x) < 2.0f / 3.0f && std::abs(hit.z) < 2.0f / 3.0f;
    }
  }
  ASSERT_GT(count(expected), 5000);
  ASSERT_GT(count(without(floor, expected)), 5000) << "no lit floor in view to go wrong on";

  const Mask z_fail = both(stencil_mask(scene, Mode::ZFail), floor);
  const int overlap = count(both(z_fail, expected));
  EXPECT_GE(overlap, 0.9 * count(expected));
  EXPECT_GE(overlap, 0.9 * count(z_fail));

  const Mask z_pass = both(stencil_mask(scene, Mode::ZPass), floor);
  EXPECT_LT(count(both(z_pass, expected)), 0.5 * count(expected)) << "z-pass right from inside?";
  EXPECT_EQ(stencil_mask(scene, Mode::Automatic), stencil_mask(scene, Mode::ZFail))
      << "the automatic choice is not z-fail";
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

TEST_F(StencilVolumeShadowTest, OpenCasterIsSkippedWithOneWarning) {
  gs::Scene scene = box_over_floor();
  scene.objects[0].casts_shadow = true;  // a plane: an open surface, it has no volume
  auto technique = gs::make_stencil_volume_shadow({});
  const gs::FrameReport first = technique->render(scene, false);
  ASSERT_EQ(first.warnings.size(), 1u);
  EXPECT_NE(first.warnings[0].find("'floor'"), std::string::npos) << first.warnings[0];
  EXPECT_TRUE(technique->render(scene, false).warnings.empty()) << "warned twice";
  technique->render_mask(scene);
  const Mask mask = white_pixels();
  const Mask floor = without(coverage(scene, 0), coverage(scene, 1));
  EXPECT_GT(count(both(mask, floor)), 500) << "the closed box lost its shadow too";
  EXPECT_EQ(glideShimGetLastError(), GLIDESHIM_OK) << glideShimGetLastErrorMessage();
}

}  // namespace
