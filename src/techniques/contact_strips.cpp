// The strips beside a caster's cut by a receiver's surface (contact_strips.h). World space in;
// the light's Glide screen (texels, y down) and light clip w (metres along the light's axis) out.
#include "techniques/contact_strips.h"

#include "techniques/pierced_receivers.h"
#include "techniques/projected_shadow.h"
#include "techniques/projection.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace gs {

std::vector<std::array<GrVertex, 4>> contact_strips(const LightView &view,
                                                    const std::vector<ContactSegment> &contacts) {
  std::vector<std::array<GrVertex, 4>> strips;
  const glm::mat4 light_clip = view.projection * view.view;
  const glm::mat4 clip_to_world = glm::inverse(light_clip);
  const float size = static_cast<float>(view.size);
  // The light clip w where the light's ray through a screen point (texels) meets a world plane;
  // false when it meets it behind the light or not at all.
  auto w_on_plane = [&](const glm::vec2 &screen, const glm::vec3 &normal, const glm::vec3 &point,
                        float &w) {
    const glm::vec2 ndc(screen.x / size * 2.0f - 1.0f, 1.0f - screen.y / size * 2.0f);
    const glm::vec4 far = clip_to_world * glm::vec4(ndc, 0.5f, 1.0f);
    const glm::vec3 direction = glm::vec3(far) / far.w - view.position;
    const float along = glm::dot(normal, direction);
    if (std::abs(along) < 1e-12f) return false;
    const float t = glm::dot(normal, point - view.position) / along;
    if (!(t > 0.0f)) return false;
    w = (light_clip * glm::vec4(view.position + direction * t, 1.0f)).w;
    return w > 0.0f;
  };
  for (const ContactSegment &c : contacts) {
    if (glm::dot(c.receiver_normal, view.position - c.a) <= 0.0f ||
        glm::dot(c.caster_normal, view.position - c.a) <= 0.0f) {
      continue;  // not drawn in step 1 (the receiver's mask, the closed caster): no cut to hide
    }
    const glm::vec4 clip_a = light_clip * glm::vec4(c.a, 1.0f);
    const glm::vec4 clip_b = light_clip * glm::vec4(c.b, 1.0f);
    if (!(clip_a.w > 0.0f && clip_b.w > 0.0f)) continue;
    const GrVertex va = to_screen(clip_a, view.size, view.size);
    const GrVertex vb = to_screen(clip_b, view.size, view.size);
    const glm::vec2 a(va.x, va.y), b(vb.x, vb.y);
    const float screen_length = glm::length(b - a);
    if (!(screen_length > 0.0f)) continue;  // the segment along a light ray: no width to hide
    // Both sides of the cut alike: the hidden side (the caster's plane in front of the
    // receiver) and the visible one (behind it, by less than a code near the line).
    const glm::vec2 along = (b - a) / screen_length;
    const glm::vec2 in(-along.y, along.x);
    const float k = kContactStripTexels;
    const glm::vec2 corners[4] = {a - (along + in) * k, b + (along - in) * k, b + (along + in) * k,
                                  a + (in - along) * k};
    std::array<GrVertex, 4> strip;
    bool placed = true;
    for (int i = 0; i < 4 && placed; ++i) {
      float w_receiver = 0.0f, w_caster = 0.0f;
      placed = w_on_plane(corners[i], c.receiver_normal, c.a, w_receiver) &&
               w_on_plane(corners[i], c.caster_normal, c.a, w_caster);
      // A few W-buffer codes (4096 an octave) nearer than both planes, and no nearer than
      // depth_oow's unit (1/W at most 1).
      const float w = std::max(std::min(w_receiver, w_caster) * (1.0f - 2e-3f),
                               0.5f * std::max(view.caster_front, 1e-3f));
      std::memset(&strip[static_cast<std::size_t>(i)], 0, sizeof(GrVertex));
      strip[static_cast<std::size_t>(i)].x = corners[i].x;
      strip[static_cast<std::size_t>(i)].y = corners[i].y;
      strip[static_cast<std::size_t>(i)].oow = depth_oow(view, w);
    }
    if (placed) strips.push_back(strip);
  }
  return strips;
}

}  // namespace gs
