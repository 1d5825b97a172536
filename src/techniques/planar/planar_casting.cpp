// The planar shadow technique's step 1 (the article's Listing 1): every caster triangle facing
// the light clipped to each receiver triangle's plane and edges, projected from the light onto
// that plane. Spaces: world (all geometry, and the shadow polygons it makes); light directions
// (light view x/-z, y/-z: where the light sees a point, used only to reject pairs early).
#include "techniques/planar/planar_shadow.h"

#include "scene/lighting.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/planar/planar_pieces.h"
#include "techniques/geometry/point_in_mesh.h"
#include "techniques/geometry/edge_mesh.h"
#include "techniques/geometry/projection.h"
#include "techniques/light_passes/scene_pass.h"
#include "techniques/planar/triangle_distance.h"

#include <glide.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <string>
#include <tuple>

namespace gs {

void planar::clip_keep(SmallPolygon &polygon, const glm::vec3 &normal, float offset,
                       SmallPolygon &scratch) {
  scratch.n = 0;
  for (std::size_t i = 0; i < polygon.n; ++i) {
    const glm::vec3 &a = polygon.v[i], &b = polygon.v[(i + 1) % polygon.n];
    const float da = glm::dot(normal, a) - offset, db = glm::dot(normal, b) - offset;
    if (da >= 0.0f) scratch.v[scratch.n++] = a;
    if ((da >= 0.0f) != (db >= 0.0f)) {
      // From the same end whichever way the edge is walked: neighbours sharing it meet exactly.
      const bool forward = std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
      scratch.v[scratch.n++] = forward ? a + (b - a) * (da / (da - db))
                                       : b + (a - b) * (db / (db - da));
    }
  }
  std::swap(polygon, scratch);
}

namespace {

using planar::clip_keep, planar::hidden_regions, planar::subtract_hidden;
using planar::CameraCut, planar::CasterTriangle, planar::DirectionBox, planar::HiddenRegion,
    planar::kEmptyBox, planar::kNearLightHeight, planar::PlanarCaster, planar::ReceiverTriangle,
    planar::SmallPolygon;

// The thinnest cut, for a caster passing closer to the light than a millionth of the receiver's
// reach: nearer still, the projection's rounding would move the shadow by more than it holds.
constexpr float kNearestLightShare = 1e-6f;

// An object's vertices in world space and as seen from one light.
struct LitVertices {
  std::vector<glm::vec3> world;
  std::vector<glm::vec2> direction;  // light view x/-z, y/-z
  std::vector<bool> in_front;        // in front of the light's view plane (direction valid)
};

LitVertices light_vertices(const Mesh &mesh, const glm::mat4 &model_to_world,
                           const glm::mat4 &light_view) {
  LitVertices lit;
  const std::size_t n = mesh.positions.size();
  lit.world.resize(n);
  lit.direction.resize(n);
  lit.in_front.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    lit.world[i] = glm::vec3(model_to_world * glm::vec4(mesh.positions[i], 1.0f));
    const glm::vec3 view = glm::vec3(light_view * glm::vec4(lit.world[i], 1.0f));
    lit.in_front[i] = view.z < -1e-4f;
    if (lit.in_front[i]) lit.direction[i] = glm::vec2(view.x, view.y) / -view.z;
  }
  return lit;
}

DirectionBox triangle_box(const LitVertices &lit, const glm::uvec3 &t) {
  if (!lit.in_front[t.x] || !lit.in_front[t.y] || !lit.in_front[t.z]) return {};
  return {glm::min(lit.direction[t.x], glm::min(lit.direction[t.y], lit.direction[t.z])),
          glm::max(lit.direction[t.x], glm::max(lit.direction[t.y], lit.direction[t.z]))};
}

bool faces(const glm::vec3 &light, const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c) {
  return glm::dot(glm::cross(b - a, c - a), light - a) > 0.0f;
}


struct Receiver {
  std::size_t object = 0;
  std::vector<ReceiverTriangle> triangles;
  DirectionBox box = kEmptyBox;
};

PlanarCaster prepare_caster(const Scene &scene, std::size_t index, const SpotLight &light,
                      const glm::mat4 &light_view) {
  const SceneObject &object = scene.objects[index];
  const Mesh &mesh = object.shadow_mesh.triangles.empty() ? object.mesh : object.shadow_mesh;
  const LitVertices lit = light_vertices(mesh, object.model_to_world, light_view);
  PlanarCaster caster;
  caster.object = index;
  // A closed caster's light-facing triangles cover its whole shadow when the light is outside
  // it, so the others are culled (the article's "lightface-culled"). An open one (a tube, a
  // sheet) may show the light only its back faces, and a closed one around the light shows it
  // nothing but them (every ray leaves through one): those cast too, turned to face the light.
  const bool closed =
      is_closed_surface(mesh) && !mesh_surrounds(lit.world, mesh.triangles, light.position);
  for (const glm::uvec3 &t : mesh.triangles) {
    const glm::vec3 &a = lit.world[t.x], &b = lit.world[t.y], &c = lit.world[t.z];
    const bool facing = faces(light.position, a, b, c);
    if (!facing && (closed || !faces(light.position, a, c, b))) continue;
    // Wholly behind the light's view plane: its shadow goes away from every receiver in the cone.
    if (!lit.in_front[t.x] && !lit.in_front[t.y] && !lit.in_front[t.z]) continue;
    const float distance = distance_to_triangle(light.position, a, b, c);
    if (facing) {
      caster.triangles.push_back({{a, b, c}, triangle_box(lit, t), distance});
    } else {
      caster.triangles.push_back({{a, c, b}, triangle_box(lit, t), distance});
    }
    caster.box.include(caster.triangles.back().box);
  }
  const LitVertices drawn = object.shadow_mesh.triangles.empty()
                                ? lit
                                : light_vertices(object.mesh, object.model_to_world, light_view);
  for (const glm::uvec3 &t : object.mesh.triangles) {
    const glm::vec3 &a = drawn.world[t.x], &b = drawn.world[t.y], &c = drawn.world[t.z];
    if (faces(scene.camera.position, a, b, c)) caster.seen.push_back({{a, b, c}, triangle_box(drawn, t)});
  }
  return caster;
}

// `camera` (world) and `pixel` (the tangent of a pixel's angle) size each triangle's slack.
Receiver prepare_receiver(const Scene &scene, std::size_t index, const LightBeam &beam,
                          const SpotLight &light, const glm::mat4 &light_view,
                          const glm::vec3 &camera, float pixel) {
  const SceneObject &object = scene.objects[index];
  const LitVertices lit = light_vertices(object.mesh, object.model_to_world, light_view);
  // Per vertex: the lit piece of the beam that surely holds it (-1: none), and which outer
  // planes it lies beyond (a triangle wholly beyond one of them is out of the light's reach).
  std::vector<int> region(lit.world.size());
  std::vector<std::uint64_t> beyond(lit.world.size(), 0);
  for (std::size_t i = 0; i < lit.world.size(); ++i) {
    region[i] = beam.region_holding(lit.world[i]);
    if (region[i] >= 0) continue;
    for (std::size_t p = 0; p < beam.outer.size() && p < 64; ++p) {
      if (glm::dot(beam.outer[p], glm::vec4(lit.world[i], 1.0f)) < 0.0f) beyond[i] |= 1ull << p;
    }
  }
  Receiver receiver;
  receiver.object = index;
  for (std::size_t k = 0; k < object.mesh.triangles.size(); ++k) {
    const glm::uvec3 &t = object.mesh.triangles[k];
    // The light does not shine on it anywhere: no shadow to cast on it.
    if ((beyond[t.x] & beyond[t.y] & beyond[t.z]) != 0) continue;
    ReceiverTriangle r;
    // Wholly in one lit piece only when its corners share one (a gobo's panes: a triangle
    // with corners in two of them crosses the bar between).
    r.beyond_beam = !(region[t.x] >= 0 && region[t.x] == region[t.y] && region[t.x] == region[t.z]);
    r.index = static_cast<std::uint32_t>(k);
    r.corner = {lit.world[t.x], lit.world[t.y], lit.world[t.z]};
    const glm::vec3 cross = glm::cross(r.corner[1] - r.corner[0], r.corner[2] - r.corner[0]);
    const float length = glm::length(cross);
    if (!(length > 1e-12f)) continue;  // degenerate
    r.normal = cross / length;
    r.offset = glm::dot(r.normal, r.corner[0]);
    r.light_height = glm::dot(r.normal, light.position) - r.offset;
    const glm::dvec3 a(r.corner[0]), b(r.corner[1]), c(r.corner[2]);
    r.exact_normal = glm::normalize(glm::cross(b - a, c - a));
    r.exact_offset = glm::dot(r.exact_normal, a);
    r.exact_light_height = glm::dot(r.exact_normal, glm::dvec3(light.position)) - r.exact_offset;
    // Facing away from the light (or level with it, as far as either precision tells).
    if (r.light_height <= 0.0f || r.exact_light_height <= 0.0) continue;
    for (const glm::vec3 &corner : r.corner) {
      r.light_reach = std::max(r.light_reach, glm::distance(corner, light.position));
    }
    // The edges moved out by what a sixteenth of a pixel (the snap's step) spans on the plane at
    // its most foreshortened, at the corner where that is most, and by no more than the longest
    // edge: the triangle as the scene pass drew it, its corners snapped, lies within them, and
    // step 3 cuts the polygons to the pixels it drew (planar_shadow.cpp).
    float slack = 0.0f, longest = 0.0f;
    for (std::size_t e = 0; e < 3; ++e) {
      const glm::vec3 to = r.corner[e] - camera;
      const float distance = glm::length(to);
      const float sine = std::abs(glm::dot(r.normal, to)) / distance;
      slack = std::max(slack, sine > 0.0f ? distance * pixel / (16.0f * sine) : INFINITY);
      longest = std::max(longest, glm::distance(r.corner[e], r.corner[(e + 1) % 3]));
    }
    slack = std::min(slack, longest);
    for (int e = 0; e < 3; ++e) {
      const glm::vec3 &from = r.corner[static_cast<std::size_t>(e)];
      const glm::vec3 &to = r.corner[static_cast<std::size_t>((e + 1) % 3)];
      r.inward[static_cast<std::size_t>(e)] = glm::cross(r.normal, to - from);
      r.inward_offset[static_cast<std::size_t>(e)] =
          glm::dot(r.inward[static_cast<std::size_t>(e)], from) - slack * glm::length(to - from);
    }
    r.box = triangle_box(lit, t);
    receiver.box.include(r.box);
    receiver.triangles.push_back(r);
  }
  return receiver;
}



// The height above `receiver`'s plane up to which `caster` is cast on it. A point at height d
// projects to distance * h / (h - d) from the light, its distance at least the triangle's
// `light_distance` s: above h (1 - s / reach) it lands beyond the receiver's farthest corner,
// where the edges would cut it anyway. The cut is that, or kNearLightHeight where that is lower
// (a caster a millimetre from the light, as a light inside a box, keeps all it shadows).
float top_share(const CasterTriangle &caster, const ReceiverTriangle &receiver) {
  const float share = std::max(caster.light_distance / receiver.light_reach, kNearestLightShare);
  return std::max(kNearLightHeight, 1.0f - share);
}

float top_of_casting(const CasterTriangle &caster, const ReceiverTriangle &receiver) {
  return receiver.light_height * top_share(caster, receiver);
}

// Keeps the part of a convex polygon (n corners in `v`) where `height` >= 0, as clip_keep.
template <typename Height>
void clip_exact(std::array<glm::dvec3, 5> &v, std::size_t &n, Height height) {
  std::array<glm::dvec3, 5> kept;
  std::size_t k = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 &a = v[i], &b = v[(i + 1) % n];
    const double da = height(a), db = height(b);
    if (da >= 0.0) kept[k++] = a;
    if ((da >= 0.0) != (db >= 0.0)) {
      const bool forward = std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
      kept[k++] = forward ? a + (b - a) * (da / (da - db)) : b + (a - b) * (db / (db - da));
    }
  }
  v = kept, n = k;
}

