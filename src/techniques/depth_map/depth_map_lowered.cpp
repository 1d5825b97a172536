// The false light inside casters' shadows on grazed receiver triangles (depth_map_lowered.h): the
// triangles' pixel centres found from the camera (world, in double), the map's lookup replayed at
// each against rays to the lights, counted as the error measure counts.
#include "techniques/depth_map/depth_map_lowered.h"

#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/depth_map/triangle_bvh.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
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

}  // namespace

std::vector<ContactError> lowered_errors(const Scene &scene, const std::vector<WorldMesh> &meshes,
                                         const LightFrustum &frustum, const SpotLight &light,
                                         int side, const TechniqueOptions &options) {
  std::vector<ContactError> result(scene.objects.size());
  const FootprintSpace space = camera_screen(scene);
  const glm::dmat4 camera_clip(space.camera_clip), clip_to_world = glm::inverse(camera_clip);
  const dvec3 camera(scene.camera.position), light_position(light.position);
  const LightBeam beam = light_beam(light);
  const glm::mat4 to_map = texture_from_clip() * frustum.projection * frustum.view;
  const glm::dmat4 light_view(frustum.view);
  const int width = scene.width, height = scene.height;
  const MapReplay probe(frustum, light, side, options);  // positions in the map only
  std::vector<RayBody> bodies;  // made when a grazed triangle is found
  // Every shadowing light with its beam, for the truth beside a wrong pixel.
  std::vector<std::pair<const SpotLight *, LightBeam>> lights;
  for (const SpotLight &each : scene.lights) {
    if (!each.is_projector()) lights.emplace_back(&each, light_beam(each));
  }
  auto camera_ray = [&](int x, int y, dvec3 &from, dvec3 &to) {
    const glm::dvec2 ndc((x + 0.5) / width * 2.0 - 1.0, 1.0 - (y + 0.5) / height * 2.0);
    const glm::dvec4 near_end = clip_to_world * glm::dvec4(ndc, -1.0, 1.0);
    const glm::dvec4 far_end = clip_to_world * glm::dvec4(ndc, 1.0, 1.0);
    from = dvec3(near_end) / near_end.w, to = dvec3(far_end) / far_end.w;
  };
  // The truth at pixel (x, y) as the measure takes it: -1 where no surface is seen, else 1 where
  // some light whose beam holds the seen surface, facing it, is blocked there by another object
  // that casts, 0 where none is. (Cached: the band's test asks each pixel up to 25 times.)
  std::map<std::pair<int, int>, int> truths;
  auto truth_at = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= width || y >= height) return -1;
    const auto known = truths.find({x, y});
    if (known != truths.end()) return known->second;
    dvec3 from, to;
    camera_ray(x, y, from, to);
    double nearest = 1.0;
    std::size_t seen = bodies.size(), triangle = 0;
    for (std::size_t m = 0; m < bodies.size(); ++m) {
      double t = nearest;
      std::size_t k = 0;
      if (bodies[m].triangles.nearest(from, to - from, 0.0, t, k)) nearest = t, seen = m, triangle = k;
    }
    int truth = -1;
    if (seen < bodies.size()) {
      const glm::uvec3 &t = meshes[seen].object->mesh.triangles[triangle];
      const dvec3 a(meshes[seen].position[t.x]), b(meshes[seen].position[t.y]), c(meshes[seen].position[t.z]);
      const dvec3 face = glm::cross(b - a, c - a), point = from + (to - from) * nearest;
      truth = 0;
      for (std::size_t l = 0; l < lights.size() && truth == 0; ++l) {
        const dvec3 from_light(lights[l].first->position);
        if (!(glm::dot(face, from_light - a) > 0.0) || !inside_planes(lights[l].second.inner, glm::vec3(point))) continue;
        for (std::size_t m = 0; m < bodies.size() && truth == 0; ++m) {
          if (m != seen && bodies[m].casts && blocks(bodies[m], from_light, point - from_light)) truth = 1;
        }
      }
    }
    truths.emplace(std::make_pair(x, y), truth);
    return truth;
  };
  // Whether the measure's band holds pixel (x, y): a pixel within one of it whose 4-neighbour
  // the truth calls otherwise.
  auto in_band = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int here = truth_at(x + dx, y + dy);
        if (here < 0) continue;
        for (const glm::ivec2 d : {glm::ivec2(1, 0), glm::ivec2(-1, 0), glm::ivec2(0, 1), glm::ivec2(0, -1)}) {
          const int there = truth_at(x + dx + d.x, y + dy + d.y);
          if (there >= 0 && there != here) return true;
        }
      }
    }
    return false;
  };

  for (std::size_t receiver_at = 0; receiver_at < meshes.size(); ++receiver_at) {
    const WorldMesh &receiver = meshes[receiver_at];
    // Only a receiver that casts is lowered (depth_map_lookup.h).
    if (!receiver.object->receives_shadow || !receiver.object->casts_shadow) continue;
    // Per caster, the pixels it alone shadows on this receiver's grazed triangles.
    std::map<std::size_t, std::vector<GrazedPixel>> by_caster;
    std::vector<bool> taken(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), false);
    for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
      const glm::vec3 &a = receiver.position[t.x], &b = receiver.position[t.y], &c = receiver.position[t.z];
      const glm::vec3 face = glm::cross(b - a, c - a);
      if (!(glm::dot(face, light.position - a) > 0.0f) || !(glm::dot(face, scene.camera.position - a) > 0.0f)) continue;
      // Its lowering in metres along the light's ray at its centre, against a texel's width there.
      const dvec3 centre = (dvec3(a) + dvec3(b) + dvec3(c)) / 3.0;
      const double lowered = receiver_lowering(a, b, c, true, to_map, side, options);
      const double light_depth = -(light_view * glm::dvec4(centre, 1.0)).z;
      const double step = 1e-3 * std::max(glm::length(centre - light_position), 1e-6);
      glm::dvec2 texels;
      double depth = 0.0, nearer = 0.0;
      if (!(lowered > 0.0) || !(light_depth > 0.0) || !probe.in_map(centre, texels, depth) ||
          !probe.in_map(centre + glm::normalize(light_position - centre) * step, texels, nearer) ||
          !(depth > nearer)) {
        continue;
      }
      const double lowered_metres = lowered / (depth - nearer) * step;
      if (!(lowered_metres > kGrazedLoweringTexels * frustum.texel_per_metre(side) * light_depth)) continue;
      if (bodies.empty()) bodies = ray_bodies(meshes);
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
          camera_ray(x, y, from, to);
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
          GrazedPixel pixel;
          pixel.x = x, pixel.y = y, pixel.point = point;
          pixel.corner[0] = a, pixel.corner[1] = b, pixel.corner[2] = c;
          by_caster[blocker].push_back(pixel);
        }
      }
    }
    const OtherShadows others(scene, light);
    for (const auto &[caster_at, pixels] : by_caster) {
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
          if (others.hold(bodies, receiver_at, pixel.point, normal) || in_band(pixel.x, pixel.y)) continue;
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
