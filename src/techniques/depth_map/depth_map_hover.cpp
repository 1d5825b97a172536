// The depth map's error beside the shadow edges of a caster close over its receiver
// (depth_map_hover.h). Spaces: world (meshes, planes; rays in double); light view (depths in
// metres, for the bound); the map's texture coordinates (s, t, r, q: s/q and t/q times the side
// are texels, r/q the stored depth 0..1); camera clip; screen pixels.
#include "techniques/depth_map/depth_map_hover.h"

#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gs::depth_map {
namespace {

// The texels from a shadow edge's point within which a texel holding the caster may move the
// edge: the 2x2 lookup reads a texel away, and the walk across the edge counts a run of wrong
// points that begins within a texel of it.
constexpr double kReachTexels = 2.0;

// A sample of a shadow edge longer than this on screen (pixels) is halved, at most kSubdivisions
// times: the walks across the edge then lie about a pixel apart on it.
constexpr double kSubdividePx = 1.0;
constexpr int kSubdivisions = 5;

// A point of a shadow edge on its receiver: where the light's ray through a sample of a
// silhouette segment first meets a surface behind it (world), that surface's plane (unit normal),
// the edge's direction in that plane (world, unit), its share of the edge's length on screen
// (pixels), its direction on screen (unit) and the band the measure excuses beside it (pixels).
struct EdgeSample {
  dvec3 point{0.0}, along{0.0}, normal{0.0};
  double screen_length = 0.0, band = 0.0;
  glm::dvec2 screen_along{0.0};
};

// The triangle `k` of `mesh` (world).
void corners_of(const WorldMesh &mesh, std::size_t k, glm::vec3 (&corner)[3]) {
  const glm::uvec3 &t = mesh.object->mesh.triangles[k];
  for (int m = 0; m < 3; ++m) corner[m] = mesh.position[t[m]];
}

}  // namespace

