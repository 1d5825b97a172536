// The depth map's false shadow on a caster's own lit side (depth_map_self_shadow.h).
// Spaces: world (meshes, planes; rays in double); the map's texture coordinates (s, t, r, q);
// camera clip; screen pixels.
#include "techniques/depth_map/depth_map_self_shadow.h"

#include "techniques/depth_map/depth_map_lookup.h"
#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"
#include "techniques/texel_error/texel_footprint.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace gs::depth_map {
namespace {

// A face is grazed where the tangent of the light's angle to it is under this many times the
// lookup's reach (texels) over the slope term's bound (texels): there the depth its own plane
// changes across the reach, 1 / tan texel widths a texel, passes half what the bounded copy
// pushes back, and the surface nearer the light within that reach is what the map holds.
constexpr double kGrazingTangent = 2.0;
// A pixel of a lit triangle the estimate replays: the point under its centre (world), the
// receiver and the triangle's index in it, the screen pixels it stands for, and whether the light
// grazes the triangle (else only a shadow of its own object's texels counts there).
struct LitSample {
  dvec3 point;
  const WorldMesh *mesh = nullptr;
  std::size_t triangle = 0;
  double pixels = 0.0;
  bool grazed = false;
};

}  // namespace

std::vector<EdgeErrorEstimate> self_shadow_errors(const Scene &scene,
                                                  const std::vector<WorldMesh> &meshes,
                                                  const std::vector<LightFrustum> &frusta,
                                                  const SpotLight &light, int side,
                                                  const TechniqueOptions &options) {
  std::vector<EdgeErrorEstimate> result(scene.objects.size());
  const bool bounded = std::isfinite(options.depth_bias_bound) && options.depth_bias_bound > 0.0f;
  if (!bounded) return result;  // the slope term alone follows every face's own slope
  const double grazing_tangent =
      kGrazingTangent * kFilterReachTexels / static_cast<double>(options.depth_bias_bound);
  const FootprintSpace space = camera_screen(scene);  // for the screen positions
  const glm::dmat4 camera_clip(space.camera_clip);
  const dvec3 camera(scene.camera.position), light_position(light.position);
  const LightBeam beam = light_beam(light);
  std::vector<RayBody> bodies;  // built on the first grazed triangle: most frames have none
  // The truth's shadow rays start off the surface by 1e-4 of the scene's radius (half its box's
  // diagonal, src/measure/ground_truth.cpp), which a grazed surface's own rounding needs.
  glm::dvec3 scene_low(INFINITY), scene_high(-INFINITY);
  for (const WorldMesh &mesh : meshes) {
    for (const glm::vec3 &p : mesh.position)
      scene_low = glm::min(scene_low, dvec3(p)), scene_high = glm::max(scene_high, dvec3(p));
  }
  const double offset = scene_high.x >= scene_low.x
                            ? 1e-4 * std::max(0.5 * glm::length(scene_high - scene_low), 1e-6)
                            : 1e-4;
  // Whether a caster (the object itself included) blocks the segment from the light to `point`
  // on the face with unit normal `normal` (towards the light), as the truth casts it.
  auto shadowed = [&](const dvec3 &point, const dvec3 &normal) {
    const dvec3 start = point + normal * offset;
    for (const RayBody &body : bodies) {
      if (body.casts && blocks(body, light_position, start - light_position)) return true;
    }
    return false;
  };
  auto unit_face = [](const WorldMesh &mesh, std::size_t triangle) {
    const glm::uvec3 &u = mesh.object->mesh.triangles[triangle];
    const dvec3 a(mesh.position[u.x]), b(mesh.position[u.y]), c(mesh.position[u.z]);
    const dvec3 face = glm::cross(b - a, c - a);
    const double length = glm::length(face);
    return length > 0.0 ? face / length : dvec3(0.0);
  };
  std::vector<LitSample> samples;
  for (const WorldMesh &mesh : meshes) {
    if (!mesh.object->casts_shadow || !mesh.object->receives_shadow) continue;
    const std::vector<glm::uvec3> &triangles = mesh.object->mesh.triangles;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const dvec3 corner[3] = {dvec3(mesh.position[triangles[t].x]),
                               dvec3(mesh.position[triangles[t].y]),
                               dvec3(mesh.position[triangles[t].z])};
      const dvec3 face = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
      const dvec3 centre = (corner[0] + corner[1] + corner[2]) / 3.0;
      const dvec3 to_light = light_position - centre;
      // The light's angle to the face: sine over cosine, towards the light only (the mask
      // shadows no face turned away).
      const double sine = glm::dot(face, to_light),
                   length = glm::length(face) * glm::length(to_light);
      if (!(sine > 0.0) || !(length > 0.0)) continue;
      const double cosine = std::sqrt(std::max(length * length - sine * sine, 0.0));
      const bool grazed = sine < grazing_tangent * cosine;
      if (!(glm::dot(face, camera - centre) > 0.0)) continue;  // culled by the camera passes
      // The pixels whose centres the triangle covers on screen (GL window coordinates: column
      // i's centre at i + 0.5, rows from the bottom), each at the triangle's point under it
      // (perspective-correct barycentric weights): the pixels the error measure counts.
      glm::dvec2 screen[3];
      double w[3];
      bool before = true;
      for (int k = 0; k < 3; ++k) {
        const glm::dvec4 c = camera_clip * glm::dvec4(corner[k], 1.0);
        before = before && c.w > 0.0;
        w[k] = c.w;
        screen[k] =
            (glm::dvec2(c.x, c.y) / c.w * 0.5 + 0.5) * glm::dvec2(scene.width, scene.height);
      }
      if (!before) continue;
      const double twice_area = (screen[1].x - screen[0].x) * (screen[2].y - screen[0].y) -
                                (screen[2].x - screen[0].x) * (screen[1].y - screen[0].y);
      if (!(std::abs(twice_area) > 0.0)) continue;
      if (bodies.empty()) bodies = ray_bodies(meshes);
      const glm::dvec2 low = glm::min(screen[0], glm::min(screen[1], screen[2]));
      const glm::dvec2 high = glm::max(screen[0], glm::max(screen[1], screen[2]));
      const int x0 = std::max(static_cast<int>(std::ceil(low.x - 0.5)), 0);
      const int x1 = std::min(static_cast<int>(std::floor(high.x - 0.5)), scene.width - 1);
      const int y0 = std::max(static_cast<int>(std::ceil(low.y - 0.5)), 0);
      const int y1 = std::min(static_cast<int>(std::floor(high.y - 0.5)), scene.height - 1);
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const glm::dvec2 centre_px(x + 0.5, y + 0.5);
          double weight[3], sum = 0.0;
          bool inside = true;
          for (int k = 0; k < 3; ++k) {
            const glm::dvec2 &p = screen[(k + 1) % 3], &q = screen[(k + 2) % 3];
            const double edge =
                ((q.x - p.x) * (centre_px.y - p.y) - (centre_px.x - p.x) * (q.y - p.y)) /
                twice_area;
            inside = inside && edge >= 0.0;
            weight[k] = edge / w[k];
            sum += weight[k];
          }
          if (!inside || !(sum > 0.0)) continue;
          const dvec3 point =
              (corner[0] * weight[0] + corner[1] * weight[1] + corner[2] * weight[2]) / sum;
          if (!inside_planes(beam.inner, glm::vec3(point))) continue;
          samples.push_back({point, &mesh, t, 1.0, grazed});
        }
      }
    }
  }
  if (samples.empty()) return result;
  // Kept: what the camera sees and the light reaches; excused later, where a wrong one lies
  // within the band of a true shadow (checked only for wrong samples: 0 unknown, 1 excused,
  // 2 counted).
  std::vector<LitSample> kept;
  for (const LitSample &sample : samples) {
    if (seen_past_near_plane(bodies, camera_clip, camera, sample.point) &&
        !shadowed(sample.point, unit_face(*sample.mesh, sample.triangle))) {
      kept.push_back(sample);
    }
  }
  std::vector<int> band(kept.size(), 0);
  // Whether a wrong pixel here is the band of a true shadow's edge (another caster's, or the
  // object's own): src/measure/metrics.cpp excuses one within a pixel (Chebyshev) of a pixel
  // with a 4-neighbour across the edge, so where a shadow lies at a pixel offset (dx, dy) with
  // dx^2 + dy^2 <= 5. The surfaces the camera sees there: the nearest hits along rays through
  // points of the sample's triangle's plane at those screen offsets.
  auto near_shadow = [&](const LitSample &sample) {
    const std::vector<glm::vec3> &position = sample.mesh->position;
    const glm::uvec3 &u = sample.mesh->object->mesh.triangles[sample.triangle];
    const dvec3 a(position[u.x]), b(position[u.y]), c(position[u.z]);
    // Screen pixels per metre along two unit directions in the triangle's plane (e1 along a-b,
    // e2 across it), from small steps.
    const double step = 1e-4 * std::max(glm::length(sample.point - camera), 1e-6);
    const dvec3 e1 = glm::normalize(b - a),
                e2 = glm::normalize(glm::cross(glm::cross(b - a, c - a), e1));
    const glm::dvec2 at(footprint_screen_pixels(space, glm::vec3(sample.point)));
    const glm::dvec2 d1 =
        (glm::dvec2(footprint_screen_pixels(space, glm::vec3(sample.point + e1 * step))) - at) /
        step;
    const glm::dvec2 d2 =
        (glm::dvec2(footprint_screen_pixels(space, glm::vec3(sample.point + e2 * step))) - at) /
        step;
    const double det = d1.x * d2.y - d1.y * d2.x;
    if (!(std::abs(det) > 0.0)) return true;  // seen edge-on: all of it is an edge
    for (int dx = -2; dx <= 2; ++dx) {
      for (int dy = -2; dy <= 2; ++dy) {
        if ((dx == 0 && dy == 0) || dx * dx + dy * dy > 5) continue;
        const double along1 = (dx * d2.y - dy * d2.x) / det;
        const double along2 = (d1.x * dy - d1.y * dx) / det;
        // The surface the camera sees through that pixel: the nearest on its ray.
        const dvec3 ray = sample.point + e1 * along1 + e2 * along2 - camera;
        double nearest = INFINITY;
        std::size_t seen = 0, seen_triangle = 0;
        for (std::size_t m = 0; m < bodies.size(); ++m) {
          double t = nearest;
          std::size_t hit = 0;
          if (bodies[m].triangles.nearest(camera, ray, 1e-9, t, hit))
            nearest = t, seen = m, seen_triangle = hit;
        }
        if (!std::isfinite(nearest)) continue;
        // A face turned away from the light, or out of the beam, is no shadow to the truth (nor
        // to the mask): the light does not reach it at all.
        const dvec3 point = camera + ray * nearest;
        const dvec3 normal = unit_face(meshes[seen], seen_triangle);
        const glm::uvec3 &corners = meshes[seen].object->mesh.triangles[seen_triangle];
        if (!(glm::dot(normal, light_position - dvec3(meshes[seen].position[corners.x])) > 0.0))
          continue;
        if (!inside_planes(beam.inner, glm::vec3(point))) continue;
        if (shadowed(point, normal)) return true;
      }
    }
    return false;
  };
  // The map as step 1 draws it, every caster in it; what the lookup shadows is counted for the
  // caster whose texel weighs most in it.
  std::vector<std::size_t> drawn;  // per surface of the replay, its object
  for (const WorldMesh &mesh : meshes) {
    if (mesh.object->casts_shadow)
      drawn.push_back(static_cast<std::size_t>(mesh.object - scene.objects.data()));
  }
  for (int size = 0; size < EdgeErrorEstimate::kSizes; ++size) {
    const int map_side = side << size;
    const LightFrustum &frustum = frusta[static_cast<std::size_t>(size)];
    const glm::mat4 to_map = texture_from_clip() * frustum.projection * frustum.view;
    MapReplay replay(frustum, light, map_side, options);
    for (const WorldMesh &mesh : meshes) {
      if (mesh.object->casts_shadow) replay.add(mesh, frustum);
    }
    double pixels = 0.0;
    const LitSample *lowered_for = nullptr;  // a sample of the triangle `lowered` is of
    double lowered = 0.0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const LitSample &sample = kept[k];
      if (!lowered_for || sample.mesh != lowered_for->mesh ||
          sample.triangle != lowered_for->triangle) {
        // The receiver's lowered depth (r/q) on this triangle: its receiver-plane bias.
        const std::vector<glm::vec3> &position = sample.mesh->position;
        const glm::uvec3 &u = sample.mesh->object->mesh.triangles[sample.triangle];
        const std::vector<glm::vec3> corners = {position[u.x], position[u.y], position[u.z]};
        const glm::vec4 plain = to_map * glm::vec4(corners[0], 1.0f);
        const glm::vec4 biased =
            biased_map_coords(corners, to_map, map_side, options.depth_bias_receiver)[0];
        lowered = plain.w != 0.0f ? static_cast<double>((plain.z - biased.z) / plain.w) : 0.0;
        lowered_for = &sample;
      }
      glm::dvec2 texels;
      double depth;
      if (!replay.in_map(sample.point, texels, depth)) continue;
      const int surface = replay.shadowing(texels, depth - lowered);
      if (surface < 0) continue;
      const std::size_t caster = drawn[static_cast<std::size_t>(surface)];
      // On a triangle the light does not graze, the acne above cannot be: a texel of another
      // caster shadowing it is that caster's shadow edge, which shadow_edge_error.h estimates.
      if (!sample.grazed && &scene.objects[caster] != sample.mesh->object) continue;
      if (band[k] == 0) band[k] = near_shadow(sample) ? 1 : 2;
      if (band[k] != 2) continue;
      result[caster].pixels[size] += static_cast<float>(sample.pixels);
      pixels += sample.pixels;
    }
    if (!(pixels > 0.0)) break;  // finer maps only lower the depth change a texel spans
  }
  return result;
}

}  // namespace gs::depth_map
