// The interior error along a projected shadow's edges (shadow_edge_error.h): each silhouette
// edge thrown from the light onto a receiver polygon's plane (world space), clipped to the
// polygon, measured on screen (pixels) and against the texture (texels) where it lands.
#include "techniques/texel_error/shadow_edge_error.h"
#include "techniques/texel_error/stray_on_screen.h"
#include "techniques/texel_error/surface_cuts.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace gs {
namespace {

// Screen pixels an edge through world point p, running along the tangent-plane direction u
// (unit, in t1, t2 coordinates), moves across itself when the texture moves it one texel
// across itself: with T texels and P pixels per metre, |det P| |T u| / (|det T| |P u|), which
// lies between the smaller and the larger singular value of pixels per texel.
float edge_pixels_per_texel(const FootprintSpace &space, const glm::vec3 &p, const glm::vec3 &t1,
                            const glm::vec3 &t2, const glm::vec2 &u) {
  const glm::mat2 texels = tangent_jacobian(space.light_clip, p, glm::vec2(space.texels), t1, t2);
  const glm::mat2 pixels = tangent_jacobian(space.camera_clip, p, space.pixels, t1, t2);
  const float texel_area = std::abs(glm::determinant(texels));
  const float along_screen = glm::length(pixels * u);
  // A plane edge-on to the light: one texel spans the whole plane. Finite, so it sums.
  if (!(texel_area > 1e-12f)) return 1e6f;
  if (!(along_screen > 1e-12f)) return 0.0f;  // the edge seen end-on: no length to stray along
  return std::min(std::abs(glm::determinant(pixels)) * glm::length(texels * u) /
                      (texel_area * along_screen), 1e6f);
}

// Light screen texels (x right, y down, texel centres at i + 0.5) of a world point before the
// light (w > 0).
glm::vec2 texel_of(const FootprintSpace &space, const glm::vec3 &world) {
  const glm::vec4 c = space.light_clip * glm::vec4(world, 1.0f);
  return (glm::vec2(c.x, -c.y) / c.w * 0.5f + 0.5f) * space.texels;
}

// Where the texture's edge lies near `on_edge` (texels), as a signed distance (texels) along
// `away` (unit, pointing away from the covered side) from the straight edge through it: step 1
// covers the texel centres on the edge's covered side, and the mask is shadow where the
// filtered alpha (`lookup`) is at least half (the Voodoo's filter: more than half). Bisection
// along `away`: two texels back every centre that weighs is covered, two texels on none is.
float texture_edge_offset(const glm::vec2 &on_edge, const glm::vec2 &away, EdgeLookup lookup) {
  auto covered = [&](float x, float y) {
    return glm::dot(glm::vec2(x, y) - on_edge, away) < 0.0f ? 1.0f : 0.0f;
  };
  auto alpha = [&](const glm::vec2 &p) {
    if (lookup == EdgeLookup::kNearest) {
      return covered(std::floor(p.x) + 0.5f, std::floor(p.y) + 0.5f);
    }
    // Bilinear between texel centres: the Voodoo 1's 4-bit fraction (the shim's default), or
    // GL's percentage-closer lookup, taken as exact.
    const float x0 = std::floor(p.x - 0.5f), y0 = std::floor(p.y - 0.5f);
    auto fraction = [&](float f) {
      return lookup == EdgeLookup::kVoodooBilinear ? std::floor(f * 16.0f) / 16.0f : f;
    };
    const float wx = fraction(p.x - 0.5f - x0);
    const float wy = fraction(p.y - 0.5f - y0);
    return (1.0f - wy) * ((1.0f - wx) * covered(x0 + 0.5f, y0 + 0.5f) + wx * covered(x0 + 1.5f, y0 + 0.5f)) +
           wy * ((1.0f - wx) * covered(x0 + 0.5f, y0 + 1.5f) + wx * covered(x0 + 1.5f, y0 + 1.5f));
  };
  // The Voodoo's filter sums 255 times the covered texels' weights (16ths squared) and rounds
  // (sum + 0.5) / 256 down (shader_tmu.cpp): weights of exactly half give alpha 127, which the
  // mask's test against 128 rejects, so its edge needs more than half. The others: half.
  auto shadow = [&](float a) { return lookup == EdgeLookup::kVoodooBilinear ? a > 0.5f : a >= 0.5f; };
  float inside = -2.0f, outside = 2.0f;
  for (int step = 0; step < 12; ++step) {
    const float middle = 0.5f * (inside + outside);
    (shadow(alpha(on_edge + middle * away)) ? inside : outside) = middle;
  }
  return 0.5f * (inside + outside);
}

}  // namespace

