// Internal to the depth-map technique: a replay of step 1's map and of the mask's lookup at
// chosen points, for the estimates that refuse a shadow the map would cast wrong (beside the
// lines where casters meet receivers, depth_map_contacts.h; on a caster's own lit side,
// depth_map_self_shadow.h), and the objects as ray bodies for the truth those estimates compare
// with. Spaces: world (meshes, rays in double); the map's texture coordinates (s, t, r, q, GL: s/q
// and t/q times the side are texels, r/q the stored depth 0..1).
#pragma once

#include "techniques/depth_map/depth_map_facets.h"
#include "techniques/depth_map/depth_map_lookup.h"
#include "techniques/depth_map/depth_map_passes.h"
#include "techniques/geometry/light_beam.h"
#include "techniques/geometry/projection.h"
#include "techniques/texel_error/shadow_edge_error.h"
#include "techniques/texel_error/texel_footprint.h"
#include "techniques/depth_map/triangle_bvh.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gs::depth_map {

using glm::dvec3;

// A surface as step 1 draws it into the map: its triangles as drawn (facet-pushed, world) with
// each one's slope term (glPolygonOffset's factor times its largest window depth change per
// texel), and as they are (the bounded copy slides these back).
struct DrawnSurface {
  TriangleBvh pushed, original;
  std::vector<double> slope_term;
};

// The camera's clip matrix and the screen's size (pixels), to find a world point's pixel.
inline FootprintSpace camera_screen(const Scene &scene) {
  FootprintSpace space;
  space.camera_clip =
      camera_projection(scene.camera, scene.width, scene.height) * camera_view(scene.camera);
  space.pixels = glm::vec2(static_cast<float>(scene.width), static_cast<float>(scene.height));
  return space;
}

// One map size's replay of the lookup.
class MapReplay {
 public:
  MapReplay(const LightFrustum &frustum, const SpotLight &light, int side,
            const TechniqueOptions &options)
      : light_(light.position), side_(side), options_(options) {
    to_map_ = glm::dmat4(texture_from_clip() * frustum.projection * frustum.view);
    from_clip_ = glm::inverse(glm::dmat4(frustum.projection * frustum.view));
    view_ = glm::dmat4(frustum.view);
    texel_per_metre_ = frustum.texel_per_metre(side);
    units_ = options.depth_bias_units * std::ldexp(1.0, options.depth_map_bits == 16 ? -16 : -24);
    bounded_ = std::isfinite(options.depth_bias_bound) && options.depth_bias_bound >= 0.0f;
  }

  // Adds `mesh` (world) as step 1 draws it at this size.
  void add(const WorldMesh &mesh, const LightFrustum &frustum) {
    const bool pushed = mesh.object->receives_shadow && options_.depth_map_facet_bias;
    const std::vector<glm::vec3> drawn =
        pushed ? facet_pushed_positions(mesh, frustum, light_, side_) : mesh.position;
    DrawnSurface surface;
    std::vector<dvec3> pushed_corners, original_corners;  // three a triangle (world)
    for (const glm::uvec3 &t : mesh.object->mesh.triangles) {
      glm::dvec4 corner[3];  // S, T (texels), r, q of each corner, scaled to unit size
      for (int k = 0; k < 3; ++k) {
        pushed_corners.push_back(dvec3(drawn[t[k]]));
        original_corners.push_back(dvec3(mesh.position[t[k]]));
        const glm::dvec4 m = to_map_ * glm::dvec4(pushed_corners.back(), 1.0);
        const glm::dvec4 h(m.x * side_, m.y * side_, m.z, m.w);
        const double scale = std::max({std::abs(h.x), std::abs(h.y), std::abs(h.w), 1e-30});
        corner[k] = h / scale;
      }
      // The window-space plane r/q = gx s/q + gy t/q + z0 through the homogeneous corners (r =
      // gx S + gy T + z0 q at each, Cramer's rule), as GL takes it from the part it keeps; edge-on
      // (a zero determinant) it has none, and the bounded copy decides.
      auto det3 = [](const dvec3 &a, const dvec3 &b, const dvec3 &c) {
        return glm::dot(a, glm::cross(b, c));
      };
      const dvec3 s(corner[0].x, corner[1].x, corner[2].x), tt(corner[0].y, corner[1].y, corner[2].y);
      const dvec3 q(corner[0].w, corner[1].w, corner[2].w), r(corner[0].z, corner[1].z, corner[2].z);
      const double det = det3(s, tt, q);
      double term = INFINITY;
      if (std::abs(det) > 1e-12) {
        const double gx = det3(r, tt, q) / det, gy = det3(s, r, q) / det;
        term = options_.depth_bias_slope * std::max(std::abs(gx), std::abs(gy));
      }
      surface.slope_term.push_back(term);
    }
    surface.pushed = TriangleBvh(std::move(pushed_corners));
    surface.original = TriangleBvh(std::move(original_corners));
    surfaces_.push_back(std::move(surface));
  }

