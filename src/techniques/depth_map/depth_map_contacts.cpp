// The depth map's error beside the lines where a caster meets a receiver (depth_map_contacts.h).
// Spaces: world (meshes, planes; rays in double); the map's texture coordinates (s, t, r, q, GL:
// s/q and t/q times the side are texels, r/q the stored depth 0..1); camera clip; screen pixels.
#include "techniques/depth_map/depth_map_contacts.h"

#include "techniques/depth_map/depth_map_replay.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace gs::depth_map {
namespace {

// The segment where the triangle a, b, c (world) meets the plane through `origin` with unit
// normal `normal`; false when it does not cross it (or lies in it).
bool plane_cut(const dvec3 &a, const dvec3 &b, const dvec3 &c, const dvec3 &origin,
               const dvec3 &normal, dvec3 &p, dvec3 &q) {
  const dvec3 v[3] = {a, b, c};
  const double size = std::max({glm::length(b - a), glm::length(c - b), glm::length(a - c)});
  const double touching = 1e-5 * size;  // metres: on the plane within rounding
  double h[3];
  for (int k = 0; k < 3; ++k) h[k] = glm::dot(normal, v[k] - origin);
  std::vector<dvec3> cut;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(h[k]) <= touching) cut.push_back(v[k]);
    const int n = (k + 1) % 3;
    if ((h[k] < -touching && h[n] > touching) || (h[k] > touching && h[n] < -touching)) {
      cut.push_back(v[k] + (v[n] - v[k]) * (h[k] / (h[k] - h[n])));
    }
  }
  if (cut.size() != 2) return false;
  p = cut[0], q = cut[1];
  return glm::length(q - p) > touching;
}

}  // namespace

