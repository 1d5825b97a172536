// The false light inside casters' shadows on grazed receiver triangles (depth_map_lowered.h): the
// triangles' pixel centres found from the camera (world, in double), the map's lookup replayed at
// each against rays to the lights, counted as the error measure counts.
#include "techniques/depth_map/depth_map_lowered.h"

#include "techniques/depth_map/depth_map_frame_truth.h"
#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/depth_map/triangle_bvh.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

namespace gs::depth_map {
namespace {

// A receiver triangle lowered by more than this many texels' widths at its depth (light view)
// compares behind a caster that close in front of it: farther than the walks beside feet and
// shadow edges reach (a texel from the line they start at).
constexpr double kGrazedLoweringTexels = 2.0;

// A pixel centre on a grazed triangle that one caster alone shadows from the light.
struct GrazedPixel {
  int x = 0, y = 0;
  dvec3 point{0.0};
  glm::vec3 corner[3];
};

// Whether the surface of `mesh` (its ray body `body`, world) crosses the triangle a, b, c
// (world): one of the triangle's edges passes through it, or one of its edges through the
// triangle.
bool crosses(const RayBody &body, const WorldMesh &mesh, const glm::vec3 &a, const glm::vec3 &b,
             const glm::vec3 &c) {
  const dvec3 corner[3] = {dvec3(a), dvec3(b), dvec3(c)};
  const dvec3 low = glm::min(corner[0], glm::min(corner[1], corner[2]));
  const dvec3 high = glm::max(corner[0], glm::max(corner[1], corner[2]));
  if (glm::any(glm::greaterThan(low, body.high)) || glm::any(glm::lessThan(high, body.low))) return false;
  for (int k = 0; k < 3; ++k) {
    if (blocks(body, corner[k], corner[(k + 1) % 3] - corner[k])) return true;
  }
  for (const glm::uvec3 &t : mesh.object->mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      const dvec3 p(mesh.position[t[k]]), q(mesh.position[t[(k + 1) % 3]]);
      double hit = 0.0;
      if (ray_meets_triangle(p, q - p, corner[0], corner[1], corner[2], hit) && hit > 0.0 && hit < 1.0) return true;
    }
  }
  return false;
}

}  // namespace

bool lowered_past_texels(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c,
                         const LightFrustum &frustum, const SpotLight &light, int side,
                         const TechniqueOptions &options) {
  const glm::mat4 to_map = texture_from_clip() * frustum.projection * frustum.view;
  const MapReplay probe(frustum, light, side, options);  // positions in the map only
  const dvec3 light_position(light.position);
  const dvec3 centre = (dvec3(a) + dvec3(b) + dvec3(c)) / 3.0;
  const double lowered = receiver_lowering(a, b, c, true, to_map, side, options);  // r/q
  const double light_depth = -(glm::dmat4(frustum.view) * glm::dvec4(centre, 1.0)).z;  // metres
  // r/q per metre towards the light at the centre, from a small step.
  const double step = 1e-3 * std::max(glm::length(centre - light_position), 1e-6);
  glm::dvec2 texels;
  double depth = 0.0, nearer = 0.0;
  if (!(lowered > 0.0) || !(light_depth > 0.0) || !probe.in_map(centre, texels, depth) ||
      !probe.in_map(centre + glm::normalize(light_position - centre) * step, texels, nearer) ||
      !(depth > nearer)) {
    return false;
  }
  const double lowered_metres = lowered / (depth - nearer) * step;
  return lowered_metres > kGrazedLoweringTexels * frustum.texel_per_metre(side) * light_depth;
}