  // r/q of a world point, and its s/q, t/q in texels; false behind the light's plane.
  bool in_map(const dvec3 &p, glm::dvec2 &texels, double &depth) const {
    const glm::dvec4 m = to_map_ * glm::dvec4(p, 1.0);
    if (!(m.w > 0.0)) return false;
    texels = glm::dvec2(m.x, m.y) / m.w * static_cast<double>(side_);
    depth = m.z / m.w;
    return true;
  }

  // Whether the lookup at `texels` with the compared depth `depth` says shadow.
  bool shadowed(const glm::dvec2 &texels, double depth) { return shadowing(texels, depth) >= 0; }

  // Where the lookup says shadow, the surface (its index, in the order added) that the heaviest
  // of the texels saying so holds; -1 where it says lit.
  int shadowing(const glm::dvec2 &texels, double depth) {
    if (!options_.depth_map_linear) {
      const Texel &t = stored(static_cast<int>(std::floor(texels.x)), static_cast<int>(std::floor(texels.y)));
      return depth > t.depth ? t.surface : -1;
    }
    const double x0 = std::floor(texels.x - 0.5), y0 = std::floor(texels.y - 0.5);
    const double wx = texels.x - 0.5 - x0, wy = texels.y - 0.5 - y0;
    const int i = static_cast<int>(x0), j = static_cast<int>(y0);
    const double weight[4] = {(1.0 - wy) * (1.0 - wx), (1.0 - wy) * wx, wy * (1.0 - wx), wy * wx};
    double share = 0.0, heaviest = -1.0;
    int surface = -1;
    for (int k = 0; k < 4; ++k) {
      const Texel &t = stored(i + (k & 1), j + (k >> 1));
      if (!(depth > t.depth)) continue;
      share += weight[k];
      if (weight[k] > heaviest) heaviest = weight[k], surface = t.surface;
    }
    return share >= 0.5 ? surface : -1;
  }

  // Whether a texel whose centre lies within `reach` texels (along each axis) of `texels` holds
  // surface `surface` (its index, in the order added) at a stored depth (r/q) of `depth` or
  // more: where one does, the lookup beside it may compare lit what that surface shadows.
  bool holds_beyond(const glm::dvec2 &texels, double reach, int surface, double depth) {
    const int x0 = static_cast<int>(std::ceil(texels.x - 0.5 - reach));
    const int x1 = static_cast<int>(std::floor(texels.x - 0.5 + reach));
    const int y0 = static_cast<int>(std::ceil(texels.y - 0.5 - reach));
    const int y1 = static_cast<int>(std::floor(texels.y - 0.5 + reach));
    for (int j = y0; j <= y1; ++j) {
      for (int i = x0; i <= x1; ++i) {
        const Texel &t = stored(i, j);
        if (t.surface == surface && t.depth >= depth) return true;
      }
    }
    return false;
  }

  int side() const { return side_; }

 private:
  // What a texel holds: its depth, and the surface that drew it (-1: none).
  struct Texel {
    double depth = 1.0;
    int surface = -1;
  };

