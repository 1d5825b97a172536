// Issue 14: the twelfth audit's grazing-extra-lights-narrow-cones-camera-behind_18139 (stencil
// volumes 0.498% interior false shadow served: one pixel of 201). The camera is inside the
// ring's platform looking up at fighter0's forearm where it enters the glove; light 1 grazes the
// forearm (21 degrees) and the glove's silhouette from the light runs past it. The pixel's
// surface point lies 0.27 mm inside the plane of the volume's side quad on that silhouette edge
// (the camera ray crosses the quad 0.25 mm in front of the forearm), and the exact segment from
// the point to the light enters the glove 8.4 mm from it: the point is in fighter0's own shadow
// and the volume is right. The truth (ground_truth.cpp) starts its shadow rays 1e-4 of the
// scene's radius off the surface along the face's normal (0.56 mm here), which carries this
// start across the side quad's plane, out of the glove's shadow, so the truth calls the point
// lit; with the ray started on the segment itself the pixel is the forearm's self-shadow (not
// counted) and every stencil19_* scene is 0.000%. Not a volume artefact, so the technique is
// unchanged; these tests score it against the truth with each light's reach re-decided by the
// exact segment from the surface point (double, no offset), the truth's verdict everywhere else.
// Scenes in tests/hard_cases/audit (stencil19_*; README, "A glove's shadow on its forearm").
#include "hard_case_checks.h"

#include "techniques/geometry/projection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using namespace hard_cases;  // the checks of hard_case_checks.h

namespace {

// One object's triangles in world space, double, in runs of kRun consecutive triangles, each
// with a bounding sphere (a mesh's triangles lie mostly near their neighbours in the list), so a
// line is met against only the runs it passes near.
constexpr std::size_t kRun = 32;

struct Body {
  bool casts = false;
  std::vector<glm::dvec3> position;
  std::vector<glm::uvec3> triangle;
  std::vector<glm::dvec4> run;  // centre, radius
};

std::vector<Body> bodies_of(const gs::Scene &scene) {
  std::vector<Body> bodies;
  for (const gs::SceneObject &object : scene.objects) {
    Body body;
    body.casts = object.casts_shadow;
    const glm::dmat4 model(object.model_to_world);
    for (const glm::vec3 &p : object.mesh.positions)
      body.position.emplace_back(model * glm::dvec4(glm::dvec3(p), 1.0));
    body.triangle = object.mesh.triangles;
    for (std::size_t first = 0; first < body.triangle.size(); first += kRun) {
      const std::size_t end = std::min(first + kRun, body.triangle.size());
      glm::dvec3 low(std::numeric_limits<double>::max()), high(-low);
      for (std::size_t t = first; t < end; ++t)
        for (int k = 0; k < 3; ++k)
          low = glm::min(low, body.position[body.triangle[t][k]]),
          high = glm::max(high, body.position[body.triangle[t][k]]);
      body.run.emplace_back(0.5 * (low + high), 0.5 * glm::length(high - low));
    }
    bodies.push_back(std::move(body));
  }
  return bodies;
}

// Where the line origin + t * dir meets triangle `t` of `body` (Moller-Trumbore, double): t, or
// nothing. `front_only`: only a triangle facing the origin (as the truth's camera rays see).
std::optional<double> meet(const Body &body, const glm::uvec3 &t, const glm::dvec3 &origin,
                           const glm::dvec3 &dir, bool front_only) {
  const glm::dvec3 a = body.position[t.x], e1 = body.position[t.y] - a,
                   e2 = body.position[t.z] - a;
  if (front_only && glm::dot(glm::cross(e1, e2), dir) >= 0.0) return std::nullopt;
  const glm::dvec3 p = glm::cross(dir, e2);
  const double det = glm::dot(e1, p);
  if (det == 0.0) return std::nullopt;
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(dir, q) / det;
  if (u < 0.0 || v < 0.0 || u + v > 1.0) return std::nullopt;
  return glm::dot(e2, q) / det;
}

// The smallest t in (from, to) where the line meets `body` (front faces only if `front_only`).
std::optional<double> first_meet(const Body &body, const glm::dvec3 &origin,
                                 const glm::dvec3 &dir, double from, double to,
                                 bool front_only) {
  std::optional<double> nearest;
  for (std::size_t r = 0; r < body.run.size(); ++r) {
    const glm::dvec3 centre(body.run[r]);
    const double along = glm::dot(centre - origin, dir);
    const glm::dvec3 closest = origin + dir * std::clamp(along, from, to);
    if (glm::length(centre - closest) > body.run[r].w) continue;
    const std::size_t end = std::min((r + 1) * kRun, body.triangle.size());
    for (std::size_t t = r * kRun; t < end; ++t) {
      const std::optional<double> at = meet(body, body.triangle[t], origin, dir, front_only);
      if (at && *at > from && *at < to && (!nearest || *at < *nearest)) nearest = at;
    }
  }
  return nearest;
}

// The truth with the light's reach decided exactly: per pixel, the visible point (the pixel
// centre's camera ray from the near plane, as the truth casts it, against the object the truth
// sees there) and, for each light the truth says reaches it (in the cone, the face towards it),
// whether the segment to the light crosses a caster: another object (shadow) or only its own
// (self-shadow, not counted). Segments start on the point itself: a crossing within 1 um of it
// is the point's own face. Pixels whose point is not found keep the truth's verdict.
struct ExactTruth {
  std::vector<std::uint8_t> shadow, self_only, receivers;
  long changed = 0;  // receiver pixels whose verdict differs from the truth's
};

ExactTruth exact_truth(const gs::Scene &scene, const Truth &truth) {
  const std::vector<Body> bodies = bodies_of(scene);
  const glm::dmat4 to_world = glm::inverse(
      glm::dmat4(gs::camera_projection(scene.camera, scene.width, scene.height)) *
      glm::dmat4(gs::camera_view(scene.camera)));
  ExactTruth exact{truth.exact.shadow, truth.self_only, truth.receivers, 0};
  const std::size_t lights = truth.exact.lights;
  for (int j = 0; j < scene.height; ++j) {
    for (int i = 0; i < scene.width; ++i) {
      const std::size_t pixel = static_cast<std::size_t>(j) * scene.width + i;
      const int object = truth.exact.object[pixel];
      if (object < 0 || !scene.objects[object].receives_shadow) continue;
      const double x = (i + 0.5) / scene.width * 2.0 - 1.0;  // NDC, y up; rows from the top
      const double y = 1.0 - (j + 0.5) / scene.height * 2.0;
      const glm::dvec4 near_h = to_world * glm::dvec4(x, y, -1.0, 1.0);
      const glm::dvec4 far_h = to_world * glm::dvec4(x, y, 1.0, 1.0);
      const glm::dvec3 origin = glm::dvec3(near_h) / near_h.w;
      const glm::dvec3 dir = glm::normalize(glm::dvec3(far_h) / far_h.w - origin);
      const double far = glm::length(glm::dvec3(far_h) / far_h.w - origin);
      const std::optional<double> nearest =
          first_meet(bodies[object], origin, dir, 0.0, far, true);
      if (!nearest) continue;
      const glm::dvec3 point = origin + dir * *nearest;
      bool by_other = false, by_self = false;
      for (std::size_t l = 0; l < lights; ++l) {
        if (truth.exact.reach[pixel * lights + l] == gs::LightReach::Outside) continue;
        const glm::dvec3 to_light = glm::dvec3(scene.lights[l].position) - point;
        const double distance = glm::length(to_light);
        const glm::dvec3 toward = to_light / distance;
        for (std::size_t b = 0; b < bodies.size(); ++b) {
          if (!bodies[b].casts) continue;
          if (first_meet(bodies[b], point, toward, 1e-6, distance, false))
            (static_cast<int>(b) == object ? by_self : by_other) = true;
        }
      }
      const std::uint8_t shadow = by_other ? 1 : 0, self_only = by_self && !by_other ? 1 : 0;
      exact.changed += shadow != exact.shadow[pixel] || self_only != exact.self_only[pixel];
      exact.shadow[pixel] = shadow;
      exact.self_only[pixel] = self_only;
      exact.receivers[pixel] = self_only ? 0 : 1;
    }
  }
  return exact;
}

// Stencil volumes on `file` within issue 14's budget against the exact truth; what the
// ray-cast truth says is printed beside it.
void expect_volumes_exact(const std::string &file) {
  const gs::Scene scene = load(file);
  const Truth truth = truth_of(scene);
  const Outcome o = run("stencil-volume", scene, truth);
  report(file + " stencil-volume, against the ray-cast truth", o);
  expect_clean_glide(file, o);
  for (const std::string &e : o.refusals) ADD_FAILURE() << file << ": " << e;
  const ExactTruth exact = exact_truth(scene, truth);
  const gs::MaskErrors errors =
      gs::compare_masks(o.mask, exact.shadow, exact.receivers, scene.width, scene.height,
                        exact.self_only, o.drawn);
  std::cout << "  against the exact segments: " << exact.changed << " verdicts changed, "
            << errors.receiver_pixels << " counted, interior false shadow "
            << errors.false_shadow_interior * 100.0 << "%, false light "
            << errors.false_light_interior * 100.0 << "%\n";
  ASSERT_GT(errors.receiver_pixels, 100) << file << ": too few receiver pixels to test";
  EXPECT_LE(errors.false_shadow_interior + errors.false_light_interior, kInteriorBudget) << file;
}

}  // namespace