std::vector<ContactError> hover_errors(const Scene &scene, const std::vector<WorldMesh> &meshes,
                                       const std::vector<CasterFootprint> &footprints,
                                       const LightFrustum &frustum, const SpotLight &light,
                                       int side, const TechniqueOptions &options) {
  std::vector<ContactError> result(scene.objects.size());
  const std::vector<RayBody> bodies = ray_bodies(meshes);
  const FootprintSpace space = camera_screen(scene);
  const glm::dmat4 camera_clip(space.camera_clip);
  const dvec3 camera(scene.camera.position), light_position(light.position);
  const LightBeam beam = light_beam(light);
  const OtherShadows others(scene, light);
  const glm::mat4 to_map = texture_from_clip() * frustum.projection * frustum.view;
  const MapReplay probe(frustum, light, side, options);  // positions in the map only
  auto screen_of = [&](const dvec3 &p) {
    return glm::dvec2(footprint_screen_pixels(space, glm::vec3(p)));
  };
  auto seen_by_camera = [&](const dvec3 &p) {
    const glm::dvec4 seen = camera_clip * glm::dvec4(p, 1.0);
    return seen.w > 0.0 && std::abs(seen.x) <= seen.w && std::abs(seen.y) <= seen.w;
  };

  std::vector<std::vector<EdgeSample>> by_receiver(meshes.size());
  for (const CasterFootprint &footprint : footprints) {
    const std::size_t caster_at = footprint.caster;  // meshes follow the scene's objects
    const WorldMesh &caster = meshes[caster_at];
    for (std::vector<EdgeSample> &samples : by_receiver) samples.clear();
    MapReplay reach(frustum, light, side, options);  // the caster alone, as step 1 draws it
    reach.add(caster, frustum);
    for (const SilhouetteSegment &segment : footprint.segments) {
      const dvec3 a(segment.a), b(segment.b);
      glm::dvec2 ta, tb;
      double da, db;
      if (!probe.in_map(a, ta, da) || !probe.in_map(b, tb, db)) continue;
      // The part of the segment from u - du / 2 to u + du / 2 (u from 0 at a to 1 at b): its
      // shadow edge's sample, pushed to `by_receiver` where kept (not where `split` and longer
      // than kSubdividePx, to be halved); the edge's length on screen (pixels, in the
      // receiver's plane there), or a negative one where its shadow falls on no receiver it
      // counts on.
      auto sample_at = [&](double u, double du, bool split) -> double {
        const dvec3 s = a + (b - a) * u, step = (b - a) * du;
        // The first surface behind the sample along the light's ray.
        const dvec3 ray = s - light_position;
        double nearest = INFINITY;
        std::size_t hit_body = bodies.size(), hit = 0;
        for (std::size_t m = 0; m < bodies.size(); ++m) {
          double t = 1e6;
          std::size_t triangle = 0;
          if (bodies[m].triangles.nearest(light_position, ray, 1.0 + 1e-6, t, triangle) && t < nearest) {
            nearest = t, hit_body = m, hit = triangle;
          }
        }
        if (hit_body == bodies.size() || hit_body == caster_at ||
            !meshes[hit_body].object->receives_shadow) {
          return -1.0;
        }
        glm::vec3 corner[3];
        corners_of(meshes[hit_body], hit, corner);
        const dvec3 point = light_position + ray * nearest;
        const dvec3 face = glm::cross(dvec3(corner[1] - corner[0]), dvec3(corner[2] - corner[0]));
        if (!(glm::dot(face, light_position - point) > 0.0) || !(glm::length(face) > 0.0)) return -1.0;
        const dvec3 normal = glm::normalize(face);
        // The edge in the receiver's plane: the part projected from the light.
        auto onto_plane = [&](const dvec3 &p) {
          const double scale = glm::dot(normal, point - light_position) / glm::dot(normal, p - light_position);
          return scale > 0.0 ? light_position + (p - light_position) * scale : dvec3(NAN);
        };
        const dvec3 from = onto_plane(s - step * 0.5), to = onto_plane(s + step * 0.5);
        if (!seen_by_camera(point) || !(glm::length(to - from) > 0.0)) return -1.0;
        const glm::dvec2 screen = screen_of(to) - screen_of(from);
        const double length = glm::length(screen);
        if (!(length > 1e-3) || (split && length > kSubdividePx)) return length;
        // Within the biases' reach: a texel holding the caster within the lookup's reach of the
        // edge (and a texel more, where the walk may begin) stores it at or beyond the
        // receiver's lowered depth there.
        glm::dvec2 texels;
        double behind;
        if (!reach.in_map(point, texels, behind)) return length;
        const double lowered = receiver_lowering(corner[0], corner[1], corner[2],
                                                 meshes[hit_body].object->casts_shadow, to_map,
                                                 side, options);
        if (!reach.holds_beyond(texels, kReachTexels, 0, behind - lowered)) return length;
        // The band of a shadow edge with receiver pixels on both sides (shadow_edge_error.cpp).
        const glm::dvec2 across = glm::abs(glm::dvec2(screen.y, -screen.x)) / length;
        EdgeSample sample;
        sample.point = point;
        sample.along = glm::normalize(to - from);
        sample.normal = normal;
        sample.screen_length = length;
        sample.screen_along = screen / length;
        sample.band = std::max(across.x, across.y) + across.x + across.y;
        by_receiver[hit_body].push_back(sample);
        return length;
      };
      // About two samples a texel of this map, at most 16, each halved while its shadow edge is
      // longer on screen than kSubdividePx (a receiver the light grazes stretches it), up to
      // kSubdivisions times.
      const int count = std::clamp(static_cast<int>(std::ceil(2.0 * glm::length(tb - ta))), 1, 16);
      struct Part {
        double u, du;
        int depth;
      };
      std::vector<Part> parts;
      for (int k = 0; k < count; ++k) parts.push_back({(k + 0.5) / count, 1.0 / count, 0});
      while (!parts.empty()) {
        const Part part = parts.back();
        parts.pop_back();
        const bool split = part.depth < kSubdivisions;
        if (split && sample_at(part.u, part.du, true) > kSubdividePx) {
          parts.push_back({part.u - part.du * 0.25, part.du * 0.5, part.depth + 1});
          parts.push_back({part.u + part.du * 0.25, part.du * 0.5, part.depth + 1});
        } else if (!split) {
          sample_at(part.u, part.du, false);
        }
      }
    }
    float most = 0.0f;  // the largest estimate on one receiver so far
    for (std::size_t receiver_at = 0; receiver_at < meshes.size(); ++receiver_at) {
      const std::vector<EdgeSample> &samples = by_receiver[receiver_at];
      if (samples.empty()) continue;
      const WorldMesh &receiver = meshes[receiver_at];
      const RayBody &surface = bodies[receiver_at];
      EdgeErrorEstimate estimate;
      for (int size = 0; size < EdgeErrorEstimate::kSizes; ++size) {
        if (size > 0 && !(estimate.pixels[0] > 0.0f)) break;  // nothing to name a size for
        const int map_side = side << size;
        MapReplay replay = caster_replay(frustum, light, map_side, options, caster, receiver);
        double pixels = 0.0;
        for (const EdgeSample &sample : samples) {
          glm::dvec2 edge_texels;
          double edge_depth;
          if (!replay.in_map(sample.point, edge_texels, edge_depth)) continue;
          const glm::dvec2 edge_screen = screen_of(sample.point);
          const dvec3 across = glm::normalize(glm::cross(sample.normal, sample.along));
          // Walks the receiver from the edge along `direction` (world, unit, in the edge's
          // plane; each point brought back onto the receiver along the light's ray) for at most
          // eight texels; the screen extent (pixels, across the edge) of the run of wrong points
          // from the edge, or a negative one where none began within a texel of it. `ends_at_edge`:
          // the run ends where the truth turns (another edge, whose band it is in too).
          auto wrong_run = [&](const dvec3 &direction, bool &ends_at_edge) -> double {
            const double probe_metres = 1e-3 * std::max(glm::length(sample.point - light_position), 1e-6);
            glm::dvec2 next_texels;
            double next_depth;
            if (!replay.in_map(sample.point + direction * probe_metres, next_texels, next_depth)) return -1.0;
            const double texels_per_metre = glm::length(next_texels - edge_texels) / probe_metres;
            if (!(texels_per_metre > 0.0)) return -1.0;
            double farthest = 0.0;  // texels: where the last wrong point lies
            dvec3 farthest_point = sample.point;
            bool wrong_seen = false, wrong_truth = false;
            ends_at_edge = false;
            for (int step = 1; step <= 20; ++step) {
              const double at = step <= 8 ? 0.25 * step : 2.0 + 0.5 * (step - 8);  // texels
              const dvec3 planar = sample.point + direction * (at / texels_per_metre);
              // Back onto the receiver: its surface the light's ray meets within a tenth of the
              // distance from the plane's point.
              const dvec3 ray = planar - light_position;
              double t = 1.1;
              std::size_t k = 0;
              if (!surface.triangles.nearest(light_position, ray, 0.9, t, k)) break;
              const dvec3 point = light_position + ray * t;
              glm::vec3 corner[3];
              corners_of(receiver, k, corner);
              const dvec3 face = glm::cross(dvec3(corner[1] - corner[0]), dvec3(corner[2] - corner[0]));
              if (!(glm::length(face) > 0.0) || !seen_by_camera(point)) break;
              const dvec3 normal = glm::normalize(face);
              // Counted where the camera sees it (past faces turned away from it, which the
              // scene pass culls) and the light shines on its face.
              const bool visible = glm::dot(normal, camera - point) > 0.0 &&
                                   glm::dot(normal, light_position - point) > 0.0 &&
                                   seen_past_near_plane(bodies, camera_clip, camera, point, true);
              // Where another caster or the receiver itself shadows it too, neither the truth
              // nor the map turns on this caster alone; where another light's shadow holds it,
              // the frame's mask is shadow whatever this one says.
              bool alone = visible;
              for (std::size_t m = 0; m < bodies.size() && alone; ++m) {
                if (m == caster_at || !(bodies[m].casts || m == receiver_at)) continue;
                alone = !blocks(bodies[m], light_position, point - light_position);
              }
              alone = alone && !others.hold(bodies, receiver_at, point, normal);
              glm::dvec2 texels;
              double depth;
              bool wrong = false, truth = wrong_truth;
              if (alone && inside_planes(beam.inner, glm::vec3(point)) &&
                  replay.in_map(point, texels, depth)) {
                const double lowered = receiver_lowering(corner[0], corner[1], corner[2],
                                                         receiver.object->casts_shadow, to_map,
                                                         map_side, options);
                truth = blocks(bodies[caster_at], light_position, point - light_position);
                wrong = truth != replay.shadowed(texels, depth - lowered);
              }
              if (wrong) {
                farthest = at + (step <= 8 ? 0.125 : 0.25);
                farthest_point = light_position + (sample.point + direction * (farthest / texels_per_metre) -
                                                   light_position) * t;
                wrong_seen = true, wrong_truth = truth;
              } else if (wrong_seen || at >= 1.0) {
                ends_at_edge = wrong_seen && truth != wrong_truth;
                break;
              }
            }
            if (!wrong_seen) return -1.0;
            const glm::dvec2 offset = screen_of(farthest_point) - edge_screen;
            return std::abs(offset.x * sample.screen_along.y - offset.y * sample.screen_along.x);
          };
          for (const double way : {1.0, -1.0}) {
            bool ends_at_edge = false;
            const double extent = wrong_run(across * way, ends_at_edge);
            if (extent < 0.0) continue;
            const double band = sample.band * (ends_at_edge ? 2.0 : 1.0);
            pixels += std::max(extent - band, 0.0) * sample.screen_length;
          }
        }
        estimate.pixels[size] = static_cast<float>(pixels);
      }
      ContactError &error = result[footprint.caster];
      if (estimate.pixels[0] > most) most = estimate.pixels[0], error.receiver = receiver_at;
      error.pixels.add(estimate);
    }
  }
  return result;
}

}  // namespace gs::depth_map