// Listing 1's lines 05-09 for one pair, in world space: the caster triangle clipped to the part
// between the receiver's plane and the light's height above it, projected from the light onto
// the plane, and clipped against the receiver's three edges within the plane.
void cast_on(const CasterTriangle &caster, const ReceiverTriangle &receiver,
             const glm::vec3 &light, const std::vector<glm::vec4> &beam, SmallPolygon &polygon,
             SmallPolygon &scratch) {
  // The cut between the plane and the top, and the projection, in double on the receiver's exact
  // plane: so every kept corner lies at most kNearLightHeight of the way up to the light however
  // close the plane passes to the light, and projects at most a thousand times as far.
  const double light_height = receiver.exact_light_height;
  const double top = light_height * top_share(caster, receiver);
  auto above = [&](const glm::dvec3 &p) {
    return glm::dot(receiver.exact_normal, p) - receiver.exact_offset;
  };
  std::array<glm::dvec3, 5> cut = {glm::dvec3(caster.corner[0]), glm::dvec3(caster.corner[1]),
                                   glm::dvec3(caster.corner[2])};
  std::size_t n = 3;
  clip_exact(cut, n, above);  // beyond the plane
  clip_exact(cut, n, [&](const glm::dvec3 &p) { return top - above(p); });
  const glm::dvec3 from(light);
  polygon.n = n;
  for (std::size_t i = 0; i < n; ++i) {
    // Along the ray from the light: the plane is reached at light_height / (light_height - d).
    const double along = light_height / (light_height - above(cut[i]));
    polygon.v[i] = glm::vec3(from + (cut[i] - from) * along);
  }
  for (std::size_t e = 0; e < 3 && polygon.n >= 3; ++e) {
    clip_keep(polygon, receiver.inward[e], receiver.inward_offset[e], scratch);
  }
  // Only where the light shines (light_beam.h): the beam's inner planes, on the receiver.
  if (!receiver.beyond_beam) return;
  for (const glm::vec4 &plane : beam) {
    if (polygon.n < 3) break;
    clip_keep(polygon, glm::vec3(plane), -plane.w, scratch);
  }
}