std::vector<ContactError> contact_errors(const Scene &scene, const std::vector<WorldMesh> &meshes,
                                         const LightFrustum &frustum, const SpotLight &light,
                                         int side, const TechniqueOptions &options) {
  std::vector<ContactError> result(scene.objects.size());
  // Every object for the rays: what hides a receiver point from the camera, and what else
  // shadows it (another caster, or the receiver itself: its own shadow is left out of the count).
  const std::vector<RayBody> bodies = ray_bodies(meshes);
  const FootprintSpace space = camera_screen(scene);  // for the screen positions
  const glm::dmat4 camera_clip(space.camera_clip);
  const dvec3 camera(scene.camera.position), light_position(light.position);
  const LightBeam beam = light_beam(light);
  // What the other lights shadow decides whether a foot is an edge in the frame's mask.
  const OtherShadows others(scene, light);
  const glm::mat4 to_map = texture_from_clip() * frustum.projection * frustum.view;
  const int largest_side = side << (EdgeErrorEstimate::kSizes - 1);
  auto box_of = [](const std::vector<glm::vec3> &points, glm::vec3 &low, glm::vec3 &high) {
    low = glm::vec3(INFINITY), high = glm::vec3(-INFINITY);
    for (const glm::vec3 &p : points) low = glm::min(low, p), high = glm::max(high, p);
  };

  // A sample of a foot: the point, its receiver's plane and triangle, and its share of the
  // foot's length on screen (pixels).
  struct FootSample {
    dvec3 point, along, normal;
    dvec3 corner[3];
    double screen_length = 0.0, excused = 0.0;
    glm::dvec2 screen_along;  // the foot's direction on screen, unit
    // Whether the frame shows the receiver a pixel across the foot (cross(normal, along), then
    // the other way) in shadow.
    bool shadowed_across[2] = {false, false};
  };
  std::vector<FootSample> samples;
  for (const WorldMesh &caster : meshes) {
    if (!caster.object->casts_shadow) continue;
    const std::size_t caster_index = static_cast<std::size_t>(caster.object - scene.objects.data());
    const std::size_t caster_at = static_cast<std::size_t>(&caster - meshes.data());
    glm::vec3 caster_low, caster_high;
    box_of(caster.position, caster_low, caster_high);
    float most = 0.0f;  // the largest estimate on one receiver so far
    for (const WorldMesh &receiver : meshes) {
      if (!receiver.object->receives_shadow || &receiver == &caster) continue;
      const std::size_t receiver_at = static_cast<std::size_t>(&receiver - meshes.data());
      samples.clear();
      for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
        const glm::vec3 &a = receiver.position[t.x], &b = receiver.position[t.y], &c = receiver.position[t.z];
        const glm::vec3 face = glm::cross(b - a, c - a);
        if (!(glm::dot(face, light.position - a) > 0.0f) || !(glm::length(face) > 0.0f)) continue;
        const glm::vec3 low = glm::min(a, glm::min(b, c)), high = glm::max(a, glm::max(b, c));
        if (glm::any(glm::greaterThan(low, caster_high)) || glm::any(glm::lessThan(high, caster_low))) continue;
        const dvec3 normal = glm::normalize(dvec3(face));
        const dvec3 corner[3] = {dvec3(a), dvec3(b), dvec3(c)};
        for (const glm::uvec3 &u : caster.object->mesh.triangles) {
          const dvec3 ca(caster.position[u.x]), cb(caster.position[u.y]), cc(caster.position[u.z]);
          dvec3 p, q;
          if (!plane_cut(ca, cb, cc, corner[0], normal, p, q)) continue;
          // The cut clipped to the receiver's triangle (inward side normals in its plane).
          double from = 0.0, to = 1.0;
          for (int k = 0; k < 3 && from < to; ++k) {
            const dvec3 inward = glm::cross(normal, corner[(k + 1) % 3] - corner[k]);
            const double at_p = glm::dot(inward, p - corner[k]), at_q = glm::dot(inward, q - corner[k]);
            if (at_p < 0.0 && at_q < 0.0) from = 1.0, to = 0.0;
            else if (at_p < 0.0) from = std::max(from, at_p / (at_p - at_q));
            else if (at_q < 0.0) to = std::min(to, at_p / (at_p - at_q));
          }
          if (!(from < to)) continue;
          const dvec3 start = p + (q - p) * from, end = p + (q - p) * to;
          const glm::vec4 cs = space.camera_clip * glm::vec4(glm::vec3(start), 1.0f);
          const glm::vec4 ce = space.camera_clip * glm::vec4(glm::vec3(end), 1.0f);
          if (!(cs.w > 0.0f && ce.w > 0.0f)) continue;
          const glm::vec2 screen = footprint_screen_pixels(space, glm::vec3(end)) -
                                   footprint_screen_pixels(space, glm::vec3(start));
          const double length = glm::length(glm::dvec2(screen));
          if (!(length > 1e-3)) continue;
          // A pixel next to the foot's edge on screen is excused (shadow_edge_error.cpp) where
          // the caster's own pixels count: they make the edge a visible one. Where they do not,
          // the receiver's pixels whose centres lie within half a pixel of the foot may be the
          // caster's all the same (the rasterizer rounds its outline), so no less is excused.
          const glm::dvec2 across = glm::abs(glm::dvec2(screen.y, -screen.x)) / length;
          const double excused =
              caster.object->receives_shadow ? std::max(across.x, across.y) + across.x + across.y : 0.5;
          // About two samples a texel of the map at its largest size, at most 16.
          glm::dvec2 ts, te;
          double ds, de;
          MapReplay probe(frustum, light, side, options);
          const double texels = probe.in_map(start, ts, ds) && probe.in_map(end, te, de)
                                    ? glm::length(te - ts) * (largest_side / side) : 1.0;
          const int count = std::clamp(static_cast<int>(std::ceil(texels)), 1, 16);
          for (int k = 0; k < count; ++k) {
            FootSample sample;
            sample.point = start + (end - start) * ((k + 0.5) / count);
            sample.along = glm::normalize(end - start);
            sample.normal = normal;
            for (int m = 0; m < 3; ++m) sample.corner[m] = corner[m];
            sample.screen_length = length / count;
            sample.screen_along = glm::dvec2(screen) / length;
            sample.excused = excused;
            samples.push_back(sample);
          }
        }
      }
      if (samples.empty()) continue;
      auto in_other_shadow = [&](const dvec3 &point, const dvec3 &normal) {
        return others.hold(bodies, receiver_at, point, normal);
      };
      // Whether the frame shows the receiver a pixel from the foot of `sample` along `direction`
      // (world, unit, in its plane) in shadow: seen by the camera (past faces turned away from
      // it, which the scene pass culls), and another light shining on it blocked there by any
      // caster or the receiver itself, or this light by a caster other than this one.
      auto shadowed_across = [&](const FootSample &sample, const dvec3 &direction) {
        const glm::dvec2 foot_screen(footprint_screen_pixels(space, glm::vec3(sample.point)));
        const double probe_metres = 1e-3 * std::max(glm::length(sample.point - camera), 1e-6);
        const glm::dvec2 probe_screen(
            footprint_screen_pixels(space, glm::vec3(sample.point + direction * probe_metres)));
        const double pixels_per_metre = glm::length(probe_screen - foot_screen) / probe_metres;
        if (!(pixels_per_metre > 0.0)) return false;
        const dvec3 point = sample.point + direction / pixels_per_metre;
        if (!(glm::dot(sample.normal, camera - point) > 0.0) ||
            !seen_past_near_plane(bodies, camera_clip, camera, point, true)) {
          return false;
        }
        for (std::size_t m = 0; m < bodies.size(); ++m) {
          if (m == caster_at || !bodies[m].casts) continue;
          if (blocks(bodies[m], light_position, point - light_position)) return true;
        }
        return in_other_shadow(point, sample.normal);
      };
      for (FootSample &sample : samples) {
        const dvec3 across = glm::normalize(glm::cross(sample.normal, sample.along));
        sample.shadowed_across[0] = shadowed_across(sample, across);
        sample.shadowed_across[1] = shadowed_across(sample, -across);
      }
      const std::size_t receiver_index = static_cast<std::size_t>(receiver.object - scene.objects.data());
      const EdgeErrorEstimate estimate = estimate_by_size(side, [&](int map_side) {
        MapReplay replay = caster_replay(frustum, light, map_side, options, caster, receiver);
        double pixels = 0.0;
        for (const FootSample &sample : samples) {
          const double lowered =
              receiver_lowering(glm::vec3(sample.corner[0]), glm::vec3(sample.corner[1]),
                                glm::vec3(sample.corner[2]), receiver.object->casts_shadow,
                                to_map, map_side, options);
          const dvec3 across = glm::normalize(glm::cross(sample.normal, sample.along));
          glm::dvec2 foot_texels;
          double foot_depth;
          if (!replay.in_map(sample.point, foot_texels, foot_depth)) continue;
          const glm::dvec2 foot_screen(footprint_screen_pixels(space, glm::vec3(sample.point)));
          // Walks the receiver from the foot along `direction` (world, unit, in its plane), at
          // most eight texels and not past its triangle (`left`: the walk stopped there); the
          // screen extent (pixels) of the run of wrong points beside the foot (straight across
          // it: its whole length; `slanted` along an edge: only its part across the foot), or a
          // negative one where none began there.
          auto wrong_run = [&](const dvec3 &direction, bool slanted, bool culled, bool &ends_at_edge,
                               bool &left, bool &false_light) -> double {
            // Metres along `direction` per texel of this map, from a small step.
            const double probe_metres = 1e-3 * std::max(glm::length(sample.point - light_position), 1e-6);
            glm::dvec2 next_texels;
            double next_depth;
            if (!replay.in_map(sample.point + direction * probe_metres, next_texels, next_depth)) return -1.0;
            const double texels_per_metre = glm::length(next_texels - foot_texels) / probe_metres;
            if (!(texels_per_metre > 0.0)) return -1.0;
            // Walked a quarter texel at a time for two texels, then half a texel to eight.
            double farthest = 0.0;  // texels: where the last wrong point lies
            bool wrong_seen = false, wrong_truth = false;
            ends_at_edge = false, left = false;
            for (int step = 1; step <= 20; ++step) {
              const double at = step <= 8 ? 0.25 * step : 2.0 + 0.5 * (step - 8);  // texels
              const dvec3 point = sample.point + direction * (at / texels_per_metre);
              bool inside = true;
              for (int m = 0; m < 3; ++m) {
                const dvec3 inward = glm::cross(sample.normal, sample.corner[(m + 1) % 3] - sample.corner[m]);
                inside = inside && glm::dot(inward, point - sample.corner[m]) >= 0.0;
              }
              if (!inside) {
                left = true;
                break;
              }
              const glm::dvec4 seen = camera_clip * glm::dvec4(point, 1.0);
              if (!(seen.w > 0.0) || std::abs(seen.x) > seen.w || std::abs(seen.y) > seen.w) break;
              // Counted where the camera sees it past the caster and the light shines on it.
              const bool visible = glm::dot(sample.normal, camera - point) > 0.0 &&
                                   seen_past_near_plane(bodies, camera_clip, camera, point, culled);
              // Where another caster or the receiver itself shadows it too, neither the truth
              // nor the map turns on this caster alone; where another light's shadow holds it,
              // the frame's mask (every light's shadow at once) is shadow whatever this one says.
              bool alone = true;
              for (std::size_t m = 0; m < bodies.size() && alone && visible; ++m) {
                if (m == caster_at || !(bodies[m].casts || m == receiver_at)) continue;
                alone = !blocks(bodies[m], light_position, point - light_position);
              }
              alone = alone && visible && !in_other_shadow(point, sample.normal);
              glm::dvec2 texels;
              double depth;
              bool wrong = false, truth = wrong_truth;
              if (visible && alone && inside_planes(beam.inner, glm::vec3(point)) &&
                  replay.in_map(point, texels, depth)) {
                truth = blocks(bodies[caster_at], light_position, point - light_position);
                wrong = truth != replay.shadowed(texels, depth - lowered);
              }
              if (wrong) {
                farthest = at + (step <= 8 ? 0.125 : 0.25);
                wrong_seen = true, wrong_truth = truth;
              } else if (wrong_seen || at >= 1.0) {
                // Past the run of wrong points beside the foot, or none began there. A run that
                // ends at a true edge (the truth turns) is that edge's band there too.
                ends_at_edge = wrong_seen && truth != wrong_truth;
                break;
              }
            }
            if (!wrong_seen) return -1.0;
            false_light = wrong_truth;
            const dvec3 reach = sample.point + direction * (farthest / texels_per_metre);
            const glm::dvec2 offset = glm::dvec2(footprint_screen_pixels(space, glm::vec3(reach))) - foot_screen;
            return slanted ? std::abs(offset.x * sample.screen_along.y - offset.y * sample.screen_along.x)
                           : glm::length(offset);
          };
          // The triangle's longest edge (world, unit): on a long thin triangle (a cylinder's side
          // under a light along its axis) the walk straight across the foot leaves it within a
          // texel, while the receiver-plane bias, one for the whole triangle, lifts all of it
          // past the caster (sunk_16563: 1.4% interior false light on a cylinder through a plate,
          // estimated at 0.7 pixels). Where the straight walk left its triangle, it is walked
          // along that edge too, and the larger run on that side counts. (Only there: beside a
          // curved foot on a wide triangle, a slanted walk runs along the band of the foot's
          // other samples and counts it again.)
          dvec3 longest(0.0);
          for (int m = 0; m < 3; ++m) {
            const dvec3 edge = sample.corner[(m + 1) % 3] - sample.corner[m];
            if (glm::length(edge) > glm::length(longest)) longest = edge;
          }
          longest = glm::normalize(longest);
          for (const double way : {1.0, -1.0}) {
            const dvec3 straight = across * way;
            // Where the frame has the receiver across the foot in shadow too (another light's,
            // or another caster's), false light beside the foot is next to no edge, and the
            // foot's band excuses none of it: a sheet through a receiver with lights on either
            // side of it starts both shadows at the cut (near-extra-lights_18628: each light's
            // gap at the cut within its band, 22 px of interior false light between the two).
            // That side and the run are then looked for as the frame shows them, past faces
            // turned away from the camera (the sheet seen from behind). Elsewhere the walk is the
            // one this estimate was measured with: every face hides (seen past back faces, the
            // open tube of dc4_tube_around_light_map64 estimates 69 px for about 40 measured).
            const bool seam = sample.shadowed_across[way > 0.0 ? 1 : 0];
            bool ends_at_edge = false, left = false, false_light = false;
            double extent = wrong_run(straight, false, seam, ends_at_edge, left, false_light);
            auto band_of = [&] {
              const double foot = seam && false_light ? 0.0 : sample.excused;
              return foot + (ends_at_edge ? sample.excused : 0.0);
            };
            double error = extent < 0.0 ? 0.0 : std::max(extent - band_of(), 0.0);
            const double slant = glm::dot(longest, straight);
            if (left && std::abs(slant) > 0.0) {
              extent = wrong_run(longest * (slant > 0.0 ? 1.0 : -1.0), true, seam, ends_at_edge,
                                 left, false_light);
              if (extent >= 0.0) error = std::max(error, extent - band_of());
            }
            pixels += error * sample.screen_length;
          }
        }
        return static_cast<double>(pixels);
      });
      ContactError &error = result[caster_index];
      if (estimate.pixels[0] > most) most = estimate.pixels[0], error.receiver = receiver_index;
      error.pixels.add(estimate);
    }
  }
  return result;
}

}  // namespace gs::depth_map