  // The depth texel (i, j) holds: the nearest surface on the ray through its centre with its
  // offset, or the nearer of that and the bounded copy's; 1 (cleared, and the lit border) where
  // nothing is drawn or outside the map.
  const Texel &stored(int i, int j) {
    static const Texel outside;
    if (i < 0 || j < 0 || i >= side_ || j >= side_) return outside;
    const long long key = static_cast<long long>(j) * side_ + i;
    const auto known = texels_.find(key);
    if (known != texels_.end()) return known->second;
    const double x = (i + 0.5) / side_ * 2.0 - 1.0, y = (j + 0.5) / side_ * 2.0 - 1.0;
    const glm::dvec4 far_point = from_clip_ * glm::dvec4(x, y, 1.0, 1.0);
    const dvec3 o(light_);
    const dvec3 d = dvec3(far_point) / far_point.w - o;
    Texel nearest;
    for (std::size_t k = 0; k < surfaces_.size(); ++k) {
      const DrawnSurface &surface = surfaces_[k];
      double t = INFINITY;
      std::size_t hit = 0;
      if (surface.pushed.nearest(o, d, 0.0, t, hit)) {
        const double depth = depth_of(o + d * t) + surface.slope_term[hit] + units_;
        if (depth < nearest.depth) nearest = {depth, static_cast<int>(k)};
      }
      t = INFINITY;
      if (bounded_ && surface.original.nearest(o, d, 0.0, t, hit)) {
        const dvec3 p = o + d * t;
        const double light_depth = std::max(-(view_ * glm::dvec4(p, 1.0)).z, 0.0);
        const double back = options_.depth_bias_bound * texel_per_metre_ * light_depth;
        const double depth = depth_of(p + glm::normalize(d) * back) + units_;
        if (depth < nearest.depth) nearest = {depth, static_cast<int>(k)};
      }
    }
    return texels_.emplace(key, nearest).first->second;
  }

  double depth_of(const dvec3 &p) const {
    const glm::dvec4 m = to_map_ * glm::dvec4(p, 1.0);
    return m.z / m.w;
  }

  glm::vec3 light_;
  int side_;
  const TechniqueOptions &options_;
  glm::dmat4 to_map_{1.0}, from_clip_{1.0}, view_{1.0};
  double texel_per_metre_ = 0.0, units_ = 0.0;
  bool bounded_ = true;
  std::vector<DrawnSurface> surfaces_;
  std::unordered_map<long long, Texel> texels_;
};

// The map of `side` texels as step 1 draws it where `caster`'s shadow meets `receiver`: the
// caster, and the receiver too when it casts (its own depths then decide beside the caster's).
inline MapReplay caster_replay(const LightFrustum &frustum, const SpotLight &light, int side,
                               const TechniqueOptions &options, const WorldMesh &caster,
                               const WorldMesh &receiver) {
  MapReplay replay(frustum, light, side, options);
  replay.add(caster, frustum);
  if (receiver.object->casts_shadow && &receiver != &caster) replay.add(receiver, frustum);
  return replay;
}

// An estimate at the map's `side` and at 2, 4 and 8 times it: `count(map_side)` at each (screen
// pixels), and no larger size tried where the side's own finds nothing (none to name).
template <typename Count>
EdgeErrorEstimate estimate_by_size(int side, Count &&count) {
  EdgeErrorEstimate estimate;
  for (int size = 0; size < EdgeErrorEstimate::kSizes; ++size) {
    if (size > 0 && !(estimate.pixels[0] > 0.0f)) break;
    estimate.pixels[size] = static_cast<float>(count(side << size));
  }
  return estimate;
}

// The r/q a receiver triangle (corners a, b, c, world) compares lowered by in the `side`-texel
// map whose texture coordinates `to_map` gives (world to s, t, r, q): its receiver-plane bias
// (depth_map_lookup.h) when the receiver casts, none when it does not.
inline double receiver_lowering(const glm::vec3 &a, const glm::vec3 &b, const glm::vec3 &c,
                                bool casts, const glm::mat4 &to_map, int side,
                                const TechniqueOptions &options) {
  if (!casts) return 0.0;
  const std::vector<glm::vec3> corners = {a, b, c};
  const glm::vec4 plain = to_map * glm::vec4(a, 1.0f);
  const glm::vec4 biased = biased_map_coords(corners, to_map, side, options.depth_bias_receiver)[0];
  return plain.w != 0.0f ? static_cast<double>((plain.z - biased.z) / plain.w) : 0.0;
}

// An object's triangles (world) and their box, for rays along segments.
struct RayBody {
  TriangleBvh triangles;
  dvec3 low{INFINITY}, high{-INFINITY};
  bool casts = false;
};