// The audit's frame (240x180, 201 receiver pixels). Against the ray-cast truth 0.498% served;
// the one pixel (142, 179) is the forearm's self-shadow under the exact segment.
TEST(HardCases, VolumesShadowAForearmWhereItEntersTheGloveAsTheExactSegmentDoes) {
  expect_volumes_exact("audit/stencil19_glove_forearm_camera_in_platform.json");
}

// Light 1 moved 0.3 m along x: the same pixel, 0.498% against the ray-cast truth.
TEST(HardCases, VolumesShadowTheForearmBesideTheGloveUnderAMovedLight) {
  expect_volumes_exact("audit/stencil19_glove_forearm_light1_moved_xp30.json");
}

// The camera 30% of the way from the forearm point to the audit's camera, looking at it, 320x240
// (thousands of receiver pixels): the sliver of self-shadow the offset loses is a few pixels
// wide here; 0.006% interior (0.117% misclassified) against the ray-cast truth.
TEST(HardCases, VolumesShadowTheForearmBesideTheGloveSeenClose) {
  expect_volumes_exact("audit/stencil19_glove_forearm_close_30.json");
}

// The audit's frame at 640x480 and with the camera 3 cm lower: 0.000% against both truths.
TEST(HardCases, VolumesShadowTheForearmBesideTheGloveAtOtherSizesAndHeights) {
  expect_volumes_exact("audit/stencil19_glove_forearm_640x480.json");
  expect_volumes_exact("audit/stencil19_glove_forearm_camera_y080.json");
}