std::vector<ContactError> lowered_errors(const Scene &scene, const std::vector<WorldMesh> &meshes,
                                         const LightFrustum &frustum, const SpotLight &light,
                                         int side, const TechniqueOptions &options) {
  std::vector<ContactError> result(scene.objects.size());
  const FootprintSpace space = camera_screen(scene);
  const glm::dmat4 camera_clip(space.camera_clip);
  const dvec3 camera(scene.camera.position), light_position(light.position);
  const LightBeam beam = light_beam(light);
  const glm::mat4 to_map = texture_from_clip() * frustum.projection * frustum.view;
  const int width = scene.width, height = scene.height;
  std::vector<RayBody> bodies;  // made when a grazed triangle is found
  std::optional<FrameTruth> frame;  // the measure's band, made with the bodies

  for (std::size_t receiver_at = 0; receiver_at < meshes.size(); ++receiver_at) {
    const WorldMesh &receiver = meshes[receiver_at];
    // Only a receiver that casts is lowered (depth_map_lookup.h).
    if (!receiver.object->receives_shadow || !receiver.object->casts_shadow) continue;
    // Per caster, the pixels it alone shadows on this receiver's grazed triangles.
    std::map<std::size_t, std::vector<GrazedPixel>> by_caster;
    std::vector<bool> taken(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), false);
    for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
      std::map<std::size_t, bool> crossed;  // per caster: whether it crosses this triangle
      const glm::vec3 &a = receiver.position[t.x], &b = receiver.position[t.y], &c = receiver.position[t.z];
      const glm::vec3 face = glm::cross(b - a, c - a);
      if (!(glm::dot(face, light.position - a) > 0.0f) || !(glm::dot(face, scene.camera.position - a) > 0.0f)) continue;
      if (!lowered_past_texels(a, b, c, frustum, light, side, options)) continue;
      if (bodies.empty()) {
        bodies = ray_bodies(meshes);
        frame.emplace(scene, meshes, bodies);
      }
      // Its pixel centres the camera sees it at, past faces turned to the camera.
      glm::vec2 low(INFINITY), high(-INFINITY);
      bool before = true;
      for (const glm::vec3 *p : {&a, &b, &c}) {
        before = before && (space.camera_clip * glm::vec4(*p, 1.0f)).w > 0.0f;
        const glm::vec2 f = footprint_screen_pixels(space, *p);
        const glm::vec2 s(f.x + 0.5f * space.pixels.x, 0.5f * space.pixels.y - f.y);
        low = glm::min(low, s), high = glm::max(high, s);
      }
      if (!before) continue;
      const int x0 = std::max(0, static_cast<int>(std::floor(low.x - 0.5f)));
      const int x1 = std::min(width - 1, static_cast<int>(std::ceil(high.x - 0.5f)));
      const int y0 = std::max(0, static_cast<int>(std::floor(low.y - 0.5f)));
      const int y1 = std::min(height - 1, static_cast<int>(std::ceil(high.y - 0.5f)));
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          const std::size_t index = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
          if (taken[index]) continue;
          dvec3 from, to;
          frame->camera_ray(x, y, from, to);
          double hit = 0.0;
          if (!ray_meets_triangle(from, to - from, dvec3(a), dvec3(b), dvec3(c), hit) || !(hit > 0.0 && hit < 1.0)) continue;
          const dvec3 point = from + (to - from) * hit;
          if (!seen_past_near_plane(bodies, camera_clip, camera, point, true) ||
              !inside_planes(beam.inner, glm::vec3(point))) {
            continue;
          }
          taken[index] = true;
          // The one caster that shadows it from this light (not the receiver itself).
          std::size_t blocker = bodies.size();
          bool alone = true;
          for (std::size_t m = 0; m < bodies.size() && alone; ++m) {
            if (!(bodies[m].casts || m == receiver_at) || !blocks(bodies[m], light_position, point - light_position)) continue;
            alone = m != receiver_at && blocker == bodies.size();
            blocker = m;
          }
          if (!alone || blocker == bodies.size()) continue;
          // A caster whose surface crosses the triangle stands in it: what its map gets wrong
          // beside that foot is the feet estimate's (depth_map_contacts.h), not counted twice.
          auto known = crossed.find(blocker);
          if (known == crossed.end()) {
            known = crossed.emplace(blocker, crosses(bodies[blocker], meshes[blocker], a, b, c)).first;
          }
          if (known->second) continue;
          GrazedPixel pixel;
          pixel.x = x, pixel.y = y, pixel.point = point;
          pixel.corner[0] = a, pixel.corner[1] = b, pixel.corner[2] = c;
          by_caster[blocker].push_back(pixel);
        }
      }
    }
    const OtherShadows others(scene, light);
    for (const auto &grazed : by_caster) {
      // Named, not bound: C++17 lambdas (clang's) cannot capture structured bindings.
      const std::size_t caster_at = grazed.first;
      const std::vector<GrazedPixel> &pixels = grazed.second;
      const EdgeErrorEstimate estimate = estimate_by_size(side, [&](int map_side) {
        MapReplay replay = caster_replay(frustum, light, map_side, options, meshes[caster_at], receiver);
        long interior = 0;
        for (const GrazedPixel &pixel : pixels) {
          double depth;
          glm::dvec2 texels;
          if (!replay.in_map(pixel.point, texels, depth)) continue;
          const double lowered = receiver_lowering(pixel.corner[0], pixel.corner[1], pixel.corner[2],
                                                   true, to_map, map_side, options);
          if (replay.shadowed(texels, depth - lowered)) continue;
          const dvec3 normal = glm::normalize(glm::cross(dvec3(pixel.corner[1] - pixel.corner[0]),
                                                         dvec3(pixel.corner[2] - pixel.corner[0])));
          if (others.hold(bodies, receiver_at, pixel.point, normal) || frame->in_band(pixel.x, pixel.y)) continue;
          ++interior;
        }
        return static_cast<double>(interior);
      });
      ContactError &error = result[caster_at];  // meshes follow the scene's objects
      if (estimate.pixels[0] > error.pixels.pixels[0]) error.receiver = receiver_at;
      error.pixels.add(estimate);
    }
  }
  return result;
}

}  // namespace gs::depth_map