// Whether the segment o .. o + d (its far end left out: the point it reaches) meets the body;
// with `facing_only`, only its triangles facing o (TriangleBvh::any).
inline bool blocks(const RayBody &body, const dvec3 &o, const dvec3 &d, bool facing_only = false) {
  double from = 0.0, to = 1.0;  // the segment clipped to the box (slabs)
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-300) {
      if (o[k] < body.low[k] || o[k] > body.high[k]) return false;
      continue;
    }
    double near = (body.low[k] - o[k]) / d[k], far = (body.high[k] - o[k]) / d[k];
    if (near > far) std::swap(near, far);
    from = std::max(from, near), to = std::min(to, far);
    if (from > to) return false;
  }
  return body.triangles.any(o, d, 1e-9, 1.0 - 1e-5, facing_only);
}

// Whether no body of `bodies` hides `point` (world) from the camera at `camera` (world), whose
// `camera_clip` maps world to its clip space: the segment from the point to where it crosses the
// near plane (clip z + w = 0, linear along it; negative at the camera) is tested, as a face
// nearer than that plane is clipped away and hides nothing (a camera whose near plane cuts into
// a hut's wall sees inside it). With `culled`, only faces turned towards the camera hide it, as
// the scene pass culls the others (an open mesh seen from behind hides nothing: the frame and
// the truth show what lies beyond it); without, every face does, which the estimates that were
// measured that way keep. False for a point nearer than the near plane.
inline bool seen_past_near_plane(const std::vector<RayBody> &bodies, const glm::dmat4 &camera_clip,
                                 const dvec3 &camera, const dvec3 &point, bool culled = false) {
  const double near_point = [&] {
    const glm::dvec4 p = camera_clip * glm::dvec4(point, 1.0);
    return p.z + p.w;
  }();
  if (!(near_point > 0.0)) return false;
  const glm::dvec4 eye = camera_clip * glm::dvec4(camera, 1.0);
  const double t_near = near_point / (near_point - (eye.z + eye.w));  // 0 point .. 1 camera
  const dvec3 start = point + (camera - point) * t_near;
  for (const RayBody &body : bodies) {
    if (blocks(body, start, point - start, culled)) return false;
  }
  return true;
}

// The frame's other shadowing lights than `light` (slides cast none) with their beams: the mask
// is the union of every light's shadow, so where one of them shadows a point the frame shows it
// in shadow whatever `light`'s map says.
class OtherShadows {
 public:
  OtherShadows(const Scene &scene, const SpotLight &light) {
    for (const SpotLight &other : scene.lights) {
      if (&other != &light && !other.is_projector()) others_.emplace_back(&other, light_beam(other));
    }
  }

  // Whether another light shines on `point` (world; `normal` its surface's plane's, unit) and
  // any body of `bodies` that casts, or the receiver `receiver_at` itself, blocks it there.
  bool hold(const std::vector<RayBody> &bodies, std::size_t receiver_at, const dvec3 &point,
            const dvec3 &normal) const {
    for (const auto &[other, other_beam] : others_) {
      const dvec3 from(other->position);
      if (!(glm::dot(normal, from - point) > 0.0) ||
          !inside_planes(other_beam.inner, glm::vec3(point))) {
        continue;
      }
      for (std::size_t m = 0; m < bodies.size(); ++m) {
        if ((bodies[m].casts || m == receiver_at) && blocks(bodies[m], from, point - from)) return true;
      }
    }
    return false;
  }

 private:
  std::vector<std::pair<const SpotLight *, LightBeam>> others_;
};

// Every object of `meshes` (world) as a ray body, in their order.
inline std::vector<RayBody> ray_bodies(const std::vector<WorldMesh> &meshes) {
  std::vector<RayBody> bodies(meshes.size());
  for (std::size_t m = 0; m < meshes.size(); ++m) {
    bodies[m].casts = meshes[m].object->casts_shadow;
    std::vector<dvec3> corners;  // three a triangle (world)
    for (const glm::uvec3 &u : meshes[m].object->mesh.triangles) {
      for (int k = 0; k < 3; ++k) {
        const dvec3 p(meshes[m].position[u[k]]);
        corners.push_back(p);
        bodies[m].low = glm::min(bodies[m].low, p), bodies[m].high = glm::max(bodies[m].high, p);
      }
    }
    bodies[m].triangles = TriangleBvh(std::move(corners));
  }
  return bodies;
}

}  // namespace gs::depth_map
