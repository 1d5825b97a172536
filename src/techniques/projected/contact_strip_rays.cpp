// The light's rays beside a contact strip (contact_strip_rays.h): world space triangles, the
// light's Glide screen (texels, y down) for where a ray goes, light clip w (metres along the
// light's axis) for the mask's near limit.
#include "techniques/projected/contact_strip_rays.h"

#include "techniques/projected/contact_strips.h"
#include "techniques/projected/projected_shadow.h"
#include "techniques/geometry/line_triangle.h"
#include "techniques/geometry/point_in_mesh.h"
#include "techniques/geometry/projection.h"
#include "techniques/light_passes/scene_pass.h"
#include "scene/scene.h"

#include <algorithm>

namespace gs {
namespace {

// Whether the camera's near-plane rectangle (clip z = -w inside the view; `camera_clip` world to
// camera clip) meets the inside of the closed surface `world`, `triangles` (world): the camera
// then sees some of what the surface holds, which it sees only from within or through that cut
// (elsewhere the surface's faces turned to the camera hide it). True when a corner lies inside,
// or an edge of either passes through the other's triangles (the rectangle as two).
bool near_plane_meets_inside(const std::vector<glm::vec3> &world,
                             const std::vector<glm::uvec3> &triangles,
                             const glm::mat4 &camera_clip) {
  const glm::mat4 to_world = glm::inverse(camera_clip);
  glm::vec3 corner[4];
  for (int k = 0; k < 4; ++k) {
    const glm::vec4 p = to_world * glm::vec4(k == 1 || k == 2 ? 1.0f : -1.0f, k >= 2 ? 1.0f : -1.0f,
                                             -1.0f, 1.0f);
    corner[k] = glm::vec3(p) / p.w;
  }
  // Boxes apart (the camera away from the caster, as in most frames): the rectangle cannot meet
  // the inside, and the tests below are left out.
  glm::vec3 low(INFINITY), high(-INFINITY), near_low(INFINITY), near_high(-INFINITY);
  for (const glm::vec3 &p : world) low = glm::min(low, p), high = glm::max(high, p);
  for (const glm::vec3 &c : corner) {
    near_low = glm::min(near_low, c), near_high = glm::max(near_high, c);
  }
  if (glm::any(glm::lessThan(high, near_low)) || glm::any(glm::lessThan(near_high, low))) {
    return false;
  }
  if (mesh_surrounds(world, triangles, corner[0])) return true;
  auto segment_meets = [](const glm::vec3 &p, const glm::vec3 &q, const glm::vec3 &a,
                          const glm::vec3 &b, const glm::vec3 &c) {
    float t = 0.0f;
    return line_meets_triangle(p, q - p, a, b - a, c - a, t) && t >= 0.0f && t <= 1.0f;
  };
  for (const glm::uvec3 &t : triangles) {
    const glm::vec3 &a = world[t.x], &b = world[t.y], &c = world[t.z];
    for (int half = 0; half < 2; ++half) {  // the rectangle's triangles 0 1 2 and 0 2 3
      const glm::vec3 &r0 = corner[0], &r1 = corner[half == 0 ? 1 : 2];
      const glm::vec3 &r2 = corner[half == 0 ? 2 : 3];
      if (segment_meets(a, b, r0, r1, r2) || segment_meets(b, c, r0, r1, r2) ||
          segment_meets(c, a, r0, r1, r2)) {
        return true;
      }
    }
    for (int k = 0; k < 4; ++k) {
      if (segment_meets(corner[k], corner[(k + 1) % 4], a, b, c)) return true;
    }
  }
  return false;
}

}  // namespace

ContactStripRays::ContactStripRays(const LightView &view, const SceneObject &caster, bool closed,
                                   const ProjectedObject &receiver, const glm::vec3 &camera,
                                   const glm::mat4 &camera_clip, const glm::vec2 &low,
                                   const glm::vec2 &high)
    : view_(view), closed_(closed), camera_(camera), camera_clip_(camera_clip),
      light_clip_(view.projection * view.view), clip_to_world_(glm::inverse(light_clip_)) {
  const Mesh &mesh = caster_mesh(caster);
  std::vector<glm::vec3> world(mesh.positions.size());
  std::vector<glm::vec4> camera_points(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    world[i] = glm::vec3(caster.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
    camera_points[i] = camera_clip_ * glm::vec4(world[i], 1.0f);
  }
  std::vector<glm::vec2> screen;
  std::vector<float> w;
  to_light_screen(world, screen, w);
  faces_.reserve(mesh.triangles.size());
  // Every caster triangle: any of them may hide a receiver point from the camera.
  for (const glm::uvec3 &t : mesh.triangles) {
    add(world, screen, w, camera_points, t, true, glm::vec2(-INFINITY), glm::vec2(INFINITY));
  }
  caster_faces_ = faces_.size();
  sees_inside_ = closed && near_plane_meets_inside(world, mesh.triangles, camera_clip_);
  to_light_screen(receiver.world, screen, w);
  for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
    add(receiver.world, screen, w, {}, t, false, low, high);
  }
}

void ContactStripRays::to_light_screen(const std::vector<glm::vec3> &world,
                                       std::vector<glm::vec2> &screen, std::vector<float> &w) const {
  screen.resize(world.size());
  w.resize(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    const glm::vec4 clip = light_clip_ * glm::vec4(world[i], 1.0f);
    w[i] = clip.w;
    if (clip.w > 0.0f) {
      const GrVertex v = to_screen(clip, view_.size, view_.size);
      screen[i] = glm::vec2(v.x, v.y);
    }
  }
}

bool ContactStripRays::add(const std::vector<glm::vec3> &world, const std::vector<glm::vec2> &screen,
                           const std::vector<float> &w, const std::vector<glm::vec4> &camera,
                           const glm::uvec3 &t, bool caster, const glm::vec2 &low,
                           const glm::vec2 &high) {
  Face f;
  f.caster = caster;
  if (w[t.x] > 0.0f && w[t.y] > 0.0f && w[t.z] > 0.0f) {
    f.low = glm::min(screen[t.x], glm::min(screen[t.y], screen[t.z]));
    f.high = glm::max(screen[t.x], glm::max(screen[t.y], screen[t.z]));
  }
  if (f.high.x < low.x || f.low.x > high.x || f.high.y < low.y || f.low.y > high.y) return false;
  const glm::vec3 &a = world[t.x], &b = world[t.y], &c = world[t.z];
  const glm::vec3 normal = glm::cross(b - a, c - a);  // as wound: outward, faces culled behind
  f.a = a, f.e1 = b - a, f.e2 = c - a;
  f.light_facing = glm::dot(normal, view_.position - a) > 0.0f;
  f.camera_facing = glm::dot(normal, camera_ - a) > 0.0f;
  if (!caster && !f.light_facing) return false;  // the receiver's mask is its light-facing surface
  if (caster && camera[t.x].w > 0.0f && camera[t.y].w > 0.0f && camera[t.z].w > 0.0f) {
    f.camera_low = glm::vec2(INFINITY), f.camera_high = glm::vec2(-INFINITY);
    for (unsigned i : {t.x, t.y, t.z}) {
      const glm::vec2 ndc = glm::vec2(camera[i]) / camera[i].w;
      f.camera_low = glm::min(f.camera_low, ndc), f.camera_high = glm::max(f.camera_high, ndc);
    }
  }
  faces_.push_back(f);
  return true;
}

void ContactStripRays::select(const glm::vec2 &low, const glm::vec2 &high) {
  selected_.clear();
  for (const Face &f : faces_) {
    if (f.high.x >= low.x && f.low.x <= high.x && f.high.y >= low.y && f.low.y <= high.y) {
      selected_.push_back(&f);
    }
  }
}

bool ContactStripRays::hidden_from_camera(const glm::vec3 &point) const {
  const glm::vec4 p = camera_clip_ * glm::vec4(point, 1.0f);
  // Clip z + w along the segment from the point to the camera, linear in world space: the near
  // plane is where it is 0 (the camera's own is negative). A point nearer than the near plane is
  // not seen, and a face crossing the segment nearer than it is clipped away and hides nothing.
  const float near_point = p.z + p.w;
  if (!(near_point > 0.0f)) return true;
  const glm::vec4 eye = camera_clip_ * glm::vec4(camera_, 1.0f);
  const float t_near = near_point / (near_point - (eye.z + eye.w));
  const glm::vec2 ndc = glm::vec2(p) / p.w;
  // A face's NDC bounds widened by a little more than float rounding; the test is exact.
  const float slack = 1e-4f;
  // t runs from the point (0) to the camera (1); a triangle the point lies on is not between.
  // One turned from the camera is culled by the scene pass and hides nothing (a crate's lid
  // seen from inside the crate).
  const auto caster_end = faces_.begin() + static_cast<std::ptrdiff_t>(caster_faces_);
  return std::any_of(faces_.begin(), caster_end, [&](const Face &f) {
    float t = 0.0f;
    return f.camera_facing && !(ndc.x < f.camera_low.x - slack || ndc.x > f.camera_high.x + slack ||
                                ndc.y < f.camera_low.y - slack || ndc.y > f.camera_high.y + slack) &&
           line_meets_triangle(point, camera_ - point, f.a, f.e1, f.e2, t) && t > 1e-4f && t < t_near;
  });
}

ContactStripRays::Seen ContactStripRays::seen_in_shadow(const glm::vec2 &p) const {
  const float size = static_cast<float>(view_.size);
  const glm::vec2 ndc(p.x / size * 2.0f - 1.0f, 1.0f - p.y / size * 2.0f);
  const glm::vec4 far = clip_to_world_ * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 direction = glm::vec3(far) / far.w - view_.position;
  const float w_at_light = (light_clip_ * glm::vec4(view_.position, 1.0f)).w;
  const float w_per_t = (light_clip_ * glm::vec4(direction, 0.0f)).w;
  float first_front = INFINITY;  // the caster's first surface step 1 draws
  hits_.clear();
  // A face's bounds widened by far more than the rounding of p's ray and of its corners' screen
  // positions (texels); the test is exact.
  const float slack = 1e-2f;
  for (const Face *f : selected_) {
    float t = 0.0f;
    if (p.x < f->low.x - slack || p.x > f->high.x + slack || p.y < f->low.y - slack ||
        p.y > f->high.y + slack) {
      continue;
    }
    if (!line_meets_triangle(view_.position, direction, f->a, f->e1, f->e2, t) || !(t > 0.0f)) continue;
    if (f->caster && (f->light_facing || !closed_)) first_front = std::min(first_front, t);
    // Step 1's mask leaves out the receiver nearer the light than the caster's front.
    if (f->caster || w_at_light + w_per_t * t >= view_.caster_front) hits_.push_back({t, f});
  }
  // An open caster's cut: a receiver point behind its surface by less than a strip's depth
  // margin (light clip w) lies on the cut, in neither side's shadow (the sheet's base seen by
  // the camera, meshes_12312).
  Seen seen = Seen::kNone;
  const float on_cut = closed_ ? first_front
                               : first_front + kContactStripDepthShare *
                                                   (w_at_light / w_per_t + first_front);
  for (const Hit &h : hits_) {
    if (h.face->caster || !h.face->camera_facing || !(h.t > on_cut)) continue;
    // Inside a closed caster when its next surface along the ray faces away from the light;
    // outside when that one faces the light or there is none. An open one has no inside. A
    // camera whose near plane lies wholly outside the caster sees nothing inside it.
    const Hit *next = nullptr;
    for (const Hit &c : hits_) {
      if (c.face->caster && c.t > h.t && (!next || c.t < next->t)) next = &c;
    }
    const bool inside = closed_ && next && !next->face->light_facing;
    if (inside && !sees_inside_) continue;
    if (hidden_from_camera(view_.position + direction * h.t)) continue;
    if (!inside) return Seen::kOutside;
    seen = Seen::kInside;
  }
  return seen;
}

}  // namespace gs