void add_shadow_edge_error(const FootprintSpace &space, const glm::vec3 &light_position,
                           const glm::vec3 &camera_position, const glm::vec3 &normal,
                           const std::vector<ClipVertex> &polygon,
                           const std::vector<SilhouetteSegment> &segments,
                           const std::vector<std::size_t> &candidates, EdgeLookup lookup,
                           EdgeErrorEstimate &estimate, const SurfaceCuts *cuts) {
  if (polygon.size() < 3 || (candidates.empty() && !cuts)) return;
  const glm::vec3 origin = polygon[0].world;
  // Distances (world metres) from the polygon's plane, positive on the light's side.
  const float light_height = glm::dot(normal, light_position - origin);
  if (!(light_height > 0.0f)) return;
  // The polygon's sides as inward tangent-plane normals: counter-clockwise about `normal`
  // unless its area says otherwise.
  glm::vec3 area(0.0f);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    area += glm::cross(polygon[i].world - origin, polygon[(i + 1) % polygon.size()].world - origin);
  }
  const float winding = glm::dot(area, normal) < 0.0f ? -1.0f : 1.0f;
  glm::vec3 t1, t2;
  plane_tangents(normal, t1, t2);
  const PlaneFromTexture plane(space, origin, t1, t2);
  // A caster edge within this share of the light's height of the plane touches it.
  constexpr float kContactShare = 1e-3f;
  // The texture's edge strays less than this many texels from a straight edge.
  constexpr float kMostStrayTexels = 0.75f;
  // The polygon's sides along the screen's sides, where texel_footprint clipped it to what the
  // screen shows: the receiver goes on beyond them, and a true shadow edge off the screen there
  // can have its texture's edge stray onto it (issue 14: a floating wall's shadow running off a
  // side of the screen, wrong pixels that no true edge on the screen excuses). A shadow edge is
  // followed past them as far as a stray can reach back (`reach`, screen pixels).
  // Bit i: side i (polygon[i] to polygon[i + 1]) lies along the screen's side (sides past the
  // 64th, which clipping never makes, are taken as the receiver's border).
  std::uint64_t screen_sides = 0;
  for (std::size_t i = 0; i < polygon.size() && i < 64; ++i) {
    const glm::vec3 &p = polygon[i].world, &q = polygon[(i + 1) % polygon.size()].world;
    if (along_screen_side(space, p, q)) screen_sides |= std::uint64_t{1} << i;
  }
  // The reach at the polygon's corners on those sides, found when an edge first needs it.
  float reach = -1.0f;
  auto corner_reach = [&] {
    if (reach >= 0.0f) return reach;
    reach = 0.0f;
    for (std::size_t i = 0; i < polygon.size() && i < 64; ++i) {
      if (!(screen_sides >> i & 1u)) continue;
      for (const glm::vec3 &corner : {polygon[i].world, polygon[(i + 1) % polygon.size()].world}) {
        reach = std::max(reach, stray_reach_pixels(space, plane, texel_of(space, corner)));
      }
    }
    return reach;
  };
  // Strictly inside the screen and before the camera's near plane (camera clip space).
  auto well_inside = [&](const glm::vec3 &world) {
    const glm::vec4 c = space.camera_clip * glm::vec4(world, 1.0f);
    return c.w > 0.0f && c.z >= -c.w && std::abs(c.x) < c.w && std::abs(c.y) < c.w;
  };
  const bool clipped_by_screen = screen_sides != 0;
  const glm::vec2 half_screen = 0.5f * space.pixels;
  // One edge: a silhouette segment, or with `cut_of_mask` the caster's cut through the surface
  // that masks the texture (surface_cuts.h), whose samples a kept contact strip covers stray
  // nowhere.
  auto add_edge = [&](const SilhouetteSegment &segment, bool cut_of_mask) {
    const float height_a = glm::dot(normal, segment.a - origin);
    const float height_b = glm::dot(normal, segment.b - origin);
    // Only what lies between the plane and the light throws a shadow on it (a contact edge
    // rounded a hair below the plane too: a cut by the receiver's plane lies in it); a point as
    // high as the light would throw it to infinity.
    const float highest = light_height * 0.999f;
    const float touching = kContactShare * light_height;
    float from = 0.0f, to = 1.0f;
    keep_non_negative(height_a + touching, height_b + touching, from, to);
    keep_non_negative(highest - height_a, highest - height_b, from, to);
    if (!(from < to)) return;
    const glm::vec3 caster_ends[2] = {glm::mix(segment.a, segment.b, from),
                                      glm::mix(segment.a, segment.b, to)};
    // A cut (no sides known) borders the caster's own pixels on screen, which the error
    // measure takes as a shadow edge: it is a visible edge.
    const bool sides_known = glm::dot(segment.lit_face, segment.lit_face) > 0.0f;
    bool contact = true;
    glm::vec3 shadow_ends[2];
    for (int k = 0; k < 2; ++k) {
      const float height = glm::dot(normal, caster_ends[k] - origin);
      contact = contact && sides_known && height <= kContactShare * light_height;
      shadow_ends[k] = light_position +
                       (caster_ends[k] - light_position) * (light_height / (light_height - height));
    }
    // The shadow edge clipped to the polygon (world space, in its plane). One along a side the
    // polygon shares with its neighbour is in both: each takes half.
    from = 0.0f, to = 1.0f;
    float share = 1.0f;
    for (std::size_t i = 0; i < polygon.size() && from < to; ++i) {
      if (i < 64 && (screen_sides >> i & 1u)) continue;
      const glm::vec3 &p = polygon[i].world, &q = polygon[(i + 1) % polygon.size()].world;
      const glm::vec3 inward = winding * glm::cross(normal, q - p);
      const float at_start = glm::dot(inward, shadow_ends[0] - p);
      const float at_end = glm::dot(inward, shadow_ends[1] - p);
      const float on_side = 1e-4f * glm::dot(q - p, q - p);  // |inward| x 1e-4 |q - p|
      if (std::abs(at_start) <= on_side && std::abs(at_end) <= on_side) share = 0.5f;
      keep_non_negative(at_start, at_end, from, to);
    }
    if (clipped_by_screen && from < to &&
        !(well_inside(glm::mix(shadow_ends[0], shadow_ends[1], from)) &&
          well_inside(glm::mix(shadow_ends[0], shadow_ends[1], to)))) {
      // Within the reach of the polygon's corners, then of the edge's own ends there (its
      // texels grow along it, away from the light).
      float near_from = from, near_to = to;
      keep_near_screen(space, shadow_ends[0], shadow_ends[1], corner_reach(), near_from, near_to);
      if (near_from < near_to) {
        float end_reach = reach;
        for (float f : {near_from, near_to}) {
          const glm::vec3 point = glm::mix(shadow_ends[0], shadow_ends[1], f);
          end_reach = std::max(end_reach, stray_reach_pixels(space, plane, texel_of(space, point)));
        }
        keep_near_screen(space, shadow_ends[0], shadow_ends[1], end_reach, from, to);
      } else {
        from = near_from, to = near_to;
      }
    }
    if (!(from < to)) return;
    const glm::vec3 start = glm::mix(shadow_ends[0], shadow_ends[1], from);
    const glm::vec3 end = glm::mix(shadow_ends[0], shadow_ends[1], to);
    // Seen from behind the lit face, the caster hides the receiver beyond its foot, but for a
    // rim's: there the receiver beyond it is in shadow from the foot on, and seen.
    bool beyond = false;
    if (contact &&
        glm::dot(segment.lit_face, camera_position - 0.5f * (start + end)) < 0.0f) {
      if (!segment.rim) return;
      beyond = true;
    }
    // A visible true edge's band excuses the pixels next to it.
    const bool banded = !contact || beyond;
    const glm::vec2 start_screen = footprint_screen_pixels(space, start);
    const glm::vec2 screen_along = footprint_screen_pixels(space, end) - start_screen;
    auto on_screen = [&](const glm::vec2 &p) {  // a hundredth of a pixel for rounding
      return std::abs(p.x) <= half_screen.x + 0.01f && std::abs(p.y) <= half_screen.y + 0.01f;
    };
    // All of the edge on the screen (so where the polygon is): every point of it has a band.
    const bool all_seen = !clipped_by_screen ||
                          (on_screen(start_screen) && on_screen(start_screen + screen_along));
    const float length = glm::length(screen_along);
    // How far from a visible true edge a wrong pixel is not interior error (src/measure/
    // metrics.cpp): a pixel with a 4-neighbour across the edge is its boundary, up to
    // max(|n.x|, |n.y|) from it across (n: the edge's unit normal on screen), and one within one
    // (Chebyshev) of a boundary pixel its band, up to |n.x| + |n.y| further: 2 pixels for an
    // edge along the screen's rows or columns, 2.12 at 45 degrees.
    const glm::vec2 screen_normal = glm::vec2(screen_along.y, -screen_along.x) / std::max(length, 1e-6f);
    const glm::vec2 across = glm::abs(screen_normal);
    const float excused_pixels = std::max(across.x, across.y) + across.x + across.y;
    const glm::vec2 along(glm::dot(end - start, t1), glm::dot(end - start, t2));
    if (!(length > 1e-3f) || !(glm::length(along) > 0.0f)) return;
    const glm::vec2 u = glm::normalize(along);
    // The edge in the texture, and the side of it the caster covers.
    const glm::vec2 texel_start = texel_of(space, start), texel_end = texel_of(space, end);
    const glm::vec2 texel_along = texel_end - texel_start;
    if (!(glm::length(texel_along) > 1e-6f)) return;
    glm::vec2 away = glm::normalize(glm::vec2(texel_along.y, -texel_along.x));
    if (sides_known && glm::dot(texel_of(space, segment.face_point) - texel_start, away) > 0.0f) {
      away = -away;
    }
    // Screen pixels across the edge per texel: where even the largest stray stays within the
    // excused pixels of a visible edge, nothing counts.
    float most_pixels_per_texel = 0.0f;
    for (const glm::vec3 &end_point : {start, end}) {
      most_pixels_per_texel =
          std::max(most_pixels_per_texel, edge_pixels_per_texel(space, end_point, t1, t2, u));
    }
    // Whether the caster's lit face along the edge hides the true edge at `point` (below).
    auto face_hides = [&](const glm::vec3 &point) {
      return banded && sides_known &&
             segment_crosses_triangle(camera_position, point, segment.a, segment.b,
                                      segment.face_point);
    };
    if (banded && all_seen && most_pixels_per_texel * kMostStrayTexels <= excused_pixels &&
        !face_hides(start) && !face_hides(end) && !face_hides(0.5f * (start + end))) {
      return;
    }
    // Samples every half texel or so along the edge, at most 64 (texels repeat their pattern
    // along a straight edge); where the screen's side cuts the strays short, every other pixel
    // too, at most 256.
    const int texel_samples = static_cast<int>(std::ceil(2.0f * glm::length(texel_along)));
    const int pixel_samples = static_cast<int>(std::ceil(0.5f * length));
    const int samples = all_seen ? std::clamp(texel_samples, 1, 64)
                                 : std::clamp(std::max(texel_samples, pixel_samples), 1, 256);
    const float sample_length = share * length / static_cast<float>(samples);
    for (int k = 0; k < samples; ++k) {
      const float f = (static_cast<float>(k) + 0.5f) / static_cast<float>(samples);
      const glm::vec3 point = glm::mix(start, end, f);
      const glm::vec2 on_edge = texel_of(space, point);
      const glm::vec2 point_screen = footprint_screen_pixels(space, point);
      const float pixels_per_texel = edge_pixels_per_texel(space, point, t1, t2, u);
      // The caster's lit face along the edge hides the true edge here from the camera (a light
      // on the camera's side throws the shadow's edge behind the caster, issue 14: near_17122):
      // no band is seen to excuse the pixels next to it, and what the texture's edge strays out
      // from under the caster counts where the camera sees it past that face.
      const bool hidden = face_hides(point);
      // The true edge here on the screen: its band there excuses the pixels next to it.
      const bool point_seen = (all_seen || on_screen(point_screen)) && !hidden;
      // A kept strip holds the texels on the covered side of a cut: none of them is covered.
      if (cut_of_mask && cuts->strip_holds(on_edge - 0.75f * away)) continue;
      for (int size = 0; size < EdgeErrorEstimate::kSizes; ++size) {
        // The texture 2^size times larger: the same view, its texels that much smaller.
        const float scale = static_cast<float>(1 << size);
        const float per_texel = pixels_per_texel / scale;
        if (banded && point_seen && per_texel * kMostStrayTexels <= excused_pixels) break;
        const float offset = texture_edge_offset(on_edge * scale, away, lookup);  // texels
        // Screen pixels from the true edge to the texture's, across the edge, as far as the
        // screen shows them: where the strayed point lands on the plane (the texels' stretch on
        // either side of the edge), or the Jacobian's estimate where it has no screen position.
        glm::vec2 strayed_screen;
        float stray_pixels = 0.0f;
        glm::vec3 strayed_world;
        if (plane.screen_of(space, on_edge + offset / scale * away, strayed_screen, strayed_world)) {
          const glm::vec2 shown = on_screen_part(half_screen, point_screen, strayed_screen);
          const float strayed_across = std::abs(glm::dot(screen_normal, strayed_screen - point_screen));
          stray_pixels = std::min(strayed_across, 1e6f) * std::max(shown.y - shown.x, 0.0f);
          if (hidden && segment_crosses_triangle(camera_position, strayed_world, segment.a,
                                                 segment.b, segment.face_point)) {
            stray_pixels = 0.0f;  // the stray ends behind the face too: none of it is seen
          }
        } else if (point_seen) {
          stray_pixels = std::abs(offset) * per_texel;
        }
        // Beyond the excused pixels of a visible edge (beyond a rim, what goes under the
        // caster); beside a hidden one, what leaves the caster. Off the screen, no band.
        const float seen = !beyond || offset < 0.0f ? stray_pixels : 0.0f;
        const float stray = banded && !hidden
                                ? std::max(seen - (point_seen ? excused_pixels : 0.0f), 0.0f)
                                : (offset > 0.0f ? stray_pixels : 0.0f);
        estimate.pixels[size] += sample_length * stray;
      }
    }
  };
  for (std::size_t index : candidates) add_edge(segments[index], false);
  if (!cuts) return;
  std::vector<SilhouetteSegment> cut_segments;
  cuts->add_cuts(polygon, normal, cut_segments);
  for (const SilhouetteSegment &cut : cut_segments) add_edge(cut, true);
}