glm::mat4 light_view_matrix(const SpotLight &light) {
  glm::vec3 axis = light.target - light.position;
  axis = glm::length(axis) > 1e-6f ? glm::normalize(axis) : glm::vec3(0.0f, -1.0f, 0.0f);
  const glm::vec3 up = std::abs(axis.y) > 0.99f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  return glm::lookAt(light.position, light.position + axis, up);
}

}  // namespace

PlanarShadows project_and_clip_casters(const Scene &scene) {
  PlanarShadows result;
  result.lights.resize(scene.lights.size());
  SmallPolygon polygon, polygon_b, scratch;
  std::vector<SmallPolygon> parts, kept;
  std::vector<HiddenRegion> hidden;
  // The tangent of a pixel's angle through the camera (vertical field of view; square pixels).
  const float pixel = 2.0f * std::tan(glm::radians(scene.camera.fov_degrees) * 0.5f) /
                      static_cast<float>(std::max(scene.height, 1));
  // The camera's position and near plane (world), as projection.cpp's view matrix looks.
  CameraCut camera_cut;
  camera_cut.position = scene.camera.position;
  const glm::vec3 look = scene.camera.target - scene.camera.position;
  if (glm::length(look) > 0.0f) camera_cut.forward = glm::normalize(look);
  camera_cut.near_offset =
      glm::dot(camera_cut.forward, camera_cut.position) + scene.camera.near_plane;
  for (std::size_t l = 0; l < scene.lights.size(); ++l) {
    const SpotLight &light = scene.lights[l];
    if (light.is_projector()) continue;  // slides cast no shadows
    const glm::mat4 light_view = light_view_matrix(light);
    const LightBeam beam = light_beam(light);
    std::vector<PlanarCaster> casters;
    std::vector<Receiver> receivers;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
      if (scene.objects[i].casts_shadow) casters.push_back(prepare_caster(scene, i, light, light_view));
      if (scene.objects[i].receives_shadow) {
        receivers.push_back(
            prepare_receiver(scene, i, beam, light, light_view, camera_cut.position, pixel));
      }
    }
    ShadowPolygons &out = result.lights[l];
    for (const Receiver &receiver : receivers) {
      for (const PlanarCaster &caster : casters) {
        if (caster.object == receiver.object || !caster.box.overlaps(receiver.box)) continue;
        for (const ReceiverTriangle &r : receiver.triangles) {
          if (!r.box.overlaps(caster.box)) continue;
          bool hidden_known = false;  // `hidden` is found for this pair at its first polygon
          for (const CasterTriangle &c : caster.triangles) {
            if (!c.box.overlaps(r.box)) continue;
            const float top = top_of_casting(c, r);
            // Heights above the receiver's plane: nothing wholly beyond the plane (the receiver
            // is then between it and the light) or wholly level with the light casts on it.
            const std::array<float, 3> height = {glm::dot(r.normal, c.corner[0]) - r.offset,
                                                 glm::dot(r.normal, c.corner[1]) - r.offset,
                                                 glm::dot(r.normal, c.corner[2]) - r.offset};
            if (std::max({height[0], height[1], height[2]}) <= 0.0f) continue;
            if (std::min({height[0], height[1], height[2]}) >= top) continue;
            if (result.pairs_clipped == kMaxClippedPairs) {
              ++result.pairs_skipped;
              continue;
            }
            ++result.pairs_clipped;
            // Beyond the beam's sure inside: one polygon per lit region (light_beam.h).
            const std::size_t pieces = r.beyond_beam ? beam.regions.size() : 1;
            for (std::size_t piece = 0; piece < pieces; ++piece) {
              cast_on(c, r, light.position, beam.regions[piece], polygon, scratch);
              if (polygon.n < 3) continue;
              if (!hidden_known) {
                hidden_regions(caster, r, camera_cut, pixel, hidden, polygon_b,
                               scratch);
                hidden_known = true;
              }
              parts.assign(1, polygon);
              for (const HiddenRegion &region : hidden) {
                subtract_hidden(parts, region, kept, scratch);
              }
              for (const SmallPolygon &part : parts) {
                out.polygons.push_back({static_cast<std::uint32_t>(out.vertices.size()),
                                        static_cast<std::uint32_t>(part.n),
                                        static_cast<std::uint32_t>(receiver.object), r.index});
                out.vertices.insert(out.vertices.end(), part.v.begin(),
                                    part.v.begin() + static_cast<std::ptrdiff_t>(part.n));
              }
            }
          }
        }
      }
    }
  }
  return result;
}

}  // namespace gs
