// The depth map's error beside the shadow edges of a caster close over its receiver
// (depth_map_hover.h). Spaces: world (meshes, planes; rays in double); the map's texture
// coordinates (s, t, r, q: s/q and t/q times the side are texels, r/q the stored depth 0..1);
// camera clip; screen pixels (screen_of: x right, y up, from the screen's centre; the covered
// cells and pixels: x right, rows from the top).
#include "techniques/depth_map/depth_map_hover.h"

#include "techniques/depth_map/depth_map_frame_truth.h"
#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
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
// (pixels), its direction on screen (unit; screen_of's axes) and the band the measure excuses
// beside a shadow edge with receiver pixels on both sides (pixels across it,
// shadow_edge_error.cpp).
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
  FrameTruth frame(scene, meshes, bodies);  // the measure's band
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
        EdgeSample sample;
        sample.point = point;
        sample.along = glm::normalize(to - from);
        sample.normal = normal;
        sample.screen_length = length;
        sample.screen_along = screen / length;
        const glm::dvec2 across = glm::abs(glm::dvec2(screen.y, -screen.x)) / length;
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
      const EdgeErrorEstimate estimate = estimate_by_size(side, [&](int map_side) {
        MapReplay replay = caster_replay(frustum, light, map_side, options, caster, receiver);
        // The screen the wrong runs cover outside the measure's band, in cells a quarter of a
        // pixel wide (x right, rows from the top), each once: beside a corner of the shadow a
        // walk across one edge runs along the next, which that edge's own walks cover too.
        std::set<std::pair<long, long>> covered;
        for (const EdgeSample &sample : samples) {
          glm::dvec2 edge_texels;
          double edge_depth;
          if (!replay.in_map(sample.point, edge_texels, edge_depth)) continue;
          const glm::dvec2 edge_screen = screen_of(sample.point);
          const dvec3 across = glm::normalize(glm::cross(sample.normal, sample.along));
          // Walks the receiver from the edge along `direction` (world, unit, in the edge's
          // plane; each point brought back onto the receiver along the light's ray) for at most
          // eight texels: the run of wrong points from the edge (screen positions, the edge's
          // first and the run's far end last; none where no run began within a texel of it).
          auto wrong_run = [&](const dvec3 &direction) {
            std::vector<glm::dvec2> run;
            const double probe_metres = 1e-3 * std::max(glm::length(sample.point - light_position), 1e-6);
            glm::dvec2 next_texels;
            double next_depth;
            if (!replay.in_map(sample.point + direction * probe_metres, next_texels, next_depth)) return run;
            const double texels_per_metre = glm::length(next_texels - edge_texels) / probe_metres;
            if (!(texels_per_metre > 0.0)) return run;
            run.push_back(edge_screen);
            bool wrong_seen = false, wrong_truth = false;
            dvec3 far_end(0.0);  // world: half a step past the last wrong point
            for (int step = 1; step <= 20; ++step) {
              const double at = step <= 8 ? 0.25 * step : 2.0 + 0.5 * (step - 8);  // texels
              const dvec3 planar = sample.point + direction * (at / texels_per_metre);
              // Back onto the receiver: the first of its surface on the light's ray, no farther
              // from the plane's point than the walk has come (past its rim, or where the
              // light's ray passes to another part of it, the walk ends).
              const dvec3 ray = planar - light_position;
              const double slack = at / texels_per_metre / glm::length(ray);
              double t = 1.0 + slack;
              std::size_t k = 0;
              if (!surface.triangles.nearest(light_position, ray, 1.0 - slack, t, k)) break;
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
                run.push_back(screen_of(point));
                const double half = step <= 8 ? 0.125 : 0.25;  // texels
                far_end = light_position + (planar + direction * (half / texels_per_metre) - light_position) * t;
                wrong_seen = true, wrong_truth = truth;
              } else if (wrong_seen || at >= 1.0) {
                break;
              }
            }
            if (!wrong_seen) return std::vector<glm::dvec2>();
            run.push_back(screen_of(far_end));
            return run;
          };
          for (const double way : {1.0, -1.0}) {
            const std::vector<glm::dvec2> run = wrong_run(across * way);
            // The run as wide along the edge as the sample's share of it, a quarter of a pixel
            // at a time, beyond the edge's band from it (across it on screen) and where its pixel
            // lies outside the measure's band (beside another edge, or a surface's outline the
            // truth turns at).
            const int wide = std::max(1, static_cast<int>(std::ceil(4.0 * sample.screen_length)));
            for (std::size_t k = 1; k < run.size(); ++k) {
              const glm::dvec2 from = run[k - 1], to = run[k];
              const int parts = std::max(1, static_cast<int>(std::ceil(4.0 * glm::length(to - from))));
              for (int j = 1; j <= parts; ++j) {
                const glm::dvec2 q = from + (to - from) * (static_cast<double>(j) / parts);
                const glm::dvec2 offset = q - edge_screen;
                if (!(std::abs(offset.x * sample.screen_along.y - offset.y * sample.screen_along.x) > sample.band)) continue;
                for (int i = 0; i < wide; ++i) {
                  const glm::dvec2 c = q + sample.screen_along * (sample.screen_length * ((i + 0.5) / wide - 0.5));
                  const double x = c.x + 0.5 * space.pixels.x, y = 0.5 * space.pixels.y - c.y;
                  if (!(x >= 0.0 && y >= 0.0 && x < space.pixels.x && y < space.pixels.y) ||
                      frame.in_band(static_cast<int>(x), static_cast<int>(y))) {
                    continue;
                  }
                  covered.emplace(static_cast<long>(std::floor(4.0 * x)), static_cast<long>(std::floor(4.0 * y)));
                }
              }
            }
          }
        }
        return static_cast<double>(covered.size()) / 16.0;
      });
      ContactError &error = result[footprint.caster];
      if (estimate.pixels[0] > most) most = estimate.pixels[0], error.receiver = receiver_at;
      error.pixels.add(estimate);
    }
  }
  return result;
}

}  // namespace gs::depth_map
