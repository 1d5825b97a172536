// The light's rays beside a contact strip (contact_strip_rays.h): world space triangles, the
// light's Glide screen (texels, y down) for where a ray goes, light clip w (metres along the
// light's axis) for the mask's near limit.
#include "techniques/contact_strip_rays.h"

#include "techniques/projected_shadow.h"
#include "techniques/projection.h"
#include "techniques/scene_pass.h"
#include "scene/scene.h"

#include <algorithm>

namespace gs {
namespace {

// Moller-Trumbore, edges included: where the line origin + t * direction meets the triangle
// a, a + e1, a + e2 (world); false when it is parallel to it or misses it.
bool meets(const glm::vec3 &origin, const glm::vec3 &direction, const glm::vec3 &a,
           const glm::vec3 &e1, const glm::vec3 &e2, float &t) {
  const glm::vec3 q = glm::cross(direction, e2);
  const float det = glm::dot(e1, q);
  if (det == 0.0f) return false;
  const glm::vec3 s = origin - a;
  const float u = glm::dot(s, q) / det;
  if (u < 0.0f || u > 1.0f) return false;
  const glm::vec3 r = glm::cross(s, e1);
  const float v = glm::dot(direction, r) / det;
  if (v < 0.0f || u + v > 1.0f) return false;
  t = glm::dot(e2, r) / det;
  return true;
}

}  // namespace

ContactStripRays::ContactStripRays(const LightView &view, const SceneObject &caster,
                                   const ProjectedObject &receiver, const glm::vec3 &camera,
                                   const glm::mat4 &camera_clip)
    : view_(view), camera_(camera), camera_clip_(camera_clip),
      light_clip_(view.projection * view.view), clip_to_world_(glm::inverse(light_clip_)) {
  const Mesh &mesh = caster_mesh(caster);
  std::vector<glm::vec3> world(mesh.positions.size());
  std::vector<glm::vec4> clip(world.size()), camera_points(world.size());
  for (std::size_t i = 0; i < world.size(); ++i) {
    world[i] = glm::vec3(caster.model_to_world * glm::vec4(mesh.positions[i], 1.0f));
    clip[i] = light_clip_ * glm::vec4(world[i], 1.0f);
    camera_points[i] = camera_clip_ * glm::vec4(world[i], 1.0f);
  }
  for (const glm::uvec3 &t : mesh.triangles) add(world, clip, camera_points, t, true);
  clip.resize(receiver.world.size());
  for (std::size_t i = 0; i < clip.size(); ++i) {
    clip[i] = light_clip_ * glm::vec4(receiver.world[i], 1.0f);
  }
  for (const glm::uvec3 &t : receiver.object->mesh.triangles) {
    add(receiver.world, clip, {}, t, false);
  }
}

void ContactStripRays::add(const std::vector<glm::vec3> &world, const std::vector<glm::vec4> &clip,
                           const std::vector<glm::vec4> &camera, const glm::uvec3 &t,
                           bool caster) {
  const glm::vec3 &a = world[t.x], &b = world[t.y], &c = world[t.z];
  const glm::vec3 normal = glm::cross(b - a, c - a);  // as wound: outward, faces culled behind
  Face f{a, b - a, c - a, caster, glm::dot(normal, view_.position - a) > 0.0f,
         glm::dot(normal, camera_ - a) > 0.0f};
  if (!caster && !f.light_facing) return;  // the receiver's mask is its light-facing surface
  const glm::vec4 &p = clip[t.x], &q = clip[t.y], &r = clip[t.z];
  if (p.w > 0.0f && q.w > 0.0f && r.w > 0.0f) {
    f.low = glm::vec2(INFINITY), f.high = glm::vec2(-INFINITY);
    for (const glm::vec4 *v : {&p, &q, &r}) {
      const GrVertex screen = to_screen(*v, view_.size, view_.size);
      f.low = glm::min(f.low, glm::vec2(screen.x, screen.y));
      f.high = glm::max(f.high, glm::vec2(screen.x, screen.y));
    }
  }
  if (caster && camera[t.x].w > 0.0f && camera[t.y].w > 0.0f && camera[t.z].w > 0.0f) {
    f.camera_low = glm::vec2(INFINITY), f.camera_high = glm::vec2(-INFINITY);
    for (unsigned i : {t.x, t.y, t.z}) {
      const glm::vec2 ndc = glm::vec2(camera[i]) / camera[i].w;
      f.camera_low = glm::min(f.camera_low, ndc), f.camera_high = glm::max(f.camera_high, ndc);
    }
  }
  faces_.push_back(f);
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
  const glm::vec2 ndc = glm::vec2(p) / p.w;
  // A face's NDC bounds widened by a little more than float rounding; the test is exact.
  const float slack = 1e-4f;
  // t runs from the point (0) to the camera (1); a triangle the point lies on is not between.
  return std::any_of(faces_.begin(), faces_.end(), [&](const Face &f) {
    float t = 0.0f;
    return f.caster && !(p.w > 0.0f && (ndc.x < f.camera_low.x - slack || ndc.x > f.camera_high.x + slack ||
                                        ndc.y < f.camera_low.y - slack || ndc.y > f.camera_high.y + slack)) &&
           meets(point, camera_ - point, f.a, f.e1, f.e2, t) && t > 1e-4f && t < 1.0f;
  });
}

bool ContactStripRays::shadowed_outside(const glm::vec2 &p) const {
  const float size = static_cast<float>(view_.size);
  const glm::vec2 ndc(p.x / size * 2.0f - 1.0f, 1.0f - p.y / size * 2.0f);
  const glm::vec4 far = clip_to_world_ * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 direction = glm::vec3(far) / far.w - view_.position;
  const float w_at_light = (light_clip_ * glm::vec4(view_.position, 1.0f)).w;
  const float w_per_t = (light_clip_ * glm::vec4(direction, 0.0f)).w;
  float first_front = INFINITY;  // the caster's first light-facing surface
  hits_.clear();
  for (const Face *f : selected_) {
    float t = 0.0f;
    if (!meets(view_.position, direction, f->a, f->e1, f->e2, t) || !(t > 0.0f)) continue;
    if (f->caster && f->light_facing) first_front = std::min(first_front, t);
    // Step 1's mask leaves out the receiver nearer the light than the caster's front.
    if (f->caster || w_at_light + w_per_t * t >= view_.caster_front) hits_.push_back({t, f});
  }
  for (const Hit &h : hits_) {
    if (h.face->caster || !h.face->camera_facing || !(h.t > first_front)) continue;
    // Inside the caster (closed) when its next surface along the ray faces away from the light;
    // outside when that one faces the light or there is none.
    const Hit *next = nullptr;
    for (const Hit &c : hits_) {
      if (c.face->caster && c.t > h.t && (!next || c.t < next->t)) next = &c;
    }
    if (next && !next->face->light_facing) continue;
    if (!hidden_from_camera(view_.position + direction * h.t)) return true;
  }
  return false;
}

}  // namespace gs