void complete_cuts(const SceneObject &caster, const glm::vec3 &light_position,
                   const std::vector<glm::vec4> &cut_planes, std::vector<SilhouetteSegment> &segments) {
  if (cut_planes.empty()) return;
  const Mesh &mesh = caster_mesh(caster);
  std::vector<glm::vec3> world(mesh.positions.size());  // the caster's vertices, world space
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (std::size_t i = 0; i < world.size(); ++i) {
    world[i] = glm::vec3(caster.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
    low = glm::min(low, world[i]), high = glm::max(high, world[i]);
  }
  // Metres: a cut's ends lie on their triangle within float rounding of the caster's size.
  const float tolerance = 1e-4f * glm::length(high - low);
  struct Face {
    glm::vec3 corner[3];
    glm::vec3 normal;  // unit, by the winding: towards the light
    glm::vec4 plane;   // the cut plane it crosses
  };
  std::vector<Face> faces;
  for (const glm::uvec3 &t : mesh.triangles) {
    const glm::vec3 &a = world[t.x], &b = world[t.y], &c = world[t.z];
    const glm::vec3 n = glm::cross(b - a, c - a);
    if (!(glm::dot(n, light_position - a) > 0.0f) || !(glm::length(n) > 0.0f)) continue;
    for (const glm::vec4 &plane : cut_planes) {
      const float da = glm::dot(plane, glm::vec4(a, 1.0f)), db = glm::dot(plane, glm::vec4(b, 1.0f)),
                  dc = glm::dot(plane, glm::vec4(c, 1.0f));
      if (std::max({da, db, dc}) > 0.0f && std::min({da, db, dc}) < 0.0f) {
        faces.push_back({{a, b, c}, glm::normalize(n), plane});
      }
    }
  }
  auto on_face = [&](const Face &face, const glm::vec3 &p) {
    if (std::abs(glm::dot(face.normal, p - face.corner[0])) > tolerance) return false;
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 &u = face.corner[k], &v = face.corner[(k + 1) % 3];
      if (glm::dot(glm::cross(v - u, p - u), face.normal) < -tolerance * glm::length(v - u)) return false;
    }
    return true;
  };
  for (SilhouetteSegment &segment : segments) {
    if (glm::dot(segment.lit_face, segment.lit_face) > 0.0f) continue;
    for (const Face &face : faces) {
      if (!on_face(face, segment.a) || !on_face(face, segment.b)) continue;
      glm::vec3 sum = segment.a + segment.b;
      float count = 2.0f;
      for (const glm::vec3 &corner : face.corner) {
        if (glm::dot(face.plane, glm::vec4(corner, 1.0f)) > 0.0f) sum += corner, count += 1.0f;
      }
      segment.lit_face = face.normal;
      segment.face_point = sum / count;
      break;
    }
  }
}

void mark_rims(const std::vector<std::pair<glm::vec3, glm::vec3>> &rims,
               std::vector<SilhouetteSegment> &segments) {
  if (rims.empty()) return;
  glm::vec3 low(INFINITY), high(-INFINITY);
  for (const auto &[from, to] : rims) {
    low = glm::min(low, glm::min(from, to));
    high = glm::max(high, glm::max(from, to));
  }
  // Metres: a segment's ends lie on their edge within float rounding of the rims' extent.
  const float tolerance = 1e-4f * glm::length(high - low);
  auto on_rim = [&](const std::pair<glm::vec3, glm::vec3> &rim, const glm::vec3 &p) {
    const glm::vec3 along = rim.second - rim.first;
    const float length_squared = glm::dot(along, along);
    if (!(length_squared > 0.0f)) return false;
    const float f = std::clamp(glm::dot(p - rim.first, along) / length_squared, 0.0f, 1.0f);
    return glm::length(rim.first + f * along - p) <= tolerance;
  };
  for (SilhouetteSegment &segment : segments) {
    segment.rim = std::any_of(rims.begin(), rims.end(), [&](const auto &rim) {
      return on_rim(rim, segment.a) && on_rim(rim, segment.b);
    });
  }
}

}  // namespace gs
